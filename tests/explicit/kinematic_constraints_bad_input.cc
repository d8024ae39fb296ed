// Bad input to the kinematic constraints of the explicit solver throws an
// InputError that names the offending group (the user's name for it) and
// says what is wrong, on every rank:
//  - a symmetry plane on a boundary whose faces are not in one plane
//    normal to the given axis (the side x = 0 of a bar along z, declared
//    normal to z: its faces span the bar's length along z);
//  - a symmetry plane or a prescribed velocity on a boundary id that no
//    face of the mesh has;
// while the valid declarations of the same mesh are accepted.
#include <deal.II/base/mpi.h>

#include <rubberdyn/base/exceptions.h>

#include "../tests.h"
#include "bar.h"

using namespace dealii;
namespace ti = rubberdyn::time_integration;

namespace
{
  /**
   * Run @p declare, print the InputError it throws (or that it threw
   * none) and return whether it threw one whose entry is @p name and whose
   * message contains @p expected.
   */
  template <typename Declaration>
  bool
  throws_input_error(const Declaration &declare,
                     const std::string &name,
                     const std::string &expected,
                     const bool         root)
  {
    try
      {
        declare();
      }
    catch (const rubberdyn::InputError &error)
      {
        if (root)
          testing::out() << "InputError: " << error.what() << std::endl;
        return error.entry_path == name &&
               std::string(error.what()).find(name + ": ") == 0 &&
               error.message.find(expected) != std::string::npos;
      }
    if (root)
      testing::out() << "no exception for '" << name << "'" << std::endl;
    return false;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root = (Utilities::MPI::this_mpi_process(comm) == 0);

  // 6 x 6 x 30 mm, boundary ids 0 ... 5 (bar::boundary).
  const bar::Bar           model(6., 2, 30., 10, comm);
  ti::KinematicConstraints constraints(model.dof_handler, model.partitioner);

  testing::check(
    throws_input_error(
      [&]() {
        constraints.symmetry_plane("Side symmetry", bar::boundary::x_min, 2);
      },
      "Side symmetry",
      "the faces of boundary 0 are not in one plane normal to axis 2 (they "
      "span 30 mm along it)",
      root),
    "symmetry plane normal to z on the side x = 0");
  testing::check(throws_input_error(
                   [&]() {
                     constraints.prescribe_velocity("Press stroke",
                                                    7,
                                                    2,
                                                    [](const double) {
                                                      return 1.;
                                                    });
                   },
                   "Press stroke",
                   "no boundary face has the boundary id 7",
                   root),
                 "prescribed velocity on a boundary id that does not exist");
  testing::check(
    throws_input_error([&]() { constraints.symmetry_plane("Mirror", 9, 0); },
                       "Mirror",
                       "no boundary face has the boundary id 9",
                       root),
    "symmetry plane on a boundary id that does not exist");
  testing::check(constraints.n_groups() == 0 && constraints.entries().empty(),
                 "rejected declarations add no group");

  // The same mesh's valid declarations.
  constraints.symmetry_plane("Side symmetry", bar::boundary::x_min, 0);
  constraints.prescribe_velocity("Press stroke",
                                 bar::boundary::z_max,
                                 2,
                                 [](const double) { return 1.; });
  if (root)
    {
      testing::out() << "accepted:";
      for (const std::string &name : constraints.group_names())
        testing::out() << " '" << name << "'";
      testing::out() << std::endl;
    }
  testing::check(constraints.n_groups() == 2, "valid declarations accepted");
}
