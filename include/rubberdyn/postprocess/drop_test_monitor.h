#ifndef rubberdyn_postprocess_drop_test_monitor_h
#define rubberdyn_postprocess_drop_test_monitor_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/postprocess/postprocessor.h>

#include <memory>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  namespace postprocess
  {
    /**
     * Area-weighted sums of the z displacement over the boundary faces
     * with one boundary id: the weight of a node is the integral of its
     * trilinear shape function over those faces of the locally owned cells
     * (reference configuration, straight-sided faces as the elements see
     * them), so that the weights of all ranks add up to the faces' area
     * and every face is counted once.
     */
    class FaceAverage
    {
    public:
      FaceAverage(const dealii::DoFHandler<3, 3> &          dof_handler,
                  const dealii::Utilities::MPI::Partitioner &partitioner,
                  const dealii::types::boundary_id           boundary_id,
                  const MPI_Comm                             comm);

      /** This rank's share of the integral of u_z over the faces. */
      double
      local_integral(const VectorType &u) const;

      /** Area of the faces, summed over all ranks (mm^2). */
      double area = 0.;

    private:
      std::vector<unsigned int> local_indices;
      std::vector<double>       weights;
    };


    /**
     * What the drop test (chapter 4 of the reference study) records: the
     * columns `impactor_displacement` and `impactor_force` (compression
     * positive), `rubber_top_displacement` and `rubber_bottom_displacement`
     * (minus the area-weighted mean z displacement of the rubber's top and
     * bottom faces: the rubber's own height is H - top + bottom without the
     * penetration of the penalty contacts) and `friction_work`; the largest
     * force and compression, the separation of the impactor on its way back
     * up and its rebound velocity; and, with `Stop after rebound`, the end
     * of the run shortly after the separation.
     */
    class DropTestMonitor : public Postprocessor
    {
    public:
      /**
       * @param impactor Index of the impactor's rigid body.
       * @param stop_after_rebound End the run @p rebound_margin ms after
       *   the separation.
       */
      DropTestMonitor(const dealii::DoFHandler<3, 3> &          dof_handler,
                      const dealii::Utilities::MPI::Partitioner &partitioner,
                      const dealii::types::boundary_id           top_face,
                      const dealii::types::boundary_id           bottom_face,
                      const unsigned int                         impactor,
                      const bool   stop_after_rebound,
                      const double rebound_margin,
                      const MPI_Comm comm);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      void
      history_values(const SimulationView &view,
                     std::vector<double> &  values) override;

      void
      after_step(const SimulationView &view) override;

      bool
      stop_requested() const override;

      void
      summary(const SimulationView &     view,
              std::vector<SummaryEntry> &entries) override;

      void
      final_log(std::ostream &log) const override;

      void
      save(std::ostream &out) const override;

      void
      load(std::istream &in) override;

    private:
      FaceAverage  top_face, bottom_face;
      unsigned int impactor;
      bool         stop_after_rebound;
      double       rebound_margin;
      MPI_Comm     comm;

      double max_force = 0., max_displacement = 0.;
      double time_of_max_displacement = 0., max_rubber_compression = 0.;
      /**
       * Rebound: the impactor's velocity has turned upwards; separation:
       * after that, the contact force is zero (reset if contact resumes).
       */
      bool   rebounding       = false;
      double separation_time  = -1., rebound_velocity = 0.;
      bool   stop             = false;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
