// The message of an F-bar hull collapse names the part that collapsed
// (simulation::setup::element_groups()): in a model of several deformable parts
// the user must know which part's `Parts/<name>/F-bar stabilization` to
// raise, or that the model-wide `Time integration/F-bar stabilization`
// covers them all.
//
// Why: bushing test 1 at the default mesh with every stabilisation off
// (2026-12-07) stopped at 3.0 ms with "set Time integration/F-bar
// stabilization to 0.03 or more", which named neither the washer that had
// collapsed nor its own entry; finding the part took a script over the
// ParaView output.
//
// On the meshes of the shipped examples (tests/model/model_fixtures.h), one
// rank: a corner vertex of the mesh that only one cell of the part uses is
// moved to that cell's centre, which leaves the Gauss point next to it
// about 0.11 of the centre's volume (tests/elements/fbar_collapse_detection:
// the pinched cube), below the limit 0.25. Checked, the whole message after
// "... no longer physical; ":
// - bonded_block (rubber and steel, both F-bar), the steel pinched:
//   "set Parts/steel/F-bar stabilization (this part) or Time
//   integration/F-bar stabilization (every part without its own) to 0.03
//   or more";
// - the same, the rubber pinched: the same with `rubber`;
// - the same with the rubber's own beta 0.05: "raise Parts/rubber/F-bar
//   stabilization above 0.05";
// - rigid_drop (the rubber the one deformable part, a rigid block): "set
//   Time integration/F-bar stabilization to 0.03 or more", as in the drop
//   test study, whose input has no Parts section.
// Fails on the code before this test: every message there named the
// model-wide entry alone.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/parameters/time_integration_parameters.h>
#include <rubberdyn/simulation/simulation_setup.h>

#include <string>

#include "../tests.h"
#include "model_fixtures.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;

namespace
{
  /**
   * The failure message of the model's elements when a corner vertex used
   * by only one cell, a cell of material id @p id, is moved to that cell's
   * centre; empty if nothing fails.
   */
  std::string
  pinched_message(const model::Model &model, const types::material_id id)
  {
    const auto cells_at_vertex =
      GridTools::vertex_to_cell_map(model.triangulation);

    VectorType u(model.partitioner), v(model.partitioner), f(model.partitioner);
    bool       pinched = false;
    for (const auto &cell : model.dof_handler.active_cell_iterators())
      if (!pinched && cell->material_id() == id)
        for (const unsigned int vertex : cell->vertex_indices())
          if (!pinched &&
              cells_at_vertex[cell->vertex_index(vertex)].size() == 1)
            {
              const Tensor<1, 3> to_centre =
                cell->center() - cell->vertex(vertex);
              for (unsigned int d = 0; d < 3; ++d)
                u(cell->vertex_dof_index(vertex, d)) = to_centre[d];
              pinched = true;
            }
    check(pinched, "a corner vertex of material id " + std::to_string(id));

    elements::SolidHexElements hexes;
    hexes.initialize(model.dof_handler,
                     model.partitioner,
                     simulation::setup::element_groups(
                       model, parameters::TimeIntegration()),
                     elements::ElementSettings());
    const std::vector<double>   no_scaling(model.triangulation.n_active_cells(),
                                         1.);
    elements::ElementStepResult result;
    hexes.compute_forces(u, v, no_scaling, f, result);
    return result.failure.failed ? result.failure.message : std::string();
  }

  /** Check that @p message ends in "no longer physical; " + @p advice. */
  void
  expect(const std::string &name,
         const std::string &message,
         const std::string &advice)
  {
    const std::string tail = "the results are no longer physical; " + advice;
    const bool        right =
      message.size() >= tail.size() &&
      message.compare(message.size() - tail.size(), tail.size(), tail) == 0 &&
      message.find("F-bar hull collapse") == 0;
    out() << name << ":\n  " << message
          << "\n  (as expected: " << (right ? "yes" : "no") << ")" << std::endl;
    check(right, name + " names " + advice);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                both =
    " (this part) or Time integration/F-bar stabilization (every part "
    "without its own) to 0.03 or more";
  {
    model::Model model(MPI_COMM_WORLD);
    fixtures::make_bonded_block(model);
    expect("bonded_block, steel pinched",
           pinched_message(model, 2),
           "set Parts/steel/F-bar stabilization" + both);
    expect("bonded_block, rubber pinched",
           pinched_message(model, 1),
           "set Parts/rubber/F-bar stabilization" + both);
  }
  {
    model::Model model(MPI_COMM_WORLD);
    io::read_gmsh_mesh(model.triangulation,
                       fixtures::mesh_directory() + "bonded_block.msh",
                       "Mesh/Mesh file");
    model::Part rubber        = fixtures::rubber_part("rubber", 1);
    rubber.fbar_stabilization = 0.05;
    model.parts.push_back(std::move(rubber));
    model.parts.push_back(fixtures::steel_part("steel", 2));
    model.setup();
    expect("bonded_block, rubber with its own beta 0.05 pinched",
           pinched_message(model, 1),
           "raise Parts/rubber/F-bar stabilization above 0.05");
  }
  {
    model::Model model(MPI_COMM_WORLD);
    fixtures::make_rigid_drop(model,
                              Tensor<1, 3>(),
                              Tensor<1, 3>(),
                              Tensor<1, 3>(),
                              false);
    expect("rigid_drop, rubber (the one deformable part) pinched",
           pinched_message(model, 1),
           "set Time integration/F-bar stabilization to 0.03 or more");
  }
}
