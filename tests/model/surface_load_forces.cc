// Nodal forces of model::SurfaceLoads on a 3 x 2 x 2 block of hexahedra
// [0, 3] x [0, 2] x [0, 1.5] mm (boundary ids 0..5 on x = 0, x = 3, y = 0,
// y = 2, z = 0, z = 1.5), checked against closed forms. Every check is a
// sum of nodal forces, taken twice: from the force vector the solver sees
// (compressed over the ranks, sign turned: the contribution writes minus
// the load) and from SurfaceLoads::resultants(); both must agree.
// 1. A uniform traction t (GPa) on x = 3: the nodal forces sum to t A
//    (A = 2 x 1.5 mm^2) to round-off (1e-12 relative): the face weights
//    integrate N_a exactly on flat faces and sum_a N_a = 1. The same with
//    the traction flagged as position dependent (per quadrature point).
// 2. A uniform pressure p on each of the six faces of the undeformed
//    block: the resultant is -p A n with n the outward normal (this
//    checks the orientation of every face of deal.II's numbering).
// 3. The block rotated and stretched, x = R diag(l1, l2, l3) X: Nanson's
//    formula gives the current vector area of a face, n a = J F^{-T} N A,
//    so the pressure's resultant on each face is -p J F^{-T} N A (to
//    1e-12 relative): it follows the current area and normal.
// 4. The block deformed arbitrarily (nodes moved at random by up to 0.2
//    mm), uniform pressure on all six faces: on a closed surface
//    int n da = 0 and int x x n da = 0, and both integrands are
//    polynomials that the 2 x 2 rule integrates exactly on the bilinear
//    faces, so the resultant force and moment vanish to round-off.
// 5. A traction t_z = c x on y = 0 (x from 0 to 3, z from 0 to 1.5):
//    resultant c Lz Lx^2 / 2, first moment sum_a X_a f_a,z = c Lz Lx^3 / 3
//    (exact: the 2-point rule integrates x^2), and the moment about the
//    origin from resultants(): M_y = -c Lz Lx^3 / 3, M_x = M_z = 0.
// 6. The pressures' load stiffness for the implicit solver against central
//    differences of the forces (see the case).
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/model/surface_loads.h>

#include <functional>
#include <random>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::sci;

namespace
{
  /** The test's output: written by rank 0, discarded on the others. */
  std::ostream &
  text()
  {
    static std::ofstream discard; // never opened: writes are dropped
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      return testing::out();
    return discard;
  }

  /** The measured errors, on stderr of rank 0 (for the log, not compared). */
  std::ostream &
  measured()
  {
    static std::ofstream discard;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      return std::cerr;
    return discard;
  }
  constexpr double Lx = 3., Ly = 2., Lz = 1.5;

  struct Block
  {
    explicit Block(const MPI_Comm comm)
      : triangulation(comm)
      , fe(FE_Q<3>(1), 3)
      , dof_handler(triangulation)
    {
      GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                {3, 2, 2},
                                                Point<3>(),
                                                Point<3>(Lx, Ly, Lz),
                                                true);
      dof_handler.distribute_dofs(fe);
      partitioner = rubberdyn::ghosted_partitioner(dof_handler);
      u.reinit(partitioner);
      v.reinit(partitioner);
      mass.reinit(partitioner);
    }

    /** Set u = phi(X) - X at every owned node (ghosts updated). */
    template <typename Map>
    void
    deform(const Map &phi)
    {
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (const unsigned int vertex : cell->vertex_indices())
              {
                const Point<3>     X = cell->vertex(vertex);
                const Tensor<1, 3> x = phi(X);
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    const auto i =
                      dofs[fe.component_to_system_index(d, vertex)];
                    if (partitioner->in_local_range(i))
                      u(i) = x[d] - X[d];
                  }
              }
          }
      u.update_ghost_values();
    }

    parallel::distributed::Triangulation<3>      triangulation;
    FESystem<3>                                  fe;
    DoFHandler<3>                                dof_handler;
    std::shared_ptr<Utilities::MPI::Partitioner> partitioner;
    VectorType                                   u, v, mass;
  };

  model::BoundaryCondition
  make_condition(
    const std::string                   &name,
    const types::boundary_id             id,
    const model::BoundaryCondition::Type type,
    const std::vector<unsigned int>     &components,
    const std::vector<std::function<double(const Point<3> &, double)>>
              &functions,
    const bool depends_on_position)
  {
    model::BoundaryCondition bc;
    bc.name                = name;
    bc.boundary_ids        = {id};
    bc.type                = type;
    bc.components          = components;
    bc.functions           = functions;
    bc.depends_on_position = depends_on_position;
    return bc;
  }

  /**
   * X plus a shift of up to 0.2 mm in each direction, random but a function
   * of the position (the same on every rank), seeded with @p salt.
   */
  std::function<Tensor<1, 3>(const Point<3> &)>
  random_motion(const int salt)
  {
    return [salt](const Point<3> &X) {
      std::seed_seq                          seed{int(std::lround(10. * X[0])),
                         int(std::lround(10. * X[1])),
                         int(std::lround(10. * X[2])) + salt};
      std::mt19937                           generator(seed);
      std::uniform_real_distribution<double> shift(-0.2, 0.2);
      Tensor<1, 3>                           x = X;
      for (unsigned int d = 0; d < 3; ++d)
        x[d] += shift(generator);
      return x;
    };
  }

  struct Sums
  {
    /** Sum of the forces on the solid in the vector, per direction. */
    Tensor<1, 3> vector_force;
    /** Sum of X_a f_a,d (mm kN), per direction, from the vector. */
    Tensor<1, 3> first_moment;
    /** resultants() of each load. */
    std::vector<model::SurfaceLoads::Resultant> resultants;
  };

  /** Evaluate @p loads at time @p t on @p block's displacement. */
  Sums
  evaluate(model::SurfaceLoads &loads, Block &block, const double t)
  {
    const std::vector<model::RigidBody> bodies;
    const model::EvaluationPoint point{block.u, block.v, block.mass, bodies, t};
    VectorType                   f(block.partitioner);
    model::ContributionResults   results;
    results.reset(1, 0);
    loads.add_forces(point, f, results);
    f.compress(VectorOperation::add);
    f *= -1.;

    Sums                                 sums;
    double                               local[6] = {};
    std::vector<types::global_dof_index> dofs(block.fe.n_dofs_per_cell());
    std::vector<bool> seen(block.partitioner->locally_owned_size(), false);
    for (const auto &cell : block.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < 3; ++d)
              {
                const auto i = dofs[block.fe.component_to_system_index(d, v)];
                if (!block.partitioner->in_local_range(i))
                  continue;
                const unsigned int k = block.partitioner->global_to_local(i);
                if (seen[k])
                  continue;
                seen[k] = true;
                local[d] += f.local_element(k);
                local[3 + d] += cell->vertex(v)[0] * f.local_element(k);
              }
        }
    Utilities::MPI::sum(ArrayView<const double>(local, 6),
                        block.partitioner->get_mpi_communicator(),
                        ArrayView<double>(local, 6));
    for (unsigned int d = 0; d < 3; ++d)
      {
        sums.vector_force[d] = local[d];
        sums.first_moment[d] = local[3 + d];
      }
    sums.resultants = loads.resultants();
    return sums;
  }

  /** @p v with entries below 1e-12 |v| set to zero, for printing. */
  Tensor<1, 3>
  printable(const Tensor<1, 3> &v)
  {
    Tensor<1, 3> result = v;
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(result[d]) < 1e-12 * v.norm())
        result[d] = 0.;
    return result;
  }

  double
  relative(const Tensor<1, 3> &a, const Tensor<1, 3> &b)
  {
    return (a - b).norm() / std::max(b.norm(), 1e-300);
  }

  /** Outward unit normal and area of face id b of the undeformed block. */
  std::pair<Tensor<1, 3>, double>
  face(const unsigned int b)
  {
    const double areas[3] = {Ly * Lz, Lx * Lz, Lx * Ly};
    Tensor<1, 3> n;
    n[b / 2] = (b % 2 == 0) ? -1. : 1.;
    return {n, areas[b / 2]};
  }

  using LoadFunction = std::function<double(const Point<3> &, double)>;
  using Type         = model::BoundaryCondition::Type;
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Block                            block(MPI_COMM_WORLD);
  text() << std::setprecision(6);

  // 1. Uniform traction on x = 3, t = (0.1, -0.2, 0.3) + 0.01 t (GPa).
  {
    const std::vector<LoadFunction> traction = {
      [](const Point<3> &, double t) { return 0.1 + 0.01 * t; },
      [](const Point<3> &, double t) { return -0.2 + 0.01 * t; },
      [](const Point<3> &, double t) { return 0.3 + 0.01 * t; }};
    const double       t = 2.;
    const Tensor<1, 3> expected =
      Ly * Lz * Tensor<1, 3>({0.1 + 0.01 * t, -0.2 + 0.01 * t, 0.3 + 0.01 * t});
    for (const bool per_point : {false, true})
      {
        model::SurfaceLoads loads(block.dof_handler,
                                  block.partitioner,
                                  {make_condition("t",
                                                  1,
                                                  Type::traction,
                                                  {0, 1, 2},
                                                  traction,
                                                  per_point)});
        const Sums          sums = evaluate(loads, block, t);
        const double        e1   = relative(sums.vector_force, expected);
        const double        e2   = relative(sums.resultants[0].force, expected);
        text() << "uniform traction" << (per_point ? " (per point)" : "")
               << ": sum of nodal forces " << printable(sums.vector_force)
               << " kN, t A = " << expected << " kN, within 1e-12: "
               << (e1 < 1e-12 && e2 < 1e-12 ? "yes" : "no") << std::endl;
        measured() << "uniform traction" << (per_point ? " per point" : "")
                   << ": " << sci(std::max(e1, e2)) << std::endl;
        check(e1 < 1e-12 && e2 < 1e-12,
              "uniform traction resultant " + sci(std::max(e1, e2)));
      }
  }

  // 2. Uniform pressure p = 0.05 GPa on each face of the undeformed block.
  const double                    p        = 0.05;
  const std::vector<LoadFunction> pressure = {
    [p](const Point<3> &, double) { return p; }};
  {
    double worst = 0.;
    for (unsigned int b = 0; b < 6; ++b)
      {
        model::SurfaceLoads loads(
          block.dof_handler,
          block.partitioner,
          {make_condition("p", b, Type::pressure, {0, 1, 2}, pressure, false)});
        const Sums sums             = evaluate(loads, block, 0.);
        const auto [n, area]        = face(b);
        const Tensor<1, 3> expected = -p * area * n;
        worst                       = std::max({worst,
                                                relative(sums.vector_force, expected),
                                                relative(sums.resultants[0].force, expected)});
        text() << "pressure on face " << b << ": "
               << printable(sums.vector_force)
               << " kN, -p A n = " << printable(expected) << " kN" << std::endl;
      }
    text() << "  all within 1e-12: " << (worst < 1e-12 ? "yes" : "no")
           << std::endl;
    measured() << "flat faces: " << sci(worst) << std::endl;
    check(worst < 1e-12, "pressure on the flat faces " + sci(worst));
  }

  // 3. Rotated and stretched: F = R diag(1.3, 0.8, 1.1), R about the axis
  //    (1, 2, 2)/3 by 0.7 rad, plus a translation.
  {
    const Tensor<1, 3> axis({1. / 3., 2. / 3., 2. / 3.});
    const double       angle = 0.7;
    Tensor<2, 3>       R;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        R[i][j] = (i == j ? std::cos(angle) : 0.) +
                  (1. - std::cos(angle)) * axis[i] * axis[j];
    R[0][1] -= std::sin(angle) * axis[2];
    R[1][0] += std::sin(angle) * axis[2];
    R[0][2] += std::sin(angle) * axis[1];
    R[2][0] -= std::sin(angle) * axis[1];
    R[1][2] -= std::sin(angle) * axis[0];
    R[2][1] += std::sin(angle) * axis[0];
    Tensor<2, 3> U;
    U[0][0]              = 1.3;
    U[1][1]              = 0.8;
    U[2][2]              = 1.1;
    const Tensor<2, 3> F = R * U;
    const Tensor<1, 3> shift({0.5, -1., 2.});
    block.deform([&](const Point<3> &X) { return F * X + shift; });
    const Tensor<2, 3> cofactor = determinant(F) * transpose(invert(F));
    double             worst    = 0.;
    for (unsigned int b = 0; b < 6; ++b)
      {
        model::SurfaceLoads loads(
          block.dof_handler,
          block.partitioner,
          {make_condition("p", b, Type::pressure, {0, 1, 2}, pressure, false)});
        const Sums sums             = evaluate(loads, block, 0.);
        const auto [N, area]        = face(b);
        const Tensor<1, 3> expected = -p * area * (cofactor * N);
        worst                       = std::max({worst,
                                                relative(sums.vector_force, expected),
                                                relative(sums.resultants[0].force, expected)});
        text() << "rotated, stretched block, pressure on face " << b << ": "
               << printable(sums.vector_force)
               << " kN, -p J F^-T N A = " << printable(expected) << " kN"
               << std::endl;
      }
    text() << "  all within 1e-12: " << (worst < 1e-12 ? "yes" : "no")
           << std::endl;
    measured() << "rotated, stretched: " << sci(worst) << std::endl;
    check(worst < 1e-12, "pressure on the deformed faces " + sci(worst));
  }

  // 4. Nodes moved at random (the same on every rank: seeded, a function
  //    of the position), pressure on the whole closed surface.
  {
    block.deform(random_motion(0));
    std::vector<model::BoundaryCondition> faces;
    for (unsigned int b = 0; b < 6; ++b)
      faces.push_back(
        make_condition("p", b, Type::pressure, {0, 1, 2}, pressure, false));
    model::SurfaceLoads loads(block.dof_handler, block.partitioner, faces);
    const Sums          sums = evaluate(loads, block, 0.);
    Tensor<1, 3>        force, moment;
    for (const auto &r : sums.resultants)
      {
        force += r.force;
        moment += r.moment;
      }
    // Scale: p times the area of one face, and times the block's size.
    const double scale = p * Lx * Ly;
    const double e_f = std::max(force.norm(), sums.vector_force.norm()) / scale;
    const double e_m = moment.norm() / (scale * Lx);
    text() << "randomly deformed block, pressure on all faces: |resultant| / "
              "(p A) below 1e-13: "
           << (e_f < 1e-13 ? "yes" : "no")
           << ", |moment| / (p A L) below 1e-13: "
           << (e_m < 1e-13 ? "yes" : "no") << std::endl;
    measured() << "closed surface: " << sci(e_f) << " " << sci(e_m)
               << std::endl;
    check(e_f < 1e-13 && e_m < 1e-13,
          "closed surface " + sci(e_f) + " " + sci(e_m));
  }

  // 5. Linear traction t_z = c x on y = 0, undeformed.
  {
    block.u = 0.;
    block.u.update_ghost_values();
    const double        c = 0.02;
    model::SurfaceLoads loads(block.dof_handler,
                              block.partitioner,
                              {make_condition("linear",
                                              2,
                                              Type::traction,
                                              {2},
                                              {[c](const Point<3> &X, double) {
                                                return c * X[0];
                                              }},
                                              true)});
    const Sums          sums         = evaluate(loads, block, 0.);
    const double        force        = c * Lz * Lx * Lx / 2.;
    const double        first_moment = c * Lz * Lx * Lx * Lx / 3.;
    const Tensor<1, 3>  expected_moment({0., -first_moment, 0.});
    const double        e_f =
      std::abs(sums.vector_force[2] / force - 1.) +
      std::abs(sums.resultants[0].force[2] / force - 1.) +
      (std::abs(sums.vector_force[0]) + std::abs(sums.vector_force[1])) / force;
    const double e_m = std::abs(sums.first_moment[2] / first_moment - 1.) +
                       relative(sums.resultants[0].moment, expected_moment);
    text() << "linear traction c x: resultant " << sums.vector_force[2]
           << " kN (c Lz Lx^2 / 2 = " << force << "), first moment "
           << sums.first_moment[2] << " kN mm (c Lz Lx^3 / 3 = " << first_moment
           << "), moment about 0 " << sums.resultants[0].moment
           << " kN mm; within 1e-12: "
           << (e_f < 1e-12 && e_m < 1e-12 ? "yes" : "no") << std::endl;
    measured() << "linear traction: " << sci(e_f) << " " << sci(e_m)
               << std::endl;
    check(e_f < 1e-12 && e_m < 1e-12,
          "linear traction " + sci(e_f) + " " + sci(e_m));
  }

  // 6. The implicit solver's tangent (SurfaceLoads::add_tangents()): on the
  //    randomly deformed block, a pressure varying with position on all six
  //    faces and a traction on x = 3. For a random direction w, K w against
  //    the central difference (f(u + e w) - f(u - e w)) / (2 e), e = 1e-5
  //    mm, of the same rank's (uncompressed) forces: the pressure's forces
  //    are quadratic in the nodal positions on each face, so the central
  //    difference is exact but for round-off (~1e-16 / e relative): within
  //    1e-8 of |K w|. The traction adds no tangent (a dead load), and its
  //    forces do not change with u: their difference vanishes.
  {
    block.deform(random_motion(7));
    std::vector<model::BoundaryCondition> conditions;
    for (unsigned int b = 0; b < 6; ++b)
      conditions.push_back(make_condition("p",
                                          b,
                                          Type::pressure,
                                          {0, 1, 2},
                                          {[](const Point<3> &X, double) {
                                            return 0.01 * (1. + X[0] * X[1]);
                                          }},
                                          true));
    conditions.push_back(
      make_condition("t",
                     1,
                     Type::traction,
                     {0, 1, 2},
                     {[](const Point<3> &, double) { return 0.01; },
                      [](const Point<3> &, double) { return -0.02; },
                      [](const Point<3> &, double) { return 0.03; }},
                     false));
    model::SurfaceLoads loads(block.dof_handler, block.partitioner, conditions);
    const std::vector<model::RigidBody> bodies;

    // A random direction at every local (owned and ghost) entry, the same
    // value for a dof on every rank (seeded by its global index).
    VectorType w(block.partitioner);
    for (unsigned int i = 0;
         i < w.locally_owned_size() + block.partitioner->n_ghost_indices();
         ++i)
      {
        std::mt19937 generator(block.partitioner->local_to_global(i));
        w.local_element(i) =
          std::uniform_real_distribution<double>(-1., 1.)(generator);
      }
    const auto forces = [&](const VectorType &u) {
      const model::EvaluationPoint point{u, block.v, block.mass, bodies, 0.};
      VectorType                   f(block.partitioner);
      model::ContributionResults   results;
      results.reset(1, 0);
      loads.add_forces(point, f, results);
      return f;
    };
    const double e = 1e-5;
    VectorType   plus(block.u), minus(block.u);
    plus.add(e, w);
    minus.add(-e, w);
    // (add() changes the owned entries: the faces see the ghosts too.)
    plus.update_ghost_values();
    minus.update_ghost_values();
    const VectorType f_plus = forces(plus), f_minus = forces(minus);

    VectorType                   Kw(block.partitioner);
    const model::EvaluationPoint point{block.u,
                                       block.v,
                                       block.mass,
                                       bodies,
                                       0.};
    unsigned int                 n_blocks = 0;
    loads.add_tangents(point,
                       [&](const std::vector<types::global_dof_index> &dofs,
                           const std::vector<double>                  &K) {
                         ++n_blocks;
                         const unsigned int n = dofs.size();
                         for (unsigned int i = 0; i < n; ++i)
                           for (unsigned int j = 0; j < n; ++j)
                             Kw(dofs[i]) += K[n * i + j] * w(dofs[j]);
                       });
    double local[2] = {0., 0.};
    for (unsigned int i = 0;
         i < w.locally_owned_size() + block.partitioner->n_ghost_indices();
         ++i)
      {
        const double difference =
          (f_plus.local_element(i) - f_minus.local_element(i)) / (2. * e);
        local[0] += std::pow(Kw.local_element(i) - difference, 2);
        local[1] += std::pow(Kw.local_element(i), 2);
      }
    Utilities::MPI::sum(ArrayView<const double>(local, 2),
                        block.partitioner->get_mpi_communicator(),
                        ArrayView<double>(local, 2));
    const double error = std::sqrt(local[0] / local[1]);
    n_blocks =
      Utilities::MPI::sum(n_blocks, block.partitioner->get_mpi_communicator());
    text() << "load stiffness: " << n_blocks
           << " face blocks (the pressed faces); |K w - central difference| "
              "/ |K w| below 1e-8: "
           << (error < 1e-8 ? "yes" : "no") << "; symmetric tangent: "
           << (loads.symmetric_tangent() ? "yes" : "no") << std::endl;
    measured() << "load stiffness: " << sci(error) << std::endl;
    check(error < 1e-8 && !loads.symmetric_tangent(),
          "load stiffness " + sci(error));
  }
  return 0;
}
