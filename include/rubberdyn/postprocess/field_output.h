#ifndef rubberdyn_postprocess_field_output_h
#define rubberdyn_postprocess_field_output_h

#include <deal.II/base/mpi.h>
#include <rubberdyn/base/vector.h>

#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  /**
   * Output: fields for ParaView, time histories, run summaries.
   */
  namespace postprocess
  {
    using namespace dealii;

    /**
     * A ParaView time series: one `.pvtu` (with one `.vtu` per rank) per
     * output time, and one `.pvd` index that lists them with their times,
     * rewritten at every output so that it is valid whenever the run stops.
     */
    class FieldOutput
    {
    public:
      /**
       * @param directory Output directory (exists).
       * @param basename Name stem, e.g. "solution".
       */
      FieldOutput(const std::string &directory,
                  const std::string &basename,
                  const MPI_Comm     comm);

      /**
       * Write displacement and velocity (nodal vectors, ghosted) and the
       * given cell data (one value per active cell, locally owned cells
       * filled) at @p time, plus the MPI rank of every cell.
       */
      void
      write(const DoFHandler<3, 3> &                          dof_handler,
            const VectorType &displacement,
            const VectorType &velocity,
            const std::vector<std::pair<std::string, std::vector<float>>>
              &          cell_data,
            const double time);

    private:
      std::string                                  directory, basename;
      MPI_Comm                                     comm;
      std::vector<std::pair<double, std::string>>  records;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
