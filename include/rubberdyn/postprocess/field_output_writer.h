#ifndef rubberdyn_postprocess_field_output_writer_h
#define rubberdyn_postprocess_field_output_writer_h

#include <deal.II/base/mpi.h>

#include <rubberdyn/postprocess/field_output.h>
#include <rubberdyn/postprocess/postprocessor.h>

#include <limits>
#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace rubberdyn
{
  namespace model
  {
    class Model;
  }
  namespace elements
  {
    class ImplicitElements;
    class SolidHexElements;
  }

  namespace postprocess
  {
    /**
     * The cell data of the solid's state at displacement @p u (ghosted),
     * one value per active cell (locally owned cells filled): the cell
     * averages of the Cauchy stress components (`cauchy_stress_xx` ...
     * `_yz`), `von_mises_stress` and `pressure` (GPa), `J`,
     * `equivalent_plastic_strain` (-, 0 in laws without plasticity),
     * `part_id` (index in the model's parts) and `material_id`: what every
     * scheme writes with FieldOutput.
     */
    std::vector<std::pair<std::string, std::vector<float>>>
    solid_cell_data(const model::Model               &model,
                    const elements::ImplicitElements &elements,
                    const VectorType                 &u);

    /**
     * The ParaView series as a postprocessor: at every `Field output
     * interval` and at the end of the run it writes the displacement and
     * velocity, the cell averages of the Cauchy stress, von Mises stress,
     * pressure, J and equivalent plastic strain, and per cell the MPI rank,
     * the part id (index in the model's part list) and the material id. It
     * also tracks the smallest
     * Jacobian determinants at its output times (run_summary.json).
     */
    class FieldOutputWriter : public Postprocessor
    {
    public:
      /**
       * @param interval Time between outputs (ms); 0: only the last state.
       */
      FieldOutputWriter(const std::string &      directory,
                        const std::string &      basename,
                        const FieldOutput::Format format,
                        const double             interval,
                        const MPI_Comm           comm);

      std::string
      name() const override;

      void
      after_step(const SimulationView &view) override;

      void
      finish(const SimulationView &view) override;

      void
      summary(const SimulationView &     view,
              std::vector<SummaryEntry> &entries) override;

      void
      save(std::ostream &out) const override;

      void
      load(std::istream &in) override;

      /**
       * Also write three nodal scalar fields @p names, which @p fill adds
       * into a zeroed vector of the mesh's Q1^3 dofs (owned entries;
       * collective) at every output (postprocess::NodalScalars).
       */
      void
      add_nodal_scalars(const std::array<std::string, 3>      &names,
                        const std::function<void(VectorType &)> &fill);

      /** Write the current state now (collective). */
      void
      write(const SimulationView &view);

      /** The index file ParaView opens. */
      std::string
      index_file() const;

    private:
      FieldOutput fields;
      /** The nodal scalar fields' names and how to fill them. */
      std::vector<std::pair<std::array<std::string, 3>,
                            std::function<void(VectorType &)>>>
                  nodal_scalar_sources;
      double      interval;
      MPI_Comm    comm;
      double      next_output = 0.;
      /** Time of the last output, so that the end state is not repeated. */
      double last_output_time = -1.;
      double min_jacobian_gauss_points =
        std::numeric_limits<double>::max();
      double min_jacobian_centres = std::numeric_limits<double>::max();
      double time_of_min_jacobian = 0.;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
