#ifndef rubberdyn_io_parameter_file_h
#define rubberdyn_io_parameter_file_h

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace rubberdyn
{
  /**
   * Reading and writing parameter files.
   */
  namespace io
  {
    /**
     * Read @p filename into @p prm (whose entries are all declared).
     *
     * @throws InputError naming the file, the line and the entry, in one
     *   readable sentence, if the file is missing or unreadable, an entry is
     *   unknown, or a value does not match its pattern (type or range).
     */
    void
    read_parameter_file(dealii::ParameterHandler &prm,
                        const std::string &       filename);

    /**
     * The names listed by every `set Names = a, b, ...` of @p filename, by
     * the subsection path that holds the entry (e.g. "Parts"): a study
     * declares one subsection per listed name before the file is parsed,
     * as ASPECT does. The file is scanned line by line as ParameterHandler
     * reads it (comments, `subsection`, `end`, continuation lines); an
     * unreadable file gives an empty map (the parser then reports it).
     *
     * @throws InputError naming the entry if a name is used twice or is not
     *   made of letters, digits, '_' and '-' (names become column names).
     */
    std::map<std::string, std::vector<std::string>>
    read_listed_names(const std::string &filename);

    /**
     * Write every declared parameter of @p prm as a valid .prm file: each
     * entry with its documentation, its allowed values (the pattern) and
     * its default, in declaration order.
     */
    void
    print_documented_parameters(const dealii::ParameterHandler &prm,
                                std::ostream &                  out);
  } // namespace io
} // namespace rubberdyn

#endif
