#include <deal.II/dofs/dof_handler.h>
#include <deal.II/numerics/data_out.h>

#include <rubberdyn/postprocess/field_output.h>

#include <fstream>

namespace rubberdyn
{
  namespace postprocess
  {
    FieldOutput::FieldOutput(const std::string &directory,
                             const std::string &basename,
                             const MPI_Comm     comm)
      : directory(directory)
      , basename(basename)
      , comm(comm)
    {}



    void
    FieldOutput::write(
      const DoFHandler<3, 3> &                          dof_handler,
      const VectorType &displacement,
      const VectorType &velocity,
      const std::vector<std::pair<std::string, std::vector<float>>> &cell_data,
      const double                                                   time)
    {
      DataOut<3> data_out;
      data_out.attach_dof_handler(dof_handler);
      const std::vector<DataComponentInterpretation::DataComponentInterpretation>
        vector_type(3, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(displacement,
                               std::vector<std::string>(3, "displacement"),
                               DataOut<3>::type_dof_data,
                               vector_type);
      data_out.add_data_vector(velocity,
                               std::vector<std::string>(3, "velocity"),
                               DataOut<3>::type_dof_data,
                               vector_type);
      std::vector<Vector<float>> cell_vectors;
      cell_vectors.reserve(cell_data.size() + 1);
      for (const auto &entry : cell_data)
        {
          cell_vectors.emplace_back(entry.second.begin(), entry.second.end());
          data_out.add_data_vector(cell_vectors.back(), entry.first);
        }
      Vector<float> rank(dof_handler.get_triangulation().n_active_cells());
      rank = Utilities::MPI::this_mpi_process(comm);
      data_out.add_data_vector(rank, "mpi_rank");
      data_out.build_patches();

      const unsigned int counter = records.size();
      const std::string  pvtu =
        data_out.write_vtu_with_pvtu_record(directory + "/", basename, counter,
                                            comm, 4);
      records.emplace_back(time, pvtu);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::ofstream pvd(directory + "/" + basename + ".pvd");
          DataOutBase::write_pvd_record(pvd, records);
        }
    }
  } // namespace postprocess
} // namespace rubberdyn
