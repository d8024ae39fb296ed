#ifndef rubberdyn_tests_io_mesh_tests_h
#define rubberdyn_tests_io_mesh_tests_h
// What the mesh-reading tests of this directory share.

#include <iomanip>
#include <sstream>
#include <string>

namespace testing
{
  /** The folder of the example meshes, parameter_files/meshes/. */
  inline const std::string mesh_directory =
    std::string(SOURCE_DIR) + "/../../parameter_files/meshes/";

  /** @p value with 6 significant digits (volumes and areas in the output). */
  inline std::string
  g6(const double value)
  {
    std::ostringstream s;
    s << std::setprecision(6) << value;
    return s.str();
  }
} // namespace testing

#endif
