#ifndef rubberdyn_parameters_field_output_format_h
#define rubberdyn_parameters_field_output_format_h

#include <string>

namespace rubberdyn
{
  namespace parameters
  {
    /**
     * The file format of the ParaView series (`Output/Field output format`),
     * used by postprocess::FieldOutput.
     */
    enum class FieldOutputFormat
    {
      /** A `.pvtu` per output time and a `.pvd` index. */
      vtu,
      /** An `.h5` per output time and an `.xdmf` index. */
      hdf5
    };

    /**
     * The format names accepted by parse_field_output_format(), as a pattern
     * for a Patterns::Selection: "vtu|hdf5".
     */
    std::string
    field_output_format_names();

    /**
     * The format called @p name ("vtu" or "hdf5").
     *
     * @throws std::invalid_argument for any other name, listing the valid ones.
     */
    FieldOutputFormat
    parse_field_output_format(const std::string &name);
  } // namespace parameters
} // namespace rubberdyn

#endif
