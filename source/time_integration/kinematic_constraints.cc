#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping_q1.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/time_integration/kinematic_constraints.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace rubberdyn
{
  namespace time_integration
  {
    namespace
    {
      std::string
      ids_text(const std::set<types::boundary_id> &ids)
      {
        std::string text;
        for (const types::boundary_id id : ids)
          text += (text.empty() ? "" : ", ") + std::to_string(id);
        return text;
      }
    } // namespace



    KinematicConstraints::KinematicConstraints(
      const DoFHandler<3, 3> &                                   dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
      : dof_handler(dof_handler)
      , partitioner(partitioner)
    {}



    KinematicConstraints::Entry
    KinematicConstraints::node_entry(
      const std::vector<types::global_dof_index> &dof_indices,
      const unsigned int                          i,
      const unsigned int                          group,
      const Point<3>                             &X) const
    {
      const FiniteElement<3> &fe   = dof_handler.get_fe();
      const unsigned int      node = fe.system_to_component_index(i).second;
      Entry                   entry;
      entry.dof   = partitioner->global_to_local(dof_indices[i]);
      entry.group = group;
      entry.X     = X;
      for (unsigned int d = 0; d < 3; ++d)
        entry.node_dofs[d] = partitioner->global_to_local(
          dof_indices[fe.component_to_system_index(d, node)]);
      return entry;
    }



    std::vector<KinematicConstraints::Entry>
    KinematicConstraints::boundary_entries(
      const std::set<types::boundary_id> &boundary_ids,
      const unsigned int                  direction,
      const unsigned int                  group,
      std::vector<Point<3>> *             vertices) const
    {
      const FiniteElement<3> &fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      std::map<unsigned int, Entry>        entries;
      // Q1: the nodes are the vertices. Q2 (the mixed u-p element): the
      // support points of the face's nodes.
      const bool quadratic = fe.degree == 2;
      AssertThrow(fe.degree == 1 || fe.degree == 2,
                  ExcMessage("KinematicConstraints needs FE_Q(1) or FE_Q(2)"));
      const std::vector<Point<3>> unit_points =
        quadratic ? fe.base_element(0).get_unit_support_points() :
                    std::vector<Point<3>>();
      const MappingQ1<3> mapping;
      // Ghost cells too: an owned node may lie on a boundary face of a
      // neighbour's cell only.
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          for (const unsigned int face : cell->face_indices())
            if (cell->at_boundary(face) &&
                boundary_ids.count(cell->face(face)->boundary_id()) > 0)
              {
                cell->get_dof_indices(dof_indices);
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    const unsigned int vertex =
                      GeometryInfo<3>::face_to_cell_vertices(face, v);
                    if (vertices != nullptr)
                      vertices->push_back(cell->vertex(vertex));
                    if (quadratic)
                      continue;
                    const unsigned int i =
                      fe.component_to_system_index(direction, vertex);
                    if (partitioner->in_local_range(dof_indices[i]))
                      {
                        const Entry entry =
                          node_entry(dof_indices, i, group, cell->vertex(vertex));
                        entries[entry.dof] = entry;
                      }
                  }
                // FE_Q(2): every node of the face (vertices, edge midpoints,
                // face centre), at its support point: the nodes where a
                // Lagrange shape function of the face is one. On the
                // trilinear cells of rubberdyn's meshes MappingQ1 gives
                // their exact reference positions.
                if (quadratic)
                  for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                    {
                      const auto ci = fe.system_to_component_index(i);
                      if (ci.first != direction ||
                          !fe.has_support_on_face(i, face))
                        continue;
                      if (!partitioner->in_local_range(dof_indices[i]))
                        continue;
                      const Entry entry = node_entry(
                        dof_indices,
                        i,
                        group,
                        mapping.transform_unit_to_real_cell(
                          cell, unit_points[ci.second]));
                      entries[entry.dof] = entry;
                    }
              }
      std::vector<Entry> result;
      for (const auto &[dof, entry] : entries)
        result.push_back(entry);
      return result;
    }



    double
    KinematicConstraints::prescribed_value(const Group &   g,
                                           const Point<3> &X,
                                           const double    t) const
    {
      return g.function(X, t);
    }



    void
    KinematicConstraints::prescribe(
      const std::string &                 name,
      const std::set<types::boundary_id> &boundary_ids,
      const unsigned int                  direction,
      const Kind                          kind,
      const Function &                    function,
      const bool                          depends_on_position,
      const Point<3> &                    moment_point)
    {
      AssertThrow(direction < 3, ExcIndexRange(direction, 0, 3));
      const unsigned int    group = groups.size();
      std::vector<Point<3>> vertices;
      const std::vector<Entry> entries =
        boundary_entries(boundary_ids, direction, group, &vertices);
      const unsigned int n_vertices =
        Utilities::MPI::sum(static_cast<unsigned int>(vertices.size()),
                            partitioner->get_mpi_communicator());
      if (n_vertices == 0)
        throw InputError(name,
                         "no boundary face has the boundary id " +
                           ids_text(boundary_ids));
      groups.push_back(
        {name, kind, function, depends_on_position, moment_point, 0.});
      add_entries(group, entries);
    }



    void
    KinematicConstraints::add_entries(const unsigned int        group,
                                      const std::vector<Entry> &entries)
    {
      // A dof claimed before keeps its first group if both prescribe the
      // same motion (sampled at a few times); otherwise the input
      // contradicts itself.
      std::string conflict;
      for (const Entry &entry : entries)
        {
          const auto existing = entry_of_dof.find(entry.dof);
          if (existing == entry_of_dof.end())
            {
              entry_of_dof[entry.dof] = constrained.size();
              constrained.push_back(entry);
              continue;
            }
          const Group &first = groups[constrained[existing->second].group];
          const Group &now   = groups[group];
          for (const double t : {0., 0.37, 1.1, 10.})
            {
              const double a = prescribed_value(first, entry.X, t);
              const double b = prescribed_value(now, entry.X, t);
              const bool   same =
                (first.kind == now.kind) ?
                  std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)) :
                  (a == 0. && b == 0.);
              if (!same && conflict.empty())
                conflict = "the node at (" +
                           parameter_tools::format_short(entry.X[0]) + ", " +
                           parameter_tools::format_short(entry.X[1]) + ", " +
                           parameter_tools::format_short(entry.X[2]) +
                           ") mm is also prescribed by '" + first.name +
                           "' in the same direction, with another motion";
            }
        }
      const std::vector<std::string> conflicts = Utilities::MPI::all_gather(
        partitioner->get_mpi_communicator(), conflict);
      for (const std::string &c : conflicts)
        if (!c.empty())
          throw InputError(groups[group].name, c);
    }



    std::vector<KinematicConstraints::Entry>
    KinematicConstraints::cell_entries(
      const std::set<types::material_id> &material_ids,
      const unsigned int                  direction,
      const unsigned int                  group,
      unsigned int                       &n_cells) const
    {
      const FiniteElement<3> &fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      const std::vector<Point<3>> unit_points =
        fe.base_element(0).get_unit_support_points();
      const MappingQ1<3>            mapping;
      std::map<unsigned int, Entry> entries;
      n_cells = 0;
      // Ghost cells too: an owned node may belong to a neighbour's cell
      // only.
      for (const auto &cell : dof_handler.active_cell_iterators())
        if ((cell->is_locally_owned() || cell->is_ghost()) &&
            material_ids.count(cell->material_id()) > 0)
          {
            if (cell->is_locally_owned())
              ++n_cells;
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const auto ci = fe.system_to_component_index(i);
                if (ci.first != direction ||
                    !partitioner->in_local_range(dof_indices[i]))
                  continue;
                const Entry entry = node_entry(
                  dof_indices,
                  i,
                  group,
                  mapping.transform_unit_to_real_cell(cell,
                                                      unit_points[ci.second]));
                entries[entry.dof] = entry;
              }
          }
      std::vector<Entry> result;
      for (const auto &[dof, entry] : entries)
        result.push_back(entry);
      return result;
    }



    void
    KinematicConstraints::hold_cells(
      const std::string                  &name,
      const std::set<types::material_id> &material_ids,
      const unsigned int                  direction)
    {
      AssertThrow(direction < 3, ExcIndexRange(direction, 0, 3));
      const unsigned int group = groups.size();
      unsigned int       n_cells = 0;
      const std::vector<Entry> entries =
        cell_entries(material_ids, direction, group, n_cells);
      if (Utilities::MPI::sum(n_cells, partitioner->get_mpi_communicator()) ==
          0)
        throw InputError(name, "no cell of the mesh has its material ids");
      groups.push_back({name,
                        Kind::velocity,
                        [](const Point<3> &, double) { return 0.; },
                        false,
                        Point<3>(),
                        0.});
      add_entries(group, entries);
    }



    void
    KinematicConstraints::prescribe_velocity(
      const std::string &                  name,
      const types::boundary_id             boundary_id,
      const unsigned int                   direction,
      const std::function<double(double)> &velocity)
    {
      prescribe(name, {boundary_id}, direction, Kind::velocity,
                [velocity](const Point<3> &, const double t) {
                  return velocity(t);
                },
                false);
    }



    void
    KinematicConstraints::fix(const std::string &      name,
                              const types::boundary_id boundary_id)
    {
      // One group per direction, so that each reaction component is
      // reported.
      const char *suffix[3] = {"/x", "/y", "/z"};
      for (unsigned int d = 0; d < 3; ++d)
        prescribe_velocity(name + suffix[d], boundary_id, d, [](double) {
          return 0.;
        });
    }



    unsigned int
    KinematicConstraints::plane_normal_direction(
      const std::string &                 name,
      const std::set<types::boundary_id> &boundary_ids) const
    {
      std::vector<Point<3>> vertices;
      boundary_entries(boundary_ids, 0, 0, &vertices);
      const MPI_Comm comm = partitioner->get_mpi_communicator();
      double         range[6];
      for (unsigned int d = 0; d < 3; ++d)
        {
          range[d]     = std::numeric_limits<double>::max(); // -lowest
          range[3 + d] = std::numeric_limits<double>::max(); // highest
        }
      for (const Point<3> &x : vertices)
        for (unsigned int d = 0; d < 3; ++d)
          {
            range[d]     = std::min(range[d], x[d]);
            range[3 + d] = std::min(range[3 + d], -x[d]);
          }
      Utilities::MPI::min(ArrayView<const double>(range, 6),
                          comm,
                          ArrayView<double>(range, 6));
      if (range[0] > -range[3])
        throw InputError(name,
                         "no boundary face has the boundary id " +
                           ids_text(boundary_ids));
      double extent[3], size = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        {
          extent[d] = -range[3 + d] - range[d];
          size      = std::max(size, extent[d]);
        }
      // Flat to rounding of the coordinates (mm).
      for (unsigned int d = 0; d < 3; ++d)
        if (extent[d] <= 1e-10 * std::max(1., size))
          return d;
      throw InputError(name,
                       "the faces of boundary " + ids_text(boundary_ids) +
                         " are not in one plane normal to a coordinate axis "
                         "(their extents are " +
                         parameter_tools::format_short(extent[0]) + ", " +
                         parameter_tools::format_short(extent[1]) + ", " +
                         parameter_tools::format_short(extent[2]) +
                         " mm); a symmetry condition needs one");
    }



    void
    KinematicConstraints::symmetry_plane(const std::string &      name,
                                         const types::boundary_id boundary_id,
                                         const unsigned int normal_direction)
    {
      AssertThrow(normal_direction < 3, ExcIndexRange(normal_direction, 0, 3));
      std::vector<Point<3>> vertices;
      boundary_entries({boundary_id}, normal_direction, 0, &vertices);
      const MPI_Comm comm = partitioner->get_mpi_communicator();
      double lowest = std::numeric_limits<double>::max(), highest = -lowest;
      for (const Point<3> &x : vertices)
        {
          lowest  = std::min(lowest, x[normal_direction]);
          highest = std::max(highest, x[normal_direction]);
        }
      lowest  = Utilities::MPI::min(lowest, comm);
      highest = Utilities::MPI::max(highest, comm);
      if (lowest > highest)
        throw InputError(name,
                         "no boundary face has the boundary id " +
                           std::to_string(boundary_id));
      // Flat to rounding of the coordinates (mm).
      if (highest - lowest > 1e-10 * std::max(1., std::abs(lowest)))
        throw InputError(name,
                         "the faces of boundary " +
                           std::to_string(boundary_id) +
                           " are not in one plane normal to axis " +
                           std::to_string(normal_direction) + " (they span " +
                           parameter_tools::format_short(highest - lowest) +
                           " mm along it)");
      prescribe_velocity(name, boundary_id, normal_direction,
                         [](double) { return 0.; });
    }



    std::vector<std::string>
    KinematicConstraints::group_names() const
    {
      std::vector<std::string> names;
      for (const Group &g : groups)
        names.push_back(g.name);
      return names;
    }



    void
    KinematicConstraints::begin_step(const double time,
                                     const double time_step) const
    {
      step_time = time;
      step_size = time_step;
      static const Point<3> origin;
      for (const Group &g : groups)
        if (!g.depends_on_position)
          g.step_value = g.kind == Kind::velocity ?
                           g.function(origin, time + 0.5 * time_step) :
                           g.function(origin, time + time_step);
    }



    double
    KinematicConstraints::half_step_velocity(const Entry &entry,
                                             const double displacement) const
    {
      const Group &g = groups[entry.group];
      if (g.kind == Kind::velocity)
        return g.depends_on_position ?
                 g.function(entry.X, step_time + 0.5 * step_size) :
                 g.step_value;
      const double target = g.depends_on_position ?
                              g.function(entry.X, step_time + step_size) :
                              g.step_value;
      return (target - displacement) / step_size;
    }



    double
    KinematicConstraints::initial_velocity(const Entry &entry) const
    {
      const Group &g = groups[entry.group];
      if (g.kind == Kind::velocity)
        return g.function(entry.X, 0.);
      // A forward difference over a step far below any explicit step.
      const double h = 1e-9;
      return (g.function(entry.X, h) - g.function(entry.X, 0.)) / h;
    }



    double
    KinematicConstraints::velocity(const unsigned int group,
                                   const double       t) const
    {
      static const Point<3> origin;
      return groups[group].function(origin, t);
    }
  } // namespace time_integration
} // namespace rubberdyn
