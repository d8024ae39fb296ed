#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/numerics/data_out.h>

#include <rubberdyn/postprocess/field_output.h>

#include <fstream>
#include <hdf5.h>
#include <iomanip>
#include <stdexcept>

namespace rubberdyn
{
  namespace postprocess
  {
    FieldOutput::FieldOutput(const std::string &directory,
                             const std::string &basename,
                             const MPI_Comm     comm,
                             const Format       format)
      : directory(directory)
      , basename(basename)
      , comm(comm)
      , format(format)
    {}



    std::string
    FieldOutput::index_file() const
    {
      return directory + "/" + basename +
             (format == Format::vtu ? ".pvd" : ".xdmf");
    }



    void
    FieldOutput::write(
      const DoFHandler<3, 3> &dof_handler,
      const VectorType       &displacement,
      const VectorType       &velocity,
      const std::vector<std::pair<std::string, std::vector<float>>> &cell_data,
      const double                                                   time,
      const std::vector<NodalScalars> &nodal_scalars)
    {
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);

      DataOut<3> data_out;
      data_out.attach_dof_handler(dof_handler);
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        vector_type(3,
                    DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(displacement,
                               std::vector<std::string>(3, "displacement"),
                               DataOut<3>::type_dof_data,
                               vector_type);
      data_out.add_data_vector(velocity,
                               std::vector<std::string>(3, "velocity"),
                               DataOut<3>::type_dof_data,
                               vector_type);
      for (const NodalScalars &scalars : nodal_scalars)
        data_out.add_data_vector(
          *scalars.values,
          std::vector<std::string>(scalars.names.begin(), scalars.names.end()),
          DataOut<3>::type_dof_data,
          std::vector<DataComponentInterpretation::DataComponentInterpretation>(
            3, DataComponentInterpretation::component_is_scalar));

      if (format == Format::vtu)
        {
          std::vector<Vector<float>> cell_vectors;
          cell_vectors.reserve(cell_data.size() + 1);
          for (const auto &entry : cell_data)
            {
              cell_vectors.emplace_back(entry.second.begin(),
                                        entry.second.end());
              data_out.add_data_vector(cell_vectors.back(), entry.first);
            }
          Vector<float> rank_vector(
            dof_handler.get_triangulation().n_active_cells());
          rank_vector = rank;
          data_out.add_data_vector(rank_vector, "mpi_rank");
          // Q2 (the mixed u-p element): each cell subdivided into 2^3, so
          // ParaView sees the quadratic displacement.
          data_out.build_patches(dof_handler.get_fe().degree);

          const unsigned int counter = records.size();
          const std::string  pvtu =
            data_out.write_vtu_with_pvtu_record(directory + "/",
                                                basename,
                                                counter,
                                                comm,
                                                4);
          records.emplace_back(time, pvtu);
          if (rank == 0)
            {
              std::ofstream pvd(index_file());
              DataOutBase::write_pvd_record(pvd, records);
            }
          return;
        }

      // HDF5: deal.II writes the mesh and the nodal vectors; vertices shared
      // by cells of this rank are merged, which is exact for the continuous
      // Q1 displacement and velocity.
      data_out.build_patches(dof_handler.get_fe().degree);
      DataOutBase::DataOutFilter filter(
        DataOutBase::DataOutFilterFlags(/*filter_duplicate_vertices=*/true,
                                        /*xdmf_hdf5_output=*/true));
      data_out.write_filtered_data(filter);

      const std::string h5_file =
        basename + "_" + Utilities::int_to_string(xdmf_records.size(), 4) +
        ".h5";
      const std::string h5_path = directory + "/" + h5_file;
      data_out.write_hdf5_parallel(filter,
                                   /*write_mesh_file=*/true,
                                   h5_path,
                                   h5_path,
                                   comm);

      // The cell fields, in the order in which DataOut made patches (and the
      // filter cells) from this rank's cells: the locally owned active cells
      // in the triangulation's order. Rank r's cells follow those of ranks
      // 0..r-1 in the file, as in deal.II's own datasets.
      std::vector<unsigned int> local_cells;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          local_cells.push_back(cell->active_cell_index());
      const std::uint64_t n_local_cells = local_cells.size();
      AssertThrow(n_local_cells == 0 || filter.n_cells() == n_local_cells,
                  ExcMessage("HDF5 output: DataOut wrote " +
                             std::to_string(filter.n_cells()) +
                             " cells on this rank, but it owns " +
                             std::to_string(n_local_cells)));
      std::uint64_t offset = 0;
      const int     ierr =
        MPI_Exscan(&n_local_cells, &offset, 1, MPI_UINT64_T, MPI_SUM, comm);
      AssertThrowMPI(ierr);
      if (rank == 0)
        offset = 0; // MPI_Exscan leaves rank 0's result undefined.
      const std::uint64_t n_global_cells =
        Utilities::MPI::sum(n_local_cells, comm);
      const std::uint64_t n_global_nodes =
        Utilities::MPI::sum(std::uint64_t(n_local_cells > 0 ? filter.n_nodes() :
                                                              0),
                            comm);

      std::vector<std::pair<std::string, std::vector<float>>> fields;
      fields.reserve(cell_data.size() + 1);
      for (const auto &entry : cell_data)
        {
          AssertThrow(entry.second.size() ==
                        dof_handler.get_triangulation().n_active_cells(),
                      ExcMessage("cell field " + entry.first +
                                 " does not have one value per active cell"));
          std::vector<float> values(n_local_cells);
          for (unsigned int c = 0; c < n_local_cells; ++c)
            values[c] = entry.second[local_cells[c]];
          fields.emplace_back(entry.first, std::move(values));
        }
      fields.emplace_back("mpi_rank",
                          std::vector<float>(n_local_cells, float(rank)));
      write_hdf5_cell_data(h5_path,
                           fields,
                           n_local_cells,
                           offset,
                           n_global_cells);

      XdmfRecord record;
      record.time        = time;
      record.h5_file     = h5_file;
      record.n_nodes     = n_global_nodes;
      record.n_cells     = n_global_cells;
      record.node_fields = {{"displacement", 3}, {"velocity", 3}};
      for (const NodalScalars &scalars : nodal_scalars)
        for (const std::string &name : scalars.names)
          record.node_fields.emplace_back(name, 1);
      for (const auto &field : fields)
        record.cell_fields.push_back(field.first);
      xdmf_records.push_back(record);
      if (rank == 0)
        write_xdmf_index();
    }



    void
    FieldOutput::write_hdf5_cell_data(
      const std::string                                             &h5_path,
      const std::vector<std::pair<std::string, std::vector<float>>> &fields,
      const std::uint64_t n_local_cells,
      const std::uint64_t offset,
      const std::uint64_t n_global_cells) const
    {
      // As deal.II does, leave ranks without cells out of the collective
      // HDF5 calls: their (empty) selections would otherwise need special
      // cases.
      MPI_Comm  writers;
      const int ierr = MPI_Comm_split(comm,
                                      n_local_cells > 0 ? 1 : 0,
                                      Utilities::MPI::this_mpi_process(comm),
                                      &writers);
      AssertThrowMPI(ierr);
      if (n_local_cells > 0)
        {
          const auto check = [&](const bool ok, const std::string &what) {
            AssertThrow(ok,
                        ExcMessage("HDF5 output to " + h5_path + ": " + what +
                                   " failed"));
          };
          const hid_t file_access = H5Pcreate(H5P_FILE_ACCESS);
          check(H5Pset_fapl_mpio(file_access, writers, MPI_INFO_NULL) >= 0,
                "setting MPI-IO access");
          const hid_t file =
            H5Fopen(h5_path.c_str(), H5F_ACC_RDWR, file_access);
          check(file >= 0, "opening the file");
          const hid_t transfer = H5Pcreate(H5P_DATASET_XFER);
          check(H5Pset_dxpl_mpio(transfer, H5FD_MPIO_COLLECTIVE) >= 0,
                "setting collective transfer");

          const hsize_t global_size[1] = {n_global_cells};
          const hsize_t local_size[1]  = {n_local_cells};
          const hsize_t start[1]       = {offset};
          for (const auto &field : fields)
            {
              const hid_t file_space =
                H5Screate_simple(1, global_size, nullptr);
              const hid_t dataset = H5Dcreate2(file,
                                               field.first.c_str(),
                                               H5T_NATIVE_FLOAT,
                                               file_space,
                                               H5P_DEFAULT,
                                               H5P_DEFAULT,
                                               H5P_DEFAULT);
              check(dataset >= 0, "creating dataset " + field.first);
              check(H5Sselect_hyperslab(file_space,
                                        H5S_SELECT_SET,
                                        start,
                                        nullptr,
                                        local_size,
                                        nullptr) >= 0,
                    "selecting this rank's cells");
              const hid_t memory_space =
                H5Screate_simple(1, local_size, nullptr);
              check(H5Dwrite(dataset,
                             H5T_NATIVE_FLOAT,
                             memory_space,
                             file_space,
                             transfer,
                             field.second.data()) >= 0,
                    "writing dataset " + field.first);
              H5Sclose(memory_space);
              H5Dclose(dataset);
              H5Sclose(file_space);
            }
          H5Pclose(transfer);
          check(H5Fclose(file) >= 0, "closing the file");
          H5Pclose(file_access);
        }
      MPI_Comm_free(&writers);
    }



    void
    FieldOutput::write_xdmf_index() const
    {
      // The layout of deal.II's DataOutInterface::write_xdmf_file(), plus
      // cell-centred attributes. File names are relative to the index.
      std::ofstream xdmf(index_file());
      xdmf << std::setprecision(12); // as deal.II's .pvd records
      xdmf << "<?xml version=\"1.0\" ?>\n"
           << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
           << "<Xdmf Version=\"2.0\">\n"
           << "  <Domain>\n"
           << "    <Grid Name=\"CellTime\" GridType=\"Collection\" "
              "CollectionType=\"Temporal\">\n";
      for (const XdmfRecord &r : xdmf_records)
        {
          const auto data_item = [&](const std::string &dimensions,
                                     const std::string &type,
                                     const std::string &dataset) {
            xdmf << "          <DataItem Dimensions=\"" << dimensions << "\" "
                 << type << " Format=\"HDF\">\n"
                 << "            " << r.h5_file << ":/" << dataset << "\n"
                 << "          </DataItem>\n";
          };
          const std::string nodes   = std::to_string(r.n_nodes);
          const std::string cells   = std::to_string(r.n_cells);
          const std::string doubles = "NumberType=\"Float\" Precision=\"8\"";
          xdmf << "      <Grid Name=\"mesh\" GridType=\"Uniform\">\n"
               << "        <Time Value=\"" << r.time << "\"/>\n"
               << "        <Geometry GeometryType=\"XYZ\">\n";
          data_item(nodes + " 3", doubles, "nodes");
          xdmf << "        </Geometry>\n"
               << "        <Topology TopologyType=\"Hexahedron\" "
                  "NumberOfElements=\""
               << cells << "\">\n";
          data_item(cells + " 8", "NumberType=\"UInt\"", "cells");
          xdmf << "        </Topology>\n";
          for (const auto &field : r.node_fields)
            {
              xdmf << "        <Attribute Name=\"" << field.first
                   << "\" AttributeType=\""
                   << (field.second > 1 ? "Vector" : "Scalar")
                   << "\" Center=\"Node\">\n";
              data_item(nodes + " " + std::to_string(field.second),
                        doubles,
                        field.first);
              xdmf << "        </Attribute>\n";
            }
          for (const std::string &field : r.cell_fields)
            {
              xdmf << "        <Attribute Name=\"" << field
                   << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
              data_item(cells, "NumberType=\"Float\" Precision=\"4\"", field);
              xdmf << "        </Attribute>\n";
            }
          xdmf << "      </Grid>\n";
        }
      xdmf << "    </Grid>\n"
           << "  </Domain>\n"
           << "</Xdmf>\n";
    }
  } // namespace postprocess
} // namespace rubberdyn
