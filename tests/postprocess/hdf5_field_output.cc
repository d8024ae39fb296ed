// FieldOutput in the hdf5 format (issue: "for large runs an HDF5 + XDMF
// option, written in parallel, one file per output time, opening in
// ParaView like the .pvd"), read back with the HDF5 C API and a generic XML
// parser instead of trusting the writer:
//
// - solution.xdmf is well-formed XML (boost::property_tree's parser throws
//   otherwise), a temporal collection with one uniform grid per output time
//   and the right times, and every DataItem names an HDF5 dataset that
//   exists with the stated dimensions, number type and precision;
// - the mesh: 6 x 4 x 4 cubes of 0.5 mm, so 96 cells and 7 x 5 x 5 = 175
//   distinct vertex positions (more nodes on 2 ranks: vertices on the
//   boundary between ranks are written by both); each cell lists its
//   vertices in the VTK/XDMF hexahedron order that ParaView expects;
// - nodal vectors: displacement and velocity are linear functions of the
//   position, which Q1 interpolates exactly, so the value stored at every
//   node must equal the function at the node's coordinates. deal.II's
//   patches hold floats (DataOutBase::Patch::data is a Table<2, float>),
//   so the stored doubles are rounded to float: at most half an ulp,
//   2^-24 |value|, plus 1e-12 for double round-off;
// - nodal scalars (FieldOutput::NodalScalars, e.g. the contact pressure,
//   gap and slip): three scalar fields s_x, s_y, s_z from the x, y, z dofs
//   of one vector (here the velocity's), listed as node-centred scalars,
//   each equal at every node to that component of the velocity;
// - cell fields: f(c) = c_x + 10 c_y + 100 c_z of the cell centre c (plus
//   1000 at the second time) must be stored against the cell whose vertices
//   have that centre (the cell order of the datasets we write must match
//   deal.II's mesh). Stored as floats: values below 2048 round by at most
//   half an ulp, 6.1e-5, hence the tolerance 1e-4. Analytic checksum: the
//   centres take c_x in {0.25, ..., 2.75} (sum 9), c_y, c_z in {0.25, ...,
//   1.75} (sum 4), so sum f = 16 * 9 + 10 * 24 * 4 + 100 * 24 * 4 = 10704;
// - mpi_rank: each rank's cells form one block, in rank order, as large as
//   the number of cells the rank owns.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/postprocess/field_output.h>

#include <array>
#include <filesystem>
#include <hdf5.h>
#include <map>
#include <set>
#include <sstream>

#include "../tests.h"

using namespace dealii;
using rubberdyn::postprocess::FieldOutput;
using rubberdyn::postprocess::NodalScalars;

namespace
{
  // Displacement (scaled by the output's factor) and velocity: linear in x.
  Tensor<1, 3>
  displacement_at(const Point<3> &x, const double factor)
  {
    return factor * Tensor<1, 3>({0.1 * x[0] + 0.2 * x[1] - 0.3 * x[2] + 1.,
                                  -0.2 * x[0] + 0.05 * x[1] + 0.1 * x[2],
                                  0.3 * x[0] - 0.1 * x[1] + 0.02 * x[2] - .5});
  }

  Tensor<1, 3>
  velocity_at(const Point<3> &x, const double factor)
  {
    return factor * Tensor<1, 3>({x[1], x[2], x[0]});
  }

  double
  cell_field_at(const Point<3> &centre, const double shift)
  {
    return centre[0] + 10. * centre[1] + 100. * centre[2] + shift;
  }

  class VectorField : public Function<3>
  {
  public:
    VectorField(const bool velocity, const double factor)
      : Function<3>(3)
      , velocity(velocity)
      , factor(factor)
    {}

    double
    value(const Point<3> &x, const unsigned int component) const override
    {
      return velocity ? velocity_at(x, factor)[component] :
                        displacement_at(x, factor)[component];
    }

  private:
    const bool   velocity;
    const double factor;
  };

  // One HDF5 dataset, converted to double by the library on reading.
  struct Dataset
  {
    std::vector<hsize_t> dims;
    H5T_class_t          type_class;
    std::size_t          type_size;
    bool                 is_unsigned;
    std::vector<double>  values;
  };

  Dataset
  read_dataset(const std::string &file_name, const std::string &name)
  {
    const hid_t file = H5Fopen(file_name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    testing::check(file >= 0, "can open " + file_name);
    const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    testing::check(dataset >= 0, file_name + " has a dataset /" + name);
    Dataset     result;
    const hid_t space = H5Dget_space(dataset);
    result.dims.resize(H5Sget_simple_extent_ndims(space));
    H5Sget_simple_extent_dims(space, result.dims.data(), nullptr);
    const hid_t type  = H5Dget_type(dataset);
    result.type_class = H5Tget_class(type);
    result.type_size  = H5Tget_size(type);
    result.is_unsigned =
      (result.type_class == H5T_INTEGER && H5Tget_sign(type) == H5T_SGN_NONE);
    std::size_t n = 1;
    for (const hsize_t d : result.dims)
      n *= d;
    result.values.resize(n);
    testing::check(H5Dread(dataset,
                           H5T_NATIVE_DOUBLE,
                           H5S_ALL,
                           H5S_ALL,
                           H5P_DEFAULT,
                           result.values.data()) >= 0,
                   "can read /" + name);
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(dataset);
    H5Fclose(file);
    return result;
  }

  std::string
  trim(const std::string &text)
  {
    const auto begin = text.find_first_not_of(" \n\t");
    const auto end   = text.find_last_not_of(" \n\t");
    return begin == std::string::npos ? "" :
                                        text.substr(begin, end - begin + 1);
  }

  // Check an XDMF DataItem against the HDF5 dataset it names and return
  // that dataset.
  Dataset
  read_data_item(const boost::property_tree::ptree &item,
                 const std::string                 &directory)
  {
    const std::string reference = trim(item.data());
    const auto        colon     = reference.find(":/");
    testing::check(colon != std::string::npos,
                   "DataItem '" + reference + "' is file:/dataset");
    testing::check(item.get<std::string>("<xmlattr>.Format") == "HDF",
                   "DataItem format is HDF");
    const Dataset data =
      read_dataset(directory + "/" + reference.substr(0, colon),
                   reference.substr(colon + 2));

    std::istringstream dimensions(
      item.get<std::string>("<xmlattr>.Dimensions"));
    std::vector<hsize_t> stated;
    for (hsize_t d; dimensions >> d;)
      stated.push_back(d);
    testing::check(stated == data.dims,
                   "dimensions of " + reference + " as stated in the XDMF");

    const std::string number_type =
      item.get<std::string>("<xmlattr>.NumberType");
    if (number_type == "Float")
      testing::check(data.type_class == H5T_FLOAT &&
                       data.type_size ==
                         item.get<std::size_t>("<xmlattr>.Precision"),
                     "type of " + reference + " is the stated float");
    else
      testing::check(number_type == "UInt" && data.type_class == H5T_INTEGER &&
                       data.is_unsigned && data.type_size == 4,
                     "type of " + reference + " is the stated UInt");
    return data;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int n_ranks            = Utilities::MPI::n_mpi_processes(comm);
  const bool         root = (Utilities::MPI::this_mpi_process(comm) == 0);

  parallel::distributed::Triangulation<3> triangulation(comm);
  GridGenerator::subdivided_hyper_rectangle(triangulation,
                                            {3, 2, 2},
                                            Point<3>(0., 0., 0.),
                                            Point<3>(3., 2., 2.));
  triangulation.refine_global(1);

  const FESystem<3> fe(FE_Q<3>(1), 3);
  DoFHandler<3>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  const auto partitioner = rubberdyn::ghosted_partitioner(dof_handler);

  const std::string directory = "fields";
  if (root)
    std::filesystem::create_directories(directory);
  MPI_Barrier(comm);
  FieldOutput fields(directory, "solution", comm, FieldOutput::Format::hdf5);

  const std::array<double, 2> times   = {{0.5, 1.25}};
  const std::array<double, 2> factors = {{1., 2.}};
  const std::array<double, 2> shifts  = {{0., 1000.}};
  for (unsigned int k = 0; k < times.size(); ++k)
    {
      rubberdyn::VectorType displacement(partitioner), velocity(partitioner);
      VectorTools::interpolate(dof_handler,
                               VectorField(false, factors[k]),
                               displacement);
      VectorTools::interpolate(dof_handler,
                               VectorField(true, -factors[k]),
                               velocity);
      displacement.update_ghost_values();
      velocity.update_ghost_values();
      std::vector<float> f(triangulation.n_active_cells(), 0.f);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          f[cell->active_cell_index()] =
            cell_field_at(cell->center(), shifts[k]);
      fields.write(dof_handler,
                   displacement,
                   velocity,
                   {{"f", f}},
                   times[k],
                   {NodalScalars{{{"s_x", "s_y", "s_z"}}, &velocity}});
    }
  const std::vector<unsigned int> owned_cells =
    Utilities::MPI::gather(comm,
                           triangulation.n_locally_owned_active_cells(),
                           0);
  if (!root)
    return 0;

  auto &out = testing::out();
  out << "ranks: " << n_ranks << ", index: " << fields.index_file() << '\n';
  boost::property_tree::ptree tree;
  boost::property_tree::read_xml(fields.index_file(), tree);
  const auto &collection = tree.get_child("Xdmf.Domain.Grid");
  testing::check(collection.get<std::string>("<xmlattr>.CollectionType") ==
                   "Temporal",
                 "the XDMF holds a temporal collection");

  unsigned int k = 0;
  for (const auto &grid : collection)
    {
      if (grid.first != "Grid")
        continue;
      testing::check(k < times.size(), "no more grids than output times");
      const auto  &g    = grid.second;
      const double time = g.get<double>("Time.<xmlattr>.Value");
      testing::check(time == times[k], "time of grid " + std::to_string(k));
      const Dataset nodes =
        read_data_item(g.get_child("Geometry.DataItem"), directory);
      testing::check(g.get<std::string>("Geometry.<xmlattr>.GeometryType") ==
                       "XYZ",
                     "XYZ geometry");
      testing::check(g.get<std::string>("Topology.<xmlattr>.TopologyType") ==
                       "Hexahedron",
                     "hexahedron topology");
      const Dataset cells =
        read_data_item(g.get_child("Topology.DataItem"), directory);
      const std::size_t n_nodes = nodes.dims[0], n_cells = cells.dims[0];
      testing::check(g.get<std::size_t>(
                       "Topology.<xmlattr>.NumberOfElements") == n_cells,
                     "NumberOfElements");

      const std::string nodes_item =
        trim(g.get<std::string>("Geometry.DataItem"));
      out << "time " << time << ": "
          << nodes_item.substr(0, nodes_item.find(':')) << ", " << n_nodes
          << " nodes, " << n_cells << " cells\n";

      // The mesh.
      std::set<std::array<double, 3>> positions;
      for (std::size_t i = 0; i < n_nodes; ++i)
        {
          const std::array<double, 3> position = {{nodes.values[3 * i],
                                                   nodes.values[3 * i + 1],
                                                   nodes.values[3 * i + 2]}};
          positions.insert(position);
        }
      out << "  distinct node positions: " << positions.size() << '\n';
      testing::check(positions.size() == 175, "7 x 5 x 5 vertex positions");
      testing::check(n_ranks > 1 || n_nodes == 175,
                     "on one rank, every vertex is written once");
      testing::check(n_cells == triangulation.n_global_active_cells(),
                     "every cell written once");
      // VTK/XDMF hexahedron: bottom face counter-clockwise seen from +z,
      // then the top face above it.
      const int             corner[8][3] = {{0, 0, 0},
                                            {1, 0, 0},
                                            {1, 1, 0},
                                            {0, 1, 0},
                                            {0, 0, 1},
                                            {1, 0, 1},
                                            {1, 1, 1},
                                            {0, 1, 1}};
      std::vector<Point<3>> centres(n_cells);
      for (std::size_t c = 0; c < n_cells; ++c)
        {
          Point<3> v[8];
          for (unsigned int i = 0; i < 8; ++i)
            {
              const std::size_t node = cells.values[8 * c + i];
              testing::check(node < n_nodes, "vertex number in range");
              v[i] = Point<3>(nodes.values[3 * node],
                              nodes.values[3 * node + 1],
                              nodes.values[3 * node + 2]);
              centres[c] += v[i] / 8.;
            }
          for (unsigned int i = 0; i < 8; ++i)
            for (unsigned int d = 0; d < 3; ++d)
              testing::check(std::abs(v[i][d] - v[0][d] - 0.5 * corner[i][d]) <
                               1e-12,
                             "hexahedron vertex order of cell " +
                               std::to_string(c));
        }

      // The attributes.
      std::map<std::string, Dataset> attributes;
      for (const auto &a : g)
        if (a.first == "Attribute")
          {
            const std::string name =
              a.second.get<std::string>("<xmlattr>.Name");
            const std::string center =
              a.second.get<std::string>("<xmlattr>.Center");
            const Dataset data =
              read_data_item(a.second.get_child("DataItem"), directory);
            testing::check(data.dims[0] ==
                             (center == "Node" ? n_nodes : n_cells),
                           name + " has one entry per " + center);
            out << "  " << name << ": " << center << ", "
                << a.second.get<std::string>("<xmlattr>.AttributeType") << '\n';
            attributes[name] = data;
          }
      for (const std::string name :
           {"displacement", "velocity", "s_x", "s_y", "s_z", "f", "mpi_rank"})
        testing::check(attributes.count(name) == 1, name + " is listed");
      for (const std::string name : {"s_x", "s_y", "s_z"})
        testing::check(attributes[name].dims.size() == 1 ||
                         attributes[name].dims[1] == 1,
                       name + " has one value per node");

      // Largest error relative to the float rounding bound (must be <= 1).
      double     max_u_error = 0., max_v_error = 0., max_s_error = 0.;
      const auto relative = [](const double stored, const double exact) {
        return std::abs(stored - exact) /
               (std::ldexp(std::abs(exact), -24) + 1e-12);
      };
      for (std::size_t i = 0; i < n_nodes; ++i)
        {
          const Point<3>     x(nodes.values[3 * i],
                           nodes.values[3 * i + 1],
                           nodes.values[3 * i + 2]);
          const Tensor<1, 3> u = displacement_at(x, factors[k]);
          const Tensor<1, 3> v = velocity_at(x, -factors[k]);
          for (unsigned int d = 0; d < 3; ++d)
            {
              max_s_error = std::max(
                max_s_error,
                relative(attributes[std::string("s_") + "xyz"[d]].values[i],
                         v[d]));
              max_u_error =
                std::max(max_u_error,
                         relative(attributes["displacement"].values[3 * i + d],
                                  u[d]));
              max_v_error =
                std::max(max_v_error,
                         relative(attributes["velocity"].values[3 * i + d],
                                  v[d]));
            }
        }
      testing::check(max_u_error <= 1., "displacement at every node");
      testing::check(max_v_error <= 1., "velocity at every node");
      testing::check(max_s_error <= 1., "nodal scalars at every node");

      double f_sum = 0., max_f_error = 0.;
      for (std::size_t c = 0; c < n_cells; ++c)
        {
          const double f = attributes["f"].values[c];
          f_sum += f;
          max_f_error =
            std::max(max_f_error,
                     std::abs(f - cell_field_at(centres[c], shifts[k])));
        }
      testing::check(max_f_error < 1e-4, "f of every cell at its centre");
      testing::check(std::abs(f_sum - (10704. + 96 * shifts[k])) < 1e-2,
                     "checksum of f");
      out << "  nodal values = linear fields at the nodes: yes\n"
          << "  cell values = f(centre of the cell's vertices): yes\n"
          << "  sum of f over the cells: " << f_sum << '\n';

      // mpi_rank: blocks in rank order, sized as the ranks' cell counts.
      std::vector<unsigned int> block(n_ranks, 0);
      for (std::size_t c = 0; c < n_cells; ++c)
        {
          const double rank = attributes["mpi_rank"].values[c];
          testing::check(rank == std::floor(rank) && rank >= 0 &&
                           rank < n_ranks,
                         "mpi_rank is a rank");
          testing::check(c == 0 || rank >= attributes["mpi_rank"].values[c - 1],
                         "cells in rank order");
          ++block[static_cast<unsigned int>(rank)];
        }
      testing::check(block == owned_cells,
                     "each rank's block is as large as its cell count");
      out << "  cells per rank:";
      for (const unsigned int n : block)
        out << ' ' << n;
      out << '\n';
      ++k;
    }
  testing::check(k == times.size(), "one grid per output time");
  return 0;
}
