// The element stable step is a bound: for single free hexahedra of
// several shapes, the step the element layer reports at rest is at most
// the critical step 2 / omega_max of central differences, omega_max^2 the
// largest eigenvalue of M^-1 K with the lumped mass M (add_lumped_mass)
// and the element's own tangent K, taken by central differences of its
// internal forces (step 1e-7 mm; the eigenvalue to about 1e-8). A single
// free element is the worst case: the largest frequency of an assembled
// mesh is at most the largest of its elements' (the element eigenvalue
// inequality, T. J. R. Hughes, The Finite Element Method, Dover 2000,
// ch. 9), each with its share of the lumped mass. doc/theory.md
// section 8.3 derives the bound (Flanagan and Belytschko, IJNME 17
// (1981) 679-706) and has the table this test prints.
//
// Shapes (h = 2 mm): a cube, a 1:1:4 brick, a 4:4:1 plate, two cubes with
// every vertex moved randomly by up to 0.25 h and 0.35 h (fixed seeds), a
// frustum (top face 0.4 h wide), a cube sheared by 45 degrees, and the
// two kinds of cells of the drop test's coarsest mesh (diameter 25 mm,
// height 24 mm, `Global refinement` 0: a centre cell and a ring cell,
// whose old length was the most pessimistic).
// Materials: the shipped rubber (Yeoh, nu = 0.499) and steel (E = 210 GPa,
// nu = 0.3). Elements: F-bar with `F-bar stabilization` 0 and 1 (the
// range's ends; the step adds kappa / r_c with r_c = 0.25 the collapse
// ratio, four times the stabilisation's stiffness at rest), and the
// displacement element.
//
// Printed: dt / (2 / omega_max) for the step and, for comparison, for the
// old length volume / largest face area. Checked: the step's ratio is at
// most 1 + 1e-6 (the finite-difference error), and, without the
// stabilisation, at least 0.75 (the bound is attained by the breathing
// mode of a parallelepiped in the incompressible limit, and within
// 25 % for nu = 0.3 and the distorted shapes; measured at least 0.79).
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/geometry/standing_cylinder.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/yeoh.h>

#include <cstdio>
#include <random>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;

namespace
{
  /** Volume / largest face area, faces by their diagonals (the old l). */
  double
  old_length(const std::vector<Point<3>> &x, const double volume)
  {
    const unsigned int faces[6][4] = {{0, 2, 4, 6},
                                      {1, 3, 5, 7},
                                      {0, 1, 4, 5},
                                      {2, 3, 6, 7},
                                      {0, 1, 2, 3},
                                      {4, 5, 6, 7}};
    double             largest     = 0.;
    for (const auto &f : faces)
      largest = std::max(
        largest,
        0.5 * cross_product_3d(x[f[3]] - x[f[0]], x[f[2]] - x[f[1]]).norm());
    return volume / largest;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     h = 2.;

  // Materials.
  const double G_r = 1.1e-3, nu_r = 0.499;
  const double K_r = 2. * G_r * (1. + nu_r) / (3. * (1. - 2. * nu_r));
  const materials::Yeoh<3>    rubber(0.55e-3,
                                  -0.05e-3,
                                  0.015e-3,
                                  std::array<double, 3>{{2. / K_r, 0., 0.}},
                                  1.1e-6);
  const materials::Elastic<3> steel(210., 0.3, 7.85e-6);
  const std::vector<std::pair<std::string, const materials::MaterialModel<3> *>>
    laws = {{"rubber", &rubber}, {"steel", &steel}};

  // Shapes, vertices in deal.II's lexicographic order.
  const auto box = [&](const double a, const double b, const double c) {
    std::vector<Point<3>> x(8);
    for (unsigned int v = 0; v < 8; ++v)
      x[v] = Point<3>(a * (v & 1), b * ((v >> 1) & 1), c * ((v >> 2) & 1));
    return x;
  };
  const auto distorted = [&](const double amplitude, const unsigned int seed) {
    std::vector<Point<3>>                  x = box(h, h, h);
    std::mt19937                           generator(seed);
    std::uniform_real_distribution<double> shift(-amplitude, amplitude);
    for (auto &p : x)
      for (unsigned int d = 0; d < 3; ++d)
        p[d] += shift(generator);
    return x;
  };
  std::vector<std::pair<std::string, std::vector<Point<3>>>> shapes = {
    {"cube", box(h, h, h)},
    {"brick 1:1:4", box(h, h, 4. * h)},
    {"plate 4:4:1", box(4. * h, 4. * h, h)},
    {"distorted 0.25 h", distorted(0.25 * h, 1)},
    {"distorted 0.35 h", distorted(0.35 * h, 7)}};
  {
    std::vector<Point<3>> x = box(h, h, h);
    for (unsigned int v = 4; v < 8; ++v)
      x[v] = Point<3>((0.3 + 0.4 * (v & 1)) * h,
                      (0.3 + 0.4 * ((v >> 1) & 1)) * h,
                      h);
    shapes.emplace_back("frustum", x);
    x = box(h, h, h);
    for (auto &p : x)
      p[0] += p[2];
    shapes.emplace_back("sheared 45 deg", x);
    // The drop test's coarse cells: the one on the axis and one of the
    // ring around it (GridGenerator::subdivided_cylinder).
    Triangulation<3> cylinder;
    geometry::make_standing_cylinder(cylinder, 25., 24., 0);
    const auto radius = [](const auto &cell) {
      return std::hypot(cell->center()[0], cell->center()[1]);
    };
    auto centre = cylinder.begin_active(), ring = cylinder.begin_active();
    for (const auto &cell : cylinder.active_cell_iterators())
      {
        if (radius(cell) < radius(centre))
          centre = cell;
        if (radius(cell) > radius(ring))
          ring = cell;
      }
    for (const auto &[name, cell] :
         {std::make_pair(std::string("drop test centre"), centre),
          std::make_pair(std::string("drop test ring"), ring)})
      {
        std::vector<Point<3>> vertices(8);
        for (unsigned int v = 0; v < 8; ++v)
          vertices[v] = cell->vertex(v);
        shapes.emplace_back(name, vertices);
      }
  }

  struct Element
  {
    std::string           name;
    elements::Formulation formulation;
    double                stabilization;
  };
  const std::vector<Element> element_types = {
    {"F-bar", elements::Formulation::fbar, 0.},
    {"F-bar, stab. 1", elements::Formulation::fbar, 1.},
    {"displacement", elements::Formulation::displacement, 0.}};

  char line[200];
  std::snprintf(line,
                sizeof(line),
                "%-17s %-7s %-15s %9s %9s",
                "shape",
                "law",
                "element",
                "dt/dt_cr",
                "old l");
  out() << line << std::endl;
  double worst = 0., best_unstabilized = 1e300;
  for (const auto &[shape_name, vertices] : shapes)
    for (const auto &[law_name, law] : laws)
      for (const Element &element : element_types)
        {
          Triangulation<3> tria;
          GridGenerator::general_cell(tria, vertices);
          const FESystem<3> fe(FE_Q<3>(1), 3);
          DoFHandler<3>     dof_handler(tria);
          dof_handler.distribute_dofs(fe);
          const auto partitioner =
            std::make_shared<Utilities::MPI::Partitioner>(
              dof_handler.locally_owned_dofs(),
              MPI_COMM_SELF);
          const elements::ElementSettings settings;
          elements::SolidHexElements      hexes;
          hexes.initialize(dof_handler,
                           partitioner,
                           {{{0}, law, element.formulation, element.stabilization}},
                           settings);
          VectorType mass(partitioner);
          hexes.add_lumped_mass(mass, {1.});

          // K by central differences, symmetrised, then M^-1/2 K M^-1/2.
          VectorType u(partitioner), v(partitioner), f_plus(partitioner),
            f_minus(partitioner);
          elements::ElementStepResult result;
          const double                delta = 1e-7;
          LAPACKFullMatrix<double>    A(24, 24);
          for (unsigned int j = 0; j < 24; ++j)
            {
              f_plus  = 0.;
              f_minus = 0.;
              u[j]    = delta;
              hexes.compute_forces(u, v, {1.}, f_plus, result);
              u[j] = -delta;
              hexes.compute_forces(u, v, {1.}, f_minus, result);
              u[j] = 0.;
              for (unsigned int i = 0; i < 24; ++i)
                A(i, j) = (f_plus[i] - f_minus[i]) / (2. * delta);
            }
          for (unsigned int i = 0; i < 24; ++i)
            for (unsigned int j = 0; j < i; ++j)
              A(i, j) = A(j, i) = 0.5 * (A(i, j) + A(j, i));
          for (unsigned int i = 0; i < 24; ++i)
            for (unsigned int j = 0; j < 24; ++j)
              A(i, j) /= std::sqrt(mass[i] * mass[j]);
          A.compute_eigenvalues();
          double largest = 0.;
          for (unsigned int i = 0; i < 24; ++i)
            largest = std::max(largest, A.eigenvalue(i).real());
          const double critical = 2. / std::sqrt(largest);

          // The reported step at rest (no bulk viscosity without a rate).
          u      = 0.;
          f_plus = 0.;
          hexes.compute_forces(u, v, {1.}, f_plus, result);
          const double step = result.min_time_step;
          check(std::abs(hexes.reference_time_steps()[0] - step) <=
                  1e-12 * step,
                "the reference step is the step at rest");
          // The old step: the old length over the same wave speed.
          double volume = 0.;
          for (unsigned int i = 0; i < 24; ++i)
            volume += mass[i];
          volume /= 3. * law->density();
          const double wave_speed =
            std::sqrt(std::pow(law->reference_wave_speed(), 2) +
                      element.stabilization * law->bulk_modulus() /
                        (law->density() * settings.fbar_collapse_ratio));
          const double old_step = old_length(vertices, volume) / wave_speed;

          const double ratio = step / critical;
          worst              = std::max(worst, ratio);
          if (element.stabilization == 0.)
            best_unstabilized = std::min(best_unstabilized, ratio);
          std::snprintf(line,
                        sizeof(line),
                        "%-17s %-7s %-15s %9.3f %9.3f",
                        shape_name.c_str(),
                        law_name.c_str(),
                        element.name.c_str(),
                        ratio,
                        old_step / critical);
          out() << line << std::endl;
        }
  out() << "every step at most the critical step: "
        << (worst <= 1. + 1e-6 ? "yes" : "no") << std::endl;
  check(worst <= 1. + 1e-6, "the step is at most 2 / omega_max");
  check(best_unstabilized >= 0.75,
        "without stabilisation the step is at least 0.75 of the critical");
}
