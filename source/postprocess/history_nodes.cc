#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/postprocess/history_nodes.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace rubberdyn
{
  namespace postprocess
  {
    using namespace dealii;

    HistoryNodes::HistoryNodes(
      const model::Model                                 &model,
      const std::vector<parameters::Output::HistoryNode> &nodes)
    {
      const DoFHandler<3, 3>            &dof_handler = model.dof_handler;
      const Utilities::MPI::Partitioner &partitioner = *model.partitioner;
      const MPI_Comm    comm = partitioner.get_mpi_communicator();
      const std::string path = "Output/History nodes";
      // The mesh's size, for the tolerance (every rank sees its own cells).
      Point<3> low, high;
      for (unsigned int d = 0; d < 3; ++d)
        {
          low[d]  = std::numeric_limits<double>::max();
          high[d] = -std::numeric_limits<double>::max();
        }
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < 3; ++d)
              {
                low[d]  = std::min(low[d], cell->vertex(v)[d]);
                high[d] = std::max(high[d], cell->vertex(v)[d]);
              }
      for (unsigned int d = 0; d < 3; ++d)
        {
          low[d]  = Utilities::MPI::min(low[d], comm);
          high[d] = Utilities::MPI::max(high[d], comm);
        }
      const double tolerance = 1e-6 * low.distance(high);

      const FiniteElement<3>              &fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const parameters::Output::HistoryNode &node : nodes)
        {
          const Point<3> point(node.point[0], node.point[1], node.point[2]);
          unsigned int   part = numbers::invalid_unsigned_int;
          std::string    of_part;
          if (!node.part.empty())
            {
              for (unsigned int p = 0; p < model.parts.size(); ++p)
                if (model.parts[p].name == node.part)
                  part = p;
              if (part == numbers::invalid_unsigned_int)
                {
                  std::string names;
                  for (const model::Part &p : model.parts)
                    names += (names.empty() ? "" : ", ") + p.name;
                  throw InputError(
                    path,
                    "the part '" + node.part + "' of '" + node.name +
                      "' is not a part of the model (Parts/Names: " + names +
                      ")");
                }
              of_part = " of the part '" + node.part + "'";
            }
          // The nearest vertex of the owned cells (of the part), its dofs,
          // and every node at the point: touching parts may have nodes of
          // their own there.
          double   nearest = std::numeric_limits<double>::max();
          Point<3> where;
          std::array<types::global_dof_index, 3> global{};
          // (x dof, part index) of each node at the point.
          std::vector<std::array<types::global_dof_index, 2>> here;
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                const unsigned int cell_part =
                  model.part_of_material_id(cell->material_id());
                if (part != numbers::invalid_unsigned_int && cell_part != part)
                  continue;
                for (const unsigned int v : cell->vertex_indices())
                  {
                    const double distance = cell->vertex(v).distance(point);
                    if (distance <= tolerance || distance < nearest)
                      cell->get_dof_indices(dofs);
                    if (distance <= tolerance)
                      here.push_back({{dofs[fe.component_to_system_index(0, v)],
                                       cell_part}});
                    if (distance < nearest)
                      {
                        nearest = distance;
                        where   = cell->vertex(v);
                        for (unsigned int d = 0; d < 3; ++d)
                          global[d] = dofs[fe.component_to_system_index(d, v)];
                      }
                  }
              }
          const double closest = Utilities::MPI::min(nearest, comm);
          if (closest > tolerance)
            {
              // Where the nearest vertex is (from the rank that has it).
              std::ostringstream at;
              if (nearest == closest)
                at << where;
              std::string location;
              for (const std::string &s :
                   Utilities::MPI::all_gather(comm, at.str()))
                if (location.empty())
                  location = s;
              std::ostringstream message;
              message << "no node"
                      << (of_part.empty() ? " of the mesh" : of_part)
                      << " lies at the point of '" << node.name << "' ("
                      << point << "); the nearest is " << closest
                      << " mm away, at (" << location << ")";
              throw InputError(path, message.str());
            }
          // The distinct nodes at the point, over all ranks.
          std::map<types::global_dof_index, unsigned int> distinct;
          for (const auto &on_rank : Utilities::MPI::all_gather(comm, here))
            for (const auto &[dof, p] : on_rank)
              distinct.emplace(dof, static_cast<unsigned int>(p));
          if (distinct.size() > 1)
            {
              std::set<std::string> parts;
              for (const auto &[dof, p] : distinct)
                parts.insert(model.parts[p].name);
              std::ostringstream message;
              message << distinct.size() << " nodes lie at the point of '"
                      << node.name << "' (" << point << ")";
              if (parts.size() > 1)
                {
                  message << ", of the parts";
                  unsigned int k = 0;
                  for (const std::string &name : parts)
                    message << (k++ == 0          ? " '" :
                                k == parts.size() ? "' and '" :
                                                    "', '")
                            << name;
                  message << "'";
                  message << ": name the one meant, e.g. '" << node.name << ": "
                          << point[0] << ", " << point[1] << ", " << point[2]
                          << " in " << *parts.begin() << "'";
                }
              else
                message << ", all of the part '" << *parts.begin()
                        << "' (its mesh has unmerged nodes there)";
              throw InputError(path, message.str());
            }
          std::array<unsigned int, 3> local;
          local.fill(numbers::invalid_unsigned_int);
          if (nearest <= tolerance && partitioner.in_local_range(global[0]))
            for (unsigned int d = 0; d < 3; ++d)
              local[d] = partitioner.global_to_local(global[d]);
          owned_dofs.push_back(local);
          names.push_back(node.name);
        }
    }



    std::vector<std::string>
    HistoryNodes::columns() const
    {
      std::vector<std::string> result;
      for (const std::string &name : names)
        for (const char *d : {"_x", "_y", "_z"})
          result.push_back(name + "_displacement" + d);
      return result;
    }



    void
    HistoryNodes::append_values(const VectorType    &u,
                                std::vector<double> &values) const
    {
      std::vector<double> sums(3 * names.size(), 0.);
      for (unsigned int n = 0; n < names.size(); ++n)
        if (owned_dofs[n][0] != numbers::invalid_unsigned_int)
          for (unsigned int d = 0; d < 3; ++d)
            sums[3 * n + d] = u.local_element(owned_dofs[n][d]);
      Utilities::MPI::sum(ArrayView<const double>(sums),
                          u.get_mpi_communicator(),
                          ArrayView<double>(sums));
      values.insert(values.end(), sums.begin(), sums.end());
    }



    HistoryNodeColumns::HistoryNodeColumns(std::unique_ptr<HistoryNodes> nodes)
      : nodes(std::move(nodes))
    {}



    std::string
    HistoryNodeColumns::name() const
    {
      return "history nodes";
    }



    std::vector<std::string>
    HistoryNodeColumns::history_columns() const
    {
      return nodes->columns();
    }



    void
    HistoryNodeColumns::history_values(const SimulationView &view,
                                       std::vector<double>  &values)
    {
      nodes->append_values(view.displacement(), values);
    }
  } // namespace postprocess
} // namespace rubberdyn
