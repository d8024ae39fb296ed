// Element groups: a model of several parts, each with its own law and its
// own formulation, some material ids in no group (a rigid part).
// A 4 x 3 x 1 block of distorted 5 mm cells, material id by column: 1, 2,
// 3, 9. Group 0 = ids {1, 3}, Yeoh rubber, F-bar (6 cells: one full block
// and one of 2 lanes); group 1 = id {2}, steel, displacement element (3
// cells: one block of 3 lanes); id 9 is in no group (no element).
//
// Checks, each against an independent computation:
// - 9 elements, 2 groups; the mass of each group equals its density times
//   the volume of its cells from deal.II's cell->measure() (1e-12);
// - with a random displacement and velocity, the forces, the per-group
//   internal energies, the viscous power and the stable step of the
//   two-group model equal those of two one-group models, each holding one
//   part alone (1e-12: only the order of the sums differs);
// - the formulation is per group: group 1's energy is that of the
//   displacement element, not of F-bar, and group 0's that of F-bar;
// - the nodes of the rigid column only (x = 20 mm) get no force;
// - internal_energy is the sum of internal_energy_by_group, which is sized
//   once: a second evaluation with the same result object reuses its
//   storage and gives the same numbers;
// - a material id in two groups, and a group without a law, are refused
//   with std::invalid_argument.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/yeoh.h>

#include <random>
#include <stdexcept>

#include "../tests.h"
#include "distorted_block.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  struct Evaluation
  {
    VectorType                  f;
    elements::ElementStepResult result;
  };

  Evaluation
  evaluate(elements::SolidHexElements &hexes,
           const VectorType &          u,
           const VectorType &          v)
  {
    Evaluation e{VectorType(u.get_partitioner()), {}};
    hexes.compute_forces(u,
                         v,
                         std::vector<double>(hexes.n_elements(), 1.),
                         e.f,
                         e.result);
    check(!e.result.failure.failed, "no element fails");
    return e;
  }

  double
  relative_difference(const double a, const double b)
  {
    return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Triangulation<3>                 tria;
  fixtures::make_distorted_block(tria, 4, 3);
  const types::material_id id_of_column[4] = {1, 2, 3, 9};
  for (const auto &cell : tria.active_cell_iterators())
    cell->set_material_id(
      id_of_column[static_cast<unsigned int>(cell->center()[0] / 5.)]);
  FESystem<3>   fe(FE_Q<3>(1), 3);
  DoFHandler<3> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
    dof_handler.locally_owned_dofs(), MPI_COMM_SELF);

  const materials::Yeoh<3>    rubber(0.55e-3,
                                  -0.05e-3,
                                  0.015e-3,
                                  std::array<double, 3>{{2. / 1.65, 0., 0.}},
                                  1.1e-6);
  const materials::Elastic<3> steel(210., 0.3, 7.85e-6);
  const elements::ElementGroup rubber_part{{1, 3},
                                           &rubber,
                                           elements::Formulation::fbar};
  const elements::ElementGroup steel_part{{2},
                                          &steel,
                                          elements::Formulation::displacement};
  const elements::ElementSettings settings; // bulk viscosity on

  elements::SolidHexElements model, rubber_alone, steel_alone,
    steel_alone_fbar, rubber_alone_displacement;
  model.initialize(dof_handler, partitioner, {rubber_part, steel_part}, settings);
  rubber_alone.initialize(dof_handler, partitioner, {rubber_part}, settings);
  steel_alone.initialize(dof_handler, partitioner, {steel_part}, settings);
  steel_alone_fbar.initialize(dof_handler,
                              partitioner,
                              {{{2}, &steel, elements::Formulation::fbar}},
                              settings);
  rubber_alone_displacement.initialize(
    dof_handler,
    partitioner,
    {{{1, 3}, &rubber, elements::Formulation::displacement}},
    settings);

  // Counts and masses.
  out() << "groups " << model.n_groups() << ", elements " << model.n_elements()
        << " (rubber " << rubber_alone.n_elements() << ", steel "
        << steel_alone.n_elements() << ")" << std::endl;
  check(model.n_groups() == 2 && model.n_elements() == 9 &&
          rubber_alone.n_elements() == 6 && steel_alone.n_elements() == 3,
        "9 elements in 2 groups, none for material id 9");
  double volume[2] = {0., 0.};
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->material_id() != 9)
      volume[cell->material_id() == 2 ? 1 : 0] += cell->measure();
  const std::vector<double> mass =
    model.mass_by_group(std::vector<double>(model.n_elements(), 1.));
  const double mass_error =
    std::max(relative_difference(mass[0], rubber.density() * volume[0]),
             relative_difference(mass[1], steel.density() * volume[1]));
  out() << "mass by group (kg): " << std::setprecision(8) << mass[0] << ", "
        << mass[1] << "; equal to density x cell volumes to 1e-12: "
        << (mass_error < 1e-12 ? "yes" : "no") << std::endl;
  check(mass_error < 1e-12, "mass by group");

  // A random state: 5 % compression along z with a shear, plus a random
  // perturbation of every dof (0.05 mm), and random velocities (1 mm/ms).
  std::mt19937                           generator(3);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  VectorType                             u(partitioner), v(partitioner);
  {
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto     ci = fe.system_to_component_index(i);
            const Point<3> X  = cell->vertex(ci.second);
            u[dofs[i]] = (ci.first == 2 ? -0.05 * X[2] : 0.) +
                         (ci.first == 0 ? 0.02 * X[2] : 0.);
          }
      }
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        u[i] += 0.05 * uniform(generator);
        v[i] = uniform(generator);
      }
  }

  const Evaluation all       = evaluate(model, u, v);
  const Evaluation rubber_e  = evaluate(rubber_alone, u, v);
  const Evaluation steel_e   = evaluate(steel_alone, u, v);
  const Evaluation steel_fb  = evaluate(steel_alone_fbar, u, v);
  const Evaluation rubber_dp = evaluate(rubber_alone_displacement, u, v);

  double max_force = 0., force_error = 0.;
  for (unsigned int i = 0; i < u.size(); ++i)
    {
      max_force = std::max(max_force, std::abs(all.f[i]));
      force_error = std::max(force_error,
                             std::abs(all.f[i] - rubber_e.f[i] - steel_e.f[i]));
    }
  force_error /= max_force;
  const auto &r = all.result;
  check(r.internal_energy_by_group.size() == 2, "two group energies");
  const double energy_error = std::max(
    {relative_difference(r.internal_energy_by_group[0],
                         rubber_e.result.internal_energy),
     relative_difference(r.internal_energy_by_group[1],
                         steel_e.result.internal_energy),
     relative_difference(r.internal_energy,
                         r.internal_energy_by_group[0] +
                           r.internal_energy_by_group[1])});
  const double power_error =
    relative_difference(r.bulk_viscosity_power,
                        rubber_e.result.bulk_viscosity_power +
                          steel_e.result.bulk_viscosity_power);
  const double step_error =
    relative_difference(r.min_time_step,
                        std::min(rubber_e.result.min_time_step,
                                 steel_e.result.min_time_step));
  out() << "internal energy by group (J): rubber " << std::setprecision(6)
        << r.internal_energy_by_group[0] << ", steel "
        << r.internal_energy_by_group[1] << "; total " << r.internal_energy
        << std::endl;
  out() << "two-group model = the two parts alone, to 1e-12: forces "
        << (force_error < 1e-12 ? "yes" : "no") << ", energies "
        << (energy_error < 1e-12 ? "yes" : "no") << ", viscous power "
        << (power_error < 1e-12 ? "yes" : "no") << ", stable step "
        << (step_error < 1e-12 ? "yes" : "no") << std::endl;
  std::cerr << "differences: force " << sci(force_error) << ", energy "
            << sci(energy_error) << ", power " << sci(power_error)
            << ", step " << sci(step_error) << std::endl;
  check(force_error < 1e-12 && energy_error < 1e-12 && power_error < 1e-12 &&
          step_error < 1e-12,
        "two-group model equals its parts");

  // The formulation is the group's: the two formulations differ by more
  // than 1e-4 here, the model matches its own to 1e-12.
  out() << "steel energy: displacement " << std::setprecision(6)
        << steel_e.result.internal_energy << " J, F-bar "
        << steel_fb.result.internal_energy << " J; rubber: F-bar "
        << rubber_e.result.internal_energy << " J, displacement "
        << rubber_dp.result.internal_energy << " J" << std::endl;
  check(relative_difference(steel_e.result.internal_energy,
                            steel_fb.result.internal_energy) > 1e-4 &&
          relative_difference(rubber_e.result.internal_energy,
                              rubber_dp.result.internal_energy) > 1e-4,
        "the formulations differ on this state");

  // The rigid column's own nodes (x = 20 mm before distortion: the
  // distortion leaves x + 0.1 sin(..) z) get nothing.
  {
    double                               rigid_force = 0.;
    unsigned int                         n_rigid     = 0;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->material_id() == 9)
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const auto ci = fe.system_to_component_index(i);
              // Vertices 1, 3, 5, 7 are on the face x = 20 (lexicographic).
              if (ci.second % 2 == 1)
                {
                  rigid_force = std::max(rigid_force, std::abs(all.f[dofs[i]]));
                  ++n_rigid;
                }
            }
        }
    out() << "largest force on the nodes of the rigid column's far face ("
          << n_rigid / 3 << " counted per cell): " << rigid_force << std::endl;
    check(rigid_force == 0., "no force on nodes of the rigid part only");
  }

  // The result object is reused without reallocation.
  {
    elements::ElementStepResult reused = all.result;
    const double *const storage = reused.internal_energy_by_group.data();
    VectorType          f(partitioner);
    model.compute_forces(
      u, v, std::vector<double>(model.n_elements(), 1.), f, reused);
    const bool same =
      reused.internal_energy_by_group.data() == storage &&
      reused.internal_energy_by_group == all.result.internal_energy_by_group &&
      reused.internal_energy == all.result.internal_energy;
    out() << "a reused result keeps its storage and is overwritten: "
          << (same ? "yes" : "no") << std::endl;
    check(same, "result reused");
  }

  // Bad groups.
  const auto refused = [&](const std::vector<elements::ElementGroup> &groups) {
    elements::SolidHexElements hexes;
    try
      {
        hexes.initialize(dof_handler, partitioner, groups, settings);
      }
    catch (const std::invalid_argument &e)
      {
        out() << "refused: " << e.what() << std::endl;
        return true;
      }
    return false;
  };
  check(refused({rubber_part, {{2, 3}, &steel, elements::Formulation::fbar}}),
        "a material id in two groups is refused");
  check(refused({{{1}, nullptr, elements::Formulation::fbar}}),
        "a group without a law is refused");
}
