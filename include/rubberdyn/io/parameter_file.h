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
     * `include FILE` lines are followed: the named file's lines take the
     * include line's place (in its subsection); a relative FILE is relative
     * to the file that has the line; at most 8 levels; a cycle is refused
     * with the chain named; every file under the same limits on size and
     * line length as the file given.
     *
     * @throws InputError naming the file, the line and the entry, in one
     *   readable sentence, if the file is missing or unreadable, an entry is
     *   unknown, or a value does not match its pattern (type or range); an
     *   error in an included file names the chain of files and lines that
     *   reached it ("a.prm, line 2 -> base.prm: line 7, entry ...").
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
     * The file that sets the entry @p entry_path ("Mesh/Mesh file") when
     * @p filename is read: @p filename itself or a file it includes (the
     * last line that sets the entry counts, as in ParameterHandler), as the
     * include lines compose its path; @p filename if no line sets it. A
     * path in the entry's value is relative to this file's folder, so that
     * a base file included from another folder finds its mesh. Call after
     * read_parameter_file() has accepted @p filename.
     */
    std::string
    file_setting_entry(const std::string &filename,
                       const std::string &entry_path);

    /**
     * The full paths ("A/B/Name") of the entries of @p prm whose value is
     * not their default, in declaration order.
     */
    std::vector<std::string>
    entries_changed_from_default(const dealii::ParameterHandler &prm);

    /** The names of the top-level subsections declared in @p prm. */
    std::vector<std::string>
    subsection_names(const dealii::ParameterHandler &prm);

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
