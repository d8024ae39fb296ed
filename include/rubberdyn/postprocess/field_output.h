#ifndef rubberdyn_postprocess_field_output_h
#define rubberdyn_postprocess_field_output_h

#include <deal.II/base/mpi.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/parameters/field_output_format.h>

#include <cstdint>
#include <array>
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
     * Field output for ParaView as a time series, in one of two formats.
     *
     * <b>vtu</b>: one `.pvtu` record (with one `.vtu` piece per rank) per
     * output time, e.g. `solution_0003.pvtu` with `solution_0003.0.vtu`,
     * `solution_0003.1.vtu`, and one `solution.pvd` index listing them with
     * their times. deal.II writes every cell with its own copy of its 8
     * vertices, so the cell data are point data that are constant on each
     * cell; the pieces are zlib-compressed floats.
     *
     * <b>hdf5</b>, for large runs: one HDF5 file per output time, e.g.
     * `solution_0003.h5`, written collectively by all ranks through MPI-IO,
     * and one `solution.xdmf` index listing them with their times. Each file
     * holds the whole mesh (datasets `nodes`, n x 3 doubles, and `cells`,
     * m x 8 unsigned vertex numbers in VTK/XDMF hexahedron order), the nodal
     * vectors (`displacement`, `velocity`, n x 3 doubles) and one dataset of
     * m floats per cell field (including `mpi_rank`). The nodal values
     * pass through deal.II's patches, which hold floats: the doubles in the
     * file carry float precision. Vertices shared by cells of one rank are
     * written once (deal.II's DataOutFilter with duplicate vertices
     * filtered); vertices on a boundary between ranks are written once per
     * rank. Nothing is compressed: on 40960 cells a file is 6.1 MB against
     * 5.3 MB for the compressed vtu, but it is written in about half the
     * time (0.8 s against 1.7 s per output time on one core), and the
     * number of files does not grow with the number of ranks.
     *
     * The cell fields are true cell-centred XDMF attributes. deal.II 9.4's
     * XDMFEntry only knows node-centred attributes, and with filtered
     * vertices a field that is constant per cell cannot be stored as node
     * data (the filter would keep one cell's value at each vertex). So
     * this class writes the cell datasets into the file that deal.II has
     * written, in deal.II's cell order, and writes the XDMF file itself,
     * in the layout of DataOutInterface::write_xdmf_file().
     *
     * In both formats the mesh is the reference configuration, written anew
     * at every output time, with the displacement as a nodal vector: in
     * ParaView, "Warp By Vector" with `displacement` shows the deformed body.
     * The index file is rewritten at every output, so that it is valid
     * whenever the run stops.
     */
    /**
     * Three scalar nodal fields in one vector of the Q1^3 dofs: the x dof
     * of a node holds the first field's value there, the y dof the
     * second's, the z dof the third's (e.g. the contact pressure, gap and
     * slip of contact::MortarContactPair::add_surface_fields()).
     */
    struct NodalScalars
    {
      std::array<std::string, 3> names;
      /** Ghosted, of the mesh's Q1^3 dofs. */
      const VectorType *values;
    };

    class FieldOutput
    {
    public:
      /** The file format (`Output/Field output format`). */
      using Format = parameters::FieldOutputFormat;

      /**
       * @param directory Output directory (exists).
       * @param basename Name stem, e.g. "solution".
       * @param comm The communicator of the mesh; all its ranks call write().
       * @param format File format.
       */
      FieldOutput(const std::string &directory,
                  const std::string &basename,
                  const MPI_Comm     comm,
                  const Format       format = Format::vtu);

      /**
       * Write displacement and velocity (nodal vectors, ghosted), the
       * nodal scalars @p nodal_scalars and the given cell data (one value
       * per active cell, locally owned cells filled) at @p time, plus the
       * MPI rank of every cell. Collective.
       */
      void
      write(const DoFHandler<3, 3> &dof_handler,
            const VectorType       &displacement,
            const VectorType       &velocity,
            const std::vector<std::pair<std::string, std::vector<float>>>
                        &cell_data,
            const double time,
            const std::vector<NodalScalars> &nodal_scalars = {});

      /**
       * The index file that ParaView opens: `directory/basename.pvd` or
       * `directory/basename.xdmf`.
       */
      std::string
      index_file() const;

    private:
      /**
       * One output time of the hdf5 format, as listed in the XDMF index.
       */
      struct XdmfRecord
      {
        double        time;
        std::string   h5_file;
        std::uint64_t n_nodes, n_cells;
        /** Nodal datasets with their number of components. */
        std::vector<std::pair<std::string, unsigned int>> node_fields;
        /** Cell datasets (one float per cell). */
        std::vector<std::string> cell_fields;
      };

      /**
       * Write the cell datasets of the current output time into the HDF5
       * file that deal.II has just written and closed.
       */
      void
      write_hdf5_cell_data(
        const std::string                                             &h5_path,
        const std::vector<std::pair<std::string, std::vector<float>>> &fields,
        const std::uint64_t n_local_cells,
        const std::uint64_t offset,
        const std::uint64_t n_global_cells) const;

      /** Rewrite the XDMF index from all records (root rank only). */
      void
      write_xdmf_index() const;

      std::string directory, basename;
      MPI_Comm    comm;
      Format      format;
      /** Times and `.pvtu` names (vtu format). */
      std::vector<std::pair<double, std::string>> records;
      /** Times and `.h5` contents (hdf5 format). */
      std::vector<XdmfRecord> xdmf_records;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
