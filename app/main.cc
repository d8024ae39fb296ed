// rubberdyn: the command-line front end. All physics lives in the core
// library; this file only dispatches on the command line.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/app/command_line.h>

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return rubberdyn::app::run_command_line(argc, argv);
}
