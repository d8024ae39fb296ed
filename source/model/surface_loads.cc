#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>

#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/model/surface_loads.h>

#include <algorithm>
#include <map>
#include <utility>

namespace rubberdyn
{
  namespace model
  {
    namespace
    {
      /** The 2 x 2 Gauss rule on the unit square (deal.II's). */
      const QGauss<2> &
      face_quadrature()
      {
        static const QGauss<2> quadrature(2);
        return quadrature;
      }

      /**
       * Bilinear shape functions of the unit square in lexicographic order
       * (0: (0,0), 1: (1,0), 2: (0,1), 3: (1,1)), GeometryInfo's order of a
       * face's vertices, and their derivatives.
       */
      double
      shape(const unsigned int a, const double xi, const double eta)
      {
        return ((a & 1) ? xi : 1. - xi) * ((a & 2) ? eta : 1. - eta);
      }

      double
      shape_d_xi_of(const unsigned int a, const double eta)
      {
        return ((a & 1) ? 1. : -1.) * ((a & 2) ? eta : 1. - eta);
      }

      double
      shape_d_eta_of(const unsigned int a, const double xi)
      {
        return ((a & 1) ? xi : 1. - xi) * ((a & 2) ? 1. : -1.);
      }

      /** sum_a c[4 q + a] x_a for the four points @p x. */
      Tensor<1, 3>
      combine(const std::array<double, 16>      &c,
              const unsigned int                 q,
              const std::array<Tensor<1, 3>, 4> &x)
      {
        Tensor<1, 3> result;
        for (unsigned int a = 0; a < 4; ++a)
          result += c[4 * q + a] * x[a];
        return result;
      }

      /**
       * The cell's vertices of face @p face in the order of the face's
       * (xi, eta) such that xi x eta points out of the cell: the xi x eta
       * normal at the face's centre against the direction from the cell's
       * centre to the face's centre; xi and eta swapped if it points
       * inwards (a mesh's faces need not all be oriented alike).
       */
      template <typename CellIterator>
      std::array<unsigned int, 4>
      outward_face_vertices(const CellIterator &cell, const unsigned int face)
      {
        std::array<unsigned int, 4> vertex;
        for (unsigned int v = 0; v < 4; ++v)
          vertex[v] = GeometryInfo<3>::face_to_cell_vertices(face, v);
        Point<3> face_centre, cell_centre;
        for (unsigned int v = 0; v < 4; ++v)
          face_centre += 0.25 * cell->vertex(vertex[v]);
        for (const unsigned int v : cell->vertex_indices())
          cell_centre += 0.125 * cell->vertex(v);
        const Tensor<1, 3> d_xi =
          0.5 * (cell->vertex(vertex[1]) - cell->vertex(vertex[0]) +
                 cell->vertex(vertex[3]) - cell->vertex(vertex[2]));
        const Tensor<1, 3> d_eta =
          0.5 * (cell->vertex(vertex[2]) - cell->vertex(vertex[0]) +
                 cell->vertex(vertex[3]) - cell->vertex(vertex[1]));
        if (cross_product_3d(d_xi, d_eta) * (face_centre - cell_centre) < 0.)
          std::swap(vertex[1], vertex[2]);
        return vertex;
      }
    } // namespace



    SurfaceLoads::SurfaceLoads(
      const DoFHandler<3, 3>                                   &dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const std::vector<BoundaryCondition>                     &conditions)
      : partitioner(partitioner)
    {
      const Quadrature<2> &quadrature = face_quadrature();
      AssertDimension(quadrature.size(), 4);
      for (unsigned int q = 0; q < 4; ++q)
        {
          const double xi  = quadrature.point(q)[0];
          const double eta = quadrature.point(q)[1];
          for (unsigned int a = 0; a < 4; ++a)
            {
              shape_weight[4 * q + a] =
                shape(a, xi, eta) * quadrature.weight(q);
              shape_d_xi[4 * q + a]  = shape_d_xi_of(a, eta);
              shape_d_eta[4 * q + a] = shape_d_eta_of(a, xi);
            }
        }
      for (const BoundaryCondition &bc : conditions)
        loads.push_back(make_load(dof_handler, bc));
    }



    SurfaceLoads::Load
    SurfaceLoads::make_load(const DoFHandler<3, 3>  &dof_handler,
                            const BoundaryCondition &bc) const
    {
      const std::string path = "Boundary conditions/" + bc.name;
      Load              load;
      load.name                = bc.name;
      load.type                = bc.type;
      load.components          = bc.components;
      load.functions           = bc.functions;
      load.depends_on_position = bc.depends_on_position;
      load.moment_point        = bc.moment_point;
      if (bc.type == BoundaryCondition::Type::pressure)
        {
          if (bc.functions.size() != 1)
            throw InputError(path + "/Function expression",
                             "a pressure takes one scalar function");
        }
      else if (bc.type == BoundaryCondition::Type::traction)
        {
          if (bc.functions.size() != bc.components.size())
            throw InputError(path + "/Function expression",
                             "a traction takes one function per listed "
                             "component");
          for (const unsigned int d : bc.components)
            AssertThrow(d < 3, ExcIndexRange(d, 0, 3));
        }
      else
        throw InputError(path + "/Type",
                         "is not a load (pressure or traction)");

      add_faces(dof_handler, bc, load);
      prepare_for_evaluation(load);

      const unsigned int n_faces =
        Utilities::MPI::sum(static_cast<unsigned int>(load.face_nodes.size()),
                            partitioner->get_mpi_communicator());
      if (n_faces == 0)
        {
          std::string ids;
          for (const types::boundary_id id : bc.boundary_ids)
            ids += (ids.empty() ? "" : ", ") + std::to_string(id);
          throw InputError(path + "/Boundary ids",
                           "no boundary face has the boundary id " + ids);
        }
      return load;
    }



    void
    SurfaceLoads::add_faces(const DoFHandler<3, 3>  &dof_handler,
                            const BoundaryCondition &bc,
                            Load                    &load) const
    {
      const Quadrature<2>                 &quadrature = face_quadrature();
      const FiniteElement<3>              &fe         = dof_handler.get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      // The loaded faces of the locally owned cells; every node once.
      std::map<types::global_dof_index, unsigned int> node_of_dof;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int face : cell->face_indices())
            if (cell->at_boundary(face) &&
                bc.boundary_ids.count(cell->face(face)->boundary_id()) > 0)
              {
                cell->get_dof_indices(dof_indices);
                const std::array<unsigned int, 4> vertex =
                  outward_face_vertices(cell, face);
                std::array<unsigned int, 4> nodes;
                std::array<Tensor<1, 3>, 4> X;
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    const types::global_dof_index first =
                      dof_indices[fe.component_to_system_index(0, vertex[v])];
                    const auto existing = node_of_dof.find(first);
                    if (existing != node_of_dof.end())
                      nodes[v] = existing->second;
                    else
                      {
                        nodes[v]           = load.node_dofs.size();
                        node_of_dof[first] = nodes[v];
                        std::array<unsigned int, 3> dofs;
                        for (unsigned int d = 0; d < 3; ++d)
                          dofs[d] = partitioner->global_to_local(
                            dof_indices
                              [fe.component_to_system_index(d, vertex[v])]);
                        load.node_dofs.push_back(dofs);
                        load.node_position.push_back(cell->vertex(vertex[v]));
                      }
                    X[v] = cell->vertex(vertex[v]);
                  }
                load.face_nodes.push_back(nodes);
                std::array<Point<3>, 4> points;
                std::array<double, 16>  weights;
                for (unsigned int q = 0; q < 4; ++q)
                  {
                    points[q] = Point<3>(combine(shape_weight, q, X) /
                                         quadrature.weight(q));
                    const double area =
                      cross_product_3d(combine(shape_d_xi, q, X),
                                       combine(shape_d_eta, q, X))
                        .norm();
                    for (unsigned int a = 0; a < 4; ++a)
                      weights[4 * q + a] = shape_weight[4 * q + a] * area;
                  }
                load.quadrature_points.push_back(points);
                load.face_weights.push_back(weights);
              }
    }



    void
    SurfaceLoads::prepare_for_evaluation(Load &load)
    {
      const unsigned int n_nodes = load.node_dofs.size();
      load.node_area.assign(n_nodes, 0.);
      for (unsigned int f = 0; f < load.face_nodes.size(); ++f)
        for (unsigned int q = 0; q < 4; ++q)
          for (unsigned int a = 0; a < 4; ++a)
            load.node_area[load.face_nodes[f][a]] +=
              load.face_weights[f][4 * q + a];
      // Keep what the evaluation needs: the weights of a traction (per
      // node if uniform, per face and point if not), the points of a
      // position-dependent load.
      if (load.type == BoundaryCondition::Type::pressure)
        load.node_area.clear();
      if (load.type == BoundaryCondition::Type::pressure ||
          !load.depends_on_position)
        load.face_weights.clear();
      if (!load.depends_on_position)
        load.quadrature_points.clear();
      load.force.assign(3 * n_nodes, 0.);
      load.displacement.assign(3 * n_nodes, 0.);
      load.previous_force.assign(3 * n_nodes, 0.);
      load.previous_displacement.assign(3 * n_nodes, 0.);
    }



    std::string
    SurfaceLoads::name() const
    {
      return "surface loads";
    }



    ForceContribution::Accumulation
    SurfaceLoads::accumulation() const
    {
      return Accumulation::internal_ghosted;
    }



    unsigned int
    SurfaceLoads::n_local_faces(const unsigned int l) const
    {
      AssertIndexRange(l, loads.size());
      return loads[l].face_nodes.size();
    }



    void
    SurfaceLoads::evaluate(Load &load, const EvaluationPoint &point) const
    {
      const double         t       = point.time;
      const unsigned int   n_nodes = load.node_dofs.size();
      std::vector<double> &force   = load.force;
      for (unsigned int n = 0; n < n_nodes; ++n)
        for (unsigned int d = 0; d < 3; ++d)
          load.displacement[3 * n + d] =
            point.displacement.local_element(load.node_dofs[n][d]);

      if (load.type == BoundaryCondition::Type::traction)
        {
          const unsigned int n_components = load.components.size();
          if (!load.depends_on_position)
            {
              // f_a = t(t) int N_a dA.
              Tensor<1, 3> traction;
              for (unsigned int k = 0; k < n_components; ++k)
                traction[load.components[k]] = load.functions[k](Point<3>(), t);
              for (unsigned int n = 0; n < n_nodes; ++n)
                for (unsigned int d = 0; d < 3; ++d)
                  force[3 * n + d] = load.node_area[n] * traction[d];
              return;
            }
          std::fill(force.begin(), force.end(), 0.);
          for (unsigned int f = 0; f < load.face_nodes.size(); ++f)
            for (unsigned int q = 0; q < 4; ++q)
              {
                Tensor<1, 3> traction;
                for (unsigned int k = 0; k < n_components; ++k)
                  traction[load.components[k]] =
                    load.functions[k](load.quadrature_points[f][q], t);
                for (unsigned int a = 0; a < 4; ++a)
                  {
                    const unsigned int n = load.face_nodes[f][a];
                    const double       w = load.face_weights[f][4 * q + a];
                    for (unsigned int d = 0; d < 3; ++d)
                      force[3 * n + d] += w * traction[d];
                  }
              }
          return;
        }

      // Pressure on the current faces.
      std::fill(force.begin(), force.end(), 0.);
      const double uniform_pressure =
        load.depends_on_position ? 0. : load.functions[0](Point<3>(), t);
      std::array<Tensor<1, 3>, 4> x;
      for (unsigned int f = 0; f < load.face_nodes.size(); ++f)
        {
          for (unsigned int a = 0; a < 4; ++a)
            {
              const unsigned int n = load.face_nodes[f][a];
              for (unsigned int d = 0; d < 3; ++d)
                x[a][d] =
                  load.node_position[n][d] + load.displacement[3 * n + d];
            }
          for (unsigned int q = 0; q < 4; ++q)
            {
              const double p =
                load.depends_on_position ?
                  load.functions[0](load.quadrature_points[f][q], t) :
                  uniform_pressure;
              // n da / (dxi deta), outward.
              const Tensor<1, 3> area_vector =
                cross_product_3d(combine(shape_d_xi, q, x),
                                 combine(shape_d_eta, q, x));
              for (unsigned int a = 0; a < 4; ++a)
                {
                  const unsigned int n = load.face_nodes[f][a];
                  const double       w = -p * shape_weight[4 * q + a];
                  for (unsigned int d = 0; d < 3; ++d)
                    force[3 * n + d] += w * area_vector[d];
                }
            }
        }
    }



    void
    SurfaceLoads::add_forces(const EvaluationPoint &point,
                             VectorType            &f,
                             ContributionResults   &results)
    {
      double work = 0.;
      for (Load &load : loads)
        {
          evaluate(load, point);
          const unsigned int n_nodes = load.node_dofs.size();
          // Resisting force: minus the load.
          for (unsigned int n = 0; n < n_nodes; ++n)
            for (unsigned int d = 0; d < 3; ++d)
              f.local_element(load.node_dofs[n][d]) -= load.force[3 * n + d];
          // W^n = (f^{n-1} + f^n) / 2 . (u^n - u^{n-1}).
          load.work_pending = 0.;
          if (has_previous)
            for (unsigned int i = 0; i < 3 * n_nodes; ++i)
              load.work_pending +=
                0.5 * (load.previous_force[i] + load.force[i]) *
                (load.displacement[i] - load.previous_displacement[i]);
          work += load.work_pending;
        }
      results.external_work += work;
    }



    void
    SurfaceLoads::accept_step()
    {
      for (Load &load : loads)
        {
          load.previous_force        = load.force;
          load.previous_displacement = load.displacement;
          load.work += load.work_pending;
          load.work_pending = 0.;
        }
      has_previous = true;
    }



    void
    SurfaceLoads::save(std::ostream &out) const
    {
      const double header[2] = {double(loads.size()), has_previous ? 1. : 0.};
      binary_io::write_doubles(out, header, 2);
      for (const Load &load : loads)
        {
          binary_io::write_doubles(out, &load.work, 1);
          binary_io::write_doubles(out,
                                   load.previous_force.data(),
                                   load.previous_force.size());
          binary_io::write_doubles(out,
                                   load.previous_displacement.data(),
                                   load.previous_displacement.size());
        }
    }



    void
    SurfaceLoads::load(std::istream &in)
    {
      double header[2];
      binary_io::read_doubles(in, header, 2, "surface loads");
      if (static_cast<unsigned int>(header[0]) != loads.size())
        throw CheckpointError(
          "the checkpoint has " + std::to_string(static_cast<int>(header[0])) +
          " surface loads, the model " + std::to_string(loads.size()));
      has_previous = header[1] != 0.;
      for (Load &load : loads)
        {
          binary_io::read_doubles(in,
                                  &load.work,
                                  1,
                                  "work of load " + load.name);
          load.work_pending = 0.;
          binary_io::read_doubles(in,
                                  load.previous_force.data(),
                                  load.previous_force.size(),
                                  "forces of load " + load.name);
          binary_io::read_doubles(in,
                                  load.previous_displacement.data(),
                                  load.previous_displacement.size(),
                                  "displacements of load " + load.name);
          load.force        = load.previous_force;
          load.displacement = load.previous_displacement;
        }
    }



    bool
    SurfaceLoads::supports_implicit() const
    {
      return true;
    }



    bool
    SurfaceLoads::symmetric_tangent() const
    {
      for (const Load &load : loads)
        if (load.type == BoundaryCondition::Type::pressure)
          return false;
      return true;
    }



    void
    SurfaceLoads::add_tangents(const EvaluationPoint &point,
                               const TangentBlock    &add) const
    {
      const auto skew = [](const Tensor<1, 3> &v) {
        // [v]x with [v]x w = v x w.
        Tensor<2, 3> m;
        m[0][1] = -v[2];
        m[0][2] = v[1];
        m[1][0] = v[2];
        m[1][2] = -v[0];
        m[2][0] = -v[1];
        m[2][1] = v[0];
        return m;
      };
      const Utilities::MPI::Partitioner &partitioner =
        *point.displacement.get_partitioner();
      std::vector<types::global_dof_index> dofs(12);
      std::vector<double>                  K(144);
      std::array<Tensor<1, 3>, 4> x;
      for (const Load &load : loads)
        {
          if (load.type != BoundaryCondition::Type::pressure)
            continue;
          const double uniform_pressure =
            load.depends_on_position ?
              0. :
              load.functions[0](Point<3>(), point.time);
          for (unsigned int f = 0; f < load.face_nodes.size(); ++f)
            {
              for (unsigned int a = 0; a < 4; ++a)
                {
                  const unsigned int n = load.face_nodes[f][a];
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      dofs[3 * a + d] =
                        partitioner.local_to_global(load.node_dofs[n][d]);
                      x[a][d] =
                        load.node_position[n][d] +
                        point.displacement.local_element(load.node_dofs[n][d]);
                    }
                }
              std::fill(K.begin(), K.end(), 0.);
              for (unsigned int q = 0; q < 4; ++q)
                {
                  const double p =
                    load.depends_on_position ?
                      load.functions[0](load.quadrature_points[f][q],
                                        point.time) :
                      uniform_pressure;
                  const Tensor<2, 3> x_xi  = skew(combine(shape_d_xi, q, x));
                  const Tensor<2, 3> x_eta = skew(combine(shape_d_eta, q, x));
                  for (unsigned int a = 0; a < 4; ++a)
                    for (unsigned int b = 0; b < 4; ++b)
                      {
                        const Tensor<2, 3> block =
                          p * shape_weight[4 * q + a] *
                          (shape_d_eta[4 * q + b] * x_xi -
                           shape_d_xi[4 * q + b] * x_eta);
                        for (unsigned int i = 0; i < 3; ++i)
                          for (unsigned int j = 0; j < 3; ++j)
                            K[12 * (3 * a + i) + 3 * b + j] += block[i][j];
                      }
                }
              add(dofs, K);
            }
        }
    }



    std::vector<SurfaceLoads::Resultant>
    SurfaceLoads::resultants() const
    {
      std::vector<double> sums(6 * loads.size(), 0.);
      for (unsigned int l = 0; l < loads.size(); ++l)
        {
          const Load &load = loads[l];
          for (unsigned int n = 0; n < load.node_dofs.size(); ++n)
            {
              Tensor<1, 3> force, arm;
              for (unsigned int d = 0; d < 3; ++d)
                {
                  force[d] = load.force[3 * n + d];
                  arm[d]   = load.node_position[n][d] +
                           load.displacement[3 * n + d] - load.moment_point[d];
                }
              const Tensor<1, 3> moment = cross_product_3d(arm, force);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  sums[6 * l + d] += force[d];
                  sums[6 * l + 3 + d] += moment[d];
                }
            }
        }
      Utilities::MPI::sum(ArrayView<const double>(sums),
                          partitioner->get_mpi_communicator(),
                          ArrayView<double>(sums));
      std::vector<Resultant> result(loads.size());
      for (unsigned int l = 0; l < loads.size(); ++l)
        for (unsigned int d = 0; d < 3; ++d)
          {
            result[l].force[d]  = sums[6 * l + d];
            result[l].moment[d] = sums[6 * l + 3 + d];
          }
      return result;
    }



    std::vector<double>
    SurfaceLoads::works() const
    {
      std::vector<double> work(loads.size());
      for (unsigned int l = 0; l < loads.size(); ++l)
        work[l] = loads[l].work + loads[l].work_pending;
      Utilities::MPI::sum(ArrayView<const double>(work),
                          partitioner->get_mpi_communicator(),
                          ArrayView<double>(work));
      return work;
    }
  } // namespace model
} // namespace rubberdyn
