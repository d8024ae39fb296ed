// Models of the shipped examples built in C++ for the unit tests of
// tests/model (the .prm files of parameter_files/ transcribed).
#ifndef rubberdyn_tests_model_model_fixtures_h
#define rubberdyn_tests_model_model_fixtures_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <rubberdyn/io/gmsh_mesh.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/yeoh.h>
#include <rubberdyn/model/model.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

namespace fixtures
{
  using namespace dealii;
  using namespace rubberdyn;

  /** parameter_files/meshes/ of the source tree. */
  inline std::string
  mesh_directory()
  {
    return std::string(SOURCE_DIR) + "/../../parameter_files/meshes/";
  }

  /**
   * The rubber of the shipped examples: Yeoh, C10 = 0.00055, C20 =
   * -0.00005, C30 = 0.000015 GPa, Poisson's ratio 0.499 (K = 2 G (1 + nu) /
   * (3 (1 - 2 nu)), G = 2 C10, d1 = 2 / K), density 1.1e-6 kg/mm^3.
   */
  inline std::unique_ptr<materials::MaterialModel<3>>
  rubber_law()
  {
    const double C10 = 0.00055, nu = 0.499, G = 2. * C10;
    const double K = 2. * G * (1. + nu) / (3. * (1. - 2. * nu));
    return std::make_unique<materials::Yeoh<3>>(C10,
                                                -0.00005,
                                                0.000015,
                                                std::array<double, 3>{
                                                  {2. / K, 0., 0.}},
                                                1.1e-6);
  }

  /** A part @p name of material id @p id made of rubber_law(). */
  inline model::Part
  rubber_part(const std::string &name, const types::material_id id)
  {
    model::Part part;
    part.name         = name;
    part.material_ids = {id};
    part.law          = rubber_law();
    return part;
  }

  /**
   * A part @p name of material id @p id made of the examples' steel
   * (Elastic, E = 210 GPa, nu = 0.3, 7.85e-6 kg/mm^3).
   */
  inline model::Part
  steel_part(const std::string &name, const types::material_id id)
  {
    model::Part part;
    part.name         = name;
    part.material_ids = {id};
    part.law = std::make_unique<materials::Elastic<3>>(210., 0.3, 7.85e-6);
    return part;
  }

  /**
   * Set @p u (the Model's Q1 dofs) at every vertex of the locally owned and
   * ghost cells to @p displacement(material id of the cell, X) (mm), ghost
   * entries included. Bodies that share vertices must agree there.
   */
  inline void
  set_vertex_displacements(
    const model::Model &model,
    VectorType         &u,
    const std::function<Tensor<1, 3>(types::material_id, const Point<3> &)>
      &displacement)
  {
    for (const auto &cell : model.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const unsigned int vertex : cell->vertex_indices())
          {
            const Tensor<1, 3> value =
              displacement(cell->material_id(), cell->vertex(vertex));
            for (unsigned int d = 0; d < 3; ++d)
              u(cell->vertex_dof_index(vertex, d)) = value[d];
          }
  }

  /**
   * The largest component of the sum of all nodal forces @p f (owned
   * entries of the Model's Q1 dofs, which it numbers vertex by vertex, x,
   * y, z: the component is the global index modulo 3), over the ranks
   * (kN). Zero when the forces balance. Collective.
   */
  inline double
  largest_force_sum(const VectorType &f, const MPI_Comm comm)
  {
    double sum[3] = {0., 0., 0.};
    for (unsigned int i = 0; i < f.locally_owned_size(); ++i)
      sum[f.get_partitioner()->local_to_global(i) % 3] += f.local_element(i);
    double largest = 0.;
    for (const double component : sum)
      largest =
        std::max(largest, std::abs(Utilities::MPI::sum(component, comm)));
    return largest;
  }

  /**
   * meshes/block_on_plate.msh (a block 10 x 10 x 5 mm, volume 1, standing
   * on a plate 20 x 20 x 2 mm, volume 2, with separate nodes: the contact
   * pairs' tests) with the part @p block on the block and the examples'
   * steel (steel_part()) as the plate. Ends with model.setup().
   */
  inline void
  make_block_on_plate(model::Model &model, model::Part block)
  {
    io::read_gmsh_mesh(model.triangulation,
                       mesh_directory() + "block_on_plate.msh",
                       "Mesh/Mesh file");
    model.parts.push_back(std::move(block));
    model.parts.push_back(steel_part("plate", 2));
    model.setup();
  }

  /**
   * parameter_files/bonded_block.prm: meshes/bonded_block.msh (rubber,
   * volume 1, bonded to a steel plate, volume 2, on top), parts `rubber`
   * (Yeoh) and `steel` (Elastic, E = 210 GPa, nu = 0.3, 7.85e-6 kg/mm^3),
   * F-bar; `base` (surface 1) fixed, `press` (surface 2) pushed down in z by
   * d (t / T - sin(2 pi t / T) / (2 pi)), d = 1 mm, T = 2 ms, then held.
   * Ends with model.setup().
   */
  inline void
  make_bonded_block(model::Model &model)
  {
    io::read_gmsh_mesh(model.triangulation,
                       mesh_directory() + "bonded_block.msh",
                       "Mesh/Mesh file");
    model.parts.push_back(rubber_part("rubber", 1));
    model.parts.push_back(steel_part("steel", 2));
    model::BoundaryCondition base, press;
    base.name          = "base";
    base.boundary_ids  = {1};
    press.name         = "press";
    press.boundary_ids = {2};
    press.type         = model::BoundaryCondition::Type::displacement;
    press.components   = {2};
    const double d = 1., T = 2.;
    press.functions.push_back([=](const Point<3> &, const double t) {
      return t < T ? -d * (t / T - std::sin(2. * numbers::PI * t / T) /
                                     (2. * numbers::PI)) :
                     -d;
    });
    model.boundary_conditions.push_back(base);
    model.boundary_conditions.push_back(press);
    model.setup();
  }

  /**
   * parameter_files/rigid_drop.prm: meshes/rigid_drop.msh (a rubber block
   * 20 x 20 x 10 mm, volume 1, on the floor; a steel block 10 x 10 x 5 mm,
   * volume 2, centred 5 mm above it), parts `rubber` (Yeoh, F-bar) and
   * `block` (Model = Rigid: E = 210 GPa, nu = 0.3, 7.85e-6 kg/mm^3, free,
   * with @p velocity and @p angular_velocity at t = 0); `floor` (surface 1)
   * fixed; if @p with_sole, the rigid plane `sole` at the block's bottom
   * (z = 15, normal -z) carried by the block, touching the rubber top
   * (surface 2). Gravity @p gravity. Ends with model.setup().
   */
  inline void
  make_rigid_drop(model::Model &      model,
                  const Tensor<1, 3> &velocity,
                  const Tensor<1, 3> &angular_velocity,
                  const Tensor<1, 3> &gravity,
                  const bool          with_sole)
  {
    io::read_gmsh_mesh(model.triangulation,
                       mesh_directory() + "rigid_drop.msh",
                       "Mesh/Mesh file");
    model::Part block              = steel_part("block", 2);
    block.rigid                    = true;
    block.initial_velocity         = velocity;
    block.initial_angular_velocity = angular_velocity;
    model.parts.push_back(rubber_part("rubber", 1));
    model.parts.push_back(std::move(block));
    model::BoundaryCondition floor;
    floor.name         = "floor";
    floor.boundary_ids = {1};
    model.boundary_conditions.push_back(floor);
    if (with_sole)
      {
        model::RigidSurfaceDefinition sole;
        sole.name                 = "sole";
        sole.surface.point        = Point<3>(10., 10., 15.);
        sole.surface.normal       = Tensor<1, 3>({0., 0., -1.});
        sole.boundary_ids         = {2};
        sole.rigid_part           = "block";
        model.rigid_surfaces.push_back(sole);
      }
    model.gravity = gravity;
    model.setup();
  }
} // namespace fixtures

#endif
