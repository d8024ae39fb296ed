#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/io/parameter_file.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

// No std::regex here: libstdc++'s matcher recurses once per character, so
// a pattern like "(.*)" on a long value overflows the stack (a parameter
// file with a 100 000-character value crashed the program with SIGSEGV in
// std::__detail::_Executor). The messages are taken apart with find().

namespace rubberdyn
{
  namespace io
  {
    namespace
    {
      bool
      is_space(const char c)
      {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
               c == '\f';
      }

      /** @p text with each run of whitespace folded to one space, trimmed. */
      std::string
      fold_whitespace(const std::string &text)
      {
        std::string result;
        bool        pending_space = false;
        for (const char c : text)
          if (is_space(c))
            pending_space = !result.empty();
          else
            {
              if (pending_space)
                result += ' ';
              pending_space = false;
              result += c;
            }
        return result;
      }

      bool
      starts_with(const std::string &text, const std::string &prefix)
      {
        return text.compare(0, prefix.size(), prefix) == 0;
      }

      bool
      ends_with(const std::string &text, const std::string &suffix)
      {
        return text.size() >= suffix.size() &&
               text.compare(text.size() - suffix.size(),
                            suffix.size(),
                            suffix) == 0;
      }

      /**
       * A value or name from the input as it is quoted in a message: at
       * most 60 characters, so that a message stays one readable line.
       */
      std::string
      abridged(const std::string &text, const std::size_t max_shown = 60)
      {
        if (text.size() <= max_shown)
          return text;
        return text.substr(0, max_shown) + "... (" +
               std::to_string(text.size()) + " characters)";
      }

      /**
       * The "additional information" of a deal.II exception, without the
       * banner (file, line, function, condition), whitespace folded so it
       * reads as one sentence.
       */
      std::string
      message_of(const dealii::ExceptionBase &exception)
      {
        std::ostringstream info;
        exception.print_info(info);
        return fold_whitespace(info.str());
      }

      /**
       * What a line of a parameter file is, as ParameterHandler reads it:
       * comment removed, whitespace folded.
       */
      struct ParsedLine
      {
        enum class Kind
        {
          blank,
          set,
          subsection,
          end,
          other
        };
        Kind        kind = Kind::blank;
        std::string name; // entry or subsection name
        std::string text; // the folded line
      };

      ParsedLine
      parse_line(const std::string &raw)
      {
        ParsedLine line;
        line.text = fold_whitespace(raw.substr(0, raw.find('#')));
        if (line.text.empty())
          line.kind = ParsedLine::Kind::blank;
        else if (line.text == "end" || line.text == "END")
          line.kind = ParsedLine::Kind::end;
        else if (starts_with(line.text, "subsection ") ||
                 starts_with(line.text, "SUBSECTION "))
          {
            line.kind = ParsedLine::Kind::subsection;
            line.name = line.text.substr(11);
          }
        else if (starts_with(line.text, "set ") ||
                 starts_with(line.text, "SET "))
          {
            line.kind = ParsedLine::Kind::set;
            line.name =
              fold_whitespace(line.text.substr(4, line.text.find('=') - 4));
          }
        else
          line.kind = ParsedLine::Kind::other;
        return line;
      }

      /**
       * The lines of a parameter file with, for each, the subsection path
       * ("A/B/") in force there, found by replaying 'subsection' and 'end':
       * ParameterHandler's own path is private, and its messages name an
       * offending entry without the subsections it lives in.
       */
      class FileLines
      {
      public:
        explicit FileLines(const std::string &text)
        {
          std::istringstream       in(text);
          std::string              raw;
          std::vector<std::string> path;
          while (std::getline(in, raw))
            {
              const ParsedLine line = parse_line(raw);
              paths.push_back(joined(path));
              lines.push_back(line);
              if (line.kind == ParsedLine::Kind::subsection)
                path.push_back(line.name);
              else if (line.kind == ParsedLine::Kind::end && !path.empty())
                path.pop_back();
            }
          open_path = joined(path);
        }

        /** The line numbered @p n (from 1), blank if out of range. */
        ParsedLine
        line(const unsigned int n) const
        {
          return (n >= 1 && n <= lines.size()) ? lines[n - 1] : ParsedLine();
        }

        /** The subsection path ("A/B/") in force at line @p n. */
        std::string
        path_at(const unsigned int n) const
        {
          return (n >= 1 && n <= paths.size()) ? paths[n - 1] : "";
        }

        /**
         * The last line that sets the entry @p full_name ("A/B/Name"), 0 if
         * none does (the last one counts, as in ParameterHandler).
         */
        unsigned int
        line_setting(const std::string &full_name) const
        {
          unsigned int result = 0;
          for (unsigned int i = 0; i < lines.size(); ++i)
            if (lines[i].kind == ParsedLine::Kind::set &&
                paths[i] + lines[i].name == full_name)
              result = i + 1;
          return result;
        }

        /** The number of lines. */
        unsigned int
        size() const
        {
          return lines.size();
        }

        /** The subsections still open at the end of the file ("A/B/"). */
        std::string open_path;

      private:
        static std::string
        joined(const std::vector<std::string> &path)
        {
          std::string result;
          for (const std::string &name : path)
            result += name + '/';
          return result;
        }

        std::vector<ParsedLine>  lines;
        std::vector<std::string> paths;
      };

      /**
       * The longest logical line (lines continued with a trailing
       * backslash count as one, as ParameterHandler joins them) that a
       * parameter file may hold. The longest real value, a hardening table
       * of a few hundred points, is far shorter.
       */
      constexpr std::size_t max_line_length = 10000;

      /** The largest parameter file read (bytes). */
      constexpr std::size_t max_file_size = 1 << 20;

      /**
       * Refuse a line longer than max_line_length before ParameterHandler
       * and the message formatting see it, naming the entry it sets.
       */
      void
      check_line_lengths(const std::string &filename,
                         const std::string &text,
                         const FileLines   &file)
      {
        std::istringstream in(text);
        std::string        raw;
        std::size_t        logical_length = 0;
        unsigned int       first_line     = 1;
        for (unsigned int n = 1; std::getline(in, raw); ++n)
          {
            if (logical_length == 0)
              first_line = n;
            logical_length += raw.size();
            if (logical_length > max_line_length)
              {
                const ParsedLine  line = file.line(first_line);
                const std::string where =
                  "line " + std::to_string(first_line) + ", ";
                std::string what;
                if (line.kind == ParsedLine::Kind::set)
                  what = "entry '" + file.path_at(first_line) +
                         abridged(line.name) + "'";
                else if (line.kind == ParsedLine::Kind::subsection)
                  what = "subsection '" + file.path_at(first_line) +
                         abridged(line.name) + "'";
                else
                  what = "in subsection '" + file.path_at(first_line) + "'";
                throw InputError(filename,
                                 where + what + ": the line is longer than " +
                                   std::to_string(max_line_length) +
                                   " characters; no parameter needs that "
                                   "much");
              }
            if (!raw.empty() && raw.back() == '\\')
              continue;
            logical_length = 0;
          }
      }

      /** The deepest chain of includes read: the file given is depth 0. */
      constexpr unsigned int max_include_depth = 8;

      /**
       * The text ParameterHandler reads: the file given with every
       * `include` line replaced by the lines of the file it names, and, for
       * each line of that text, the file it came from and its line there, so
       * that a message names the file and line the user wrote.
       *
       * deal.II's own `include` is never reached (no include line is left):
       * ParameterHandler would open the named file itself, relative to the
       * working directory, and parse it unchecked — no limit on its size or
       * its lines (`include /dev/zero` reads until memory runs out), a file
       * that includes itself recursing until the stack overflows, messages
       * naming neither file nor line. Here a path is relative to the file
       * that includes it, the chain is at most max_include_depth deep, a
       * cycle is refused with the chain named, and every included file is
       * under the same limits on size and line length as the file given
       * (and all of them together under max_file_size).
       */
      class ExpandedText
      {
      public:
        /** Read @p filename and everything it includes. */
        explicit ExpandedText(const std::string &filename)
          : top(filename)
        {
          std::vector<Frame> chain;
          add_file(filename, std::filesystem::path(filename), chain);
        }

        /** The whole text. */
        std::string text;

        /**
         * The file line @p n (from 1) of the text came from: the file given,
         * or "<file given>, line 2 -> base.prm" for an included one (the
         * chain of includes that reached it).
         */
        std::string
        file_of(const unsigned int n) const
        {
          return (n >= 1 && n <= origins.size()) ? files[origins[n - 1].file] :
                                                   top;
        }

        /**
         * The path of the file line @p n (from 1) of the text came from
         * (relative to the working directory, as the include lines that
         * reached it compose it).
         */
        std::filesystem::path
        path_of(const unsigned int n) const
        {
          return (n >= 1 && n <= origins.size()) ? paths[origins[n - 1].file] :
                                                   std::filesystem::path(top);
        }

        /** The line number in its own file of line @p n of the text. */
        unsigned int
        line_in_file(const unsigned int n) const
        {
          return (n >= 1 && n <= origins.size()) ? origins[n - 1].line : n;
        }

      private:
        /** One file of the chain being read. */
        struct Frame
        {
          /** How messages name it (the chain that reached it). */
          std::string shown;
          /** Its canonical path, to find a cycle. */
          std::filesystem::path canonical;
        };

        struct Origin
        {
          unsigned int file;
          unsigned int line;
        };

        std::string                        top;
        std::vector<std::string>           files;
        std::vector<std::filesystem::path> paths;
        std::vector<Origin>                origins;

        /**
         * Read @p path (named @p shown in messages) at the end of @p chain,
         * after the checks that make it safe to read.
         */
        std::string
        read_checked(const std::string                 &shown,
                     const std::filesystem::path       &path,
                     const std::vector<Frame>          &chain,
                     std::filesystem::path             &canonical)
        {
          std::error_code error;
          if (std::filesystem::is_directory(path, error))
            throw InputError(shown,
                             chain.empty() ?
                               "is a directory, not a parameter file" :
                               "the included path is a directory, not a "
                               "parameter file");
          std::ifstream in(path, std::ios::binary);
          if (!in)
            throw InputError(shown,
                             chain.empty() ?
                               "cannot open the parameter file" :
                               "cannot open the included file (a path in "
                               "an include line is relative to the file "
                               "that has the line)");
          canonical = std::filesystem::weakly_canonical(path, error);
          if (error)
            canonical = path;
          for (const Frame &frame : chain)
            if (frame.canonical == canonical)
              throw InputError(shown,
                               "the file includes itself through this chain "
                               "(a cycle): remove one of the include lines");
          // Read at most one byte more than allowed: a device such as
          // /dev/zero never ends.
          std::string text(max_file_size + 1, '\0');
          in.read(text.data(), static_cast<std::streamsize>(text.size()));
          text.resize(static_cast<std::size_t>(in.gcount()));
          if (text.size() > max_file_size)
            throw InputError(shown,
                             std::string(chain.empty() ? "the file" :
                                                         "the included file") +
                               " is larger than " +
                               std::to_string(max_file_size) +
                               " bytes; is it a parameter file?");
          if (this->text.size() + text.size() > max_file_size)
            throw InputError(shown,
                             "with this file the included files hold more "
                             "than " +
                               std::to_string(max_file_size) +
                               " bytes in all; is it a parameter file?");
          return text;
        }

        /** Append @p path and what it includes to the text. */
        void
        add_file(const std::string           &shown,
                 const std::filesystem::path &path,
                 std::vector<Frame>          &chain)
        {
          std::filesystem::path canonical;
          const std::string file_text =
            read_checked(shown, path, chain, canonical);
          const FileLines file(file_text);
          check_line_lengths(shown, file_text, file);
          if (!chain.empty())
            check_balanced(shown, file);

          chain.push_back({shown, canonical});
          files.push_back(shown);
          paths.push_back(path);
          const unsigned int file_index = files.size() - 1;

          // The logical lines, rebuilt as ParameterHandler::parse_input()
          // does (each physical line trimmed, a trailing backslash joins the
          // next one; the comment and tabs go before the keyword is looked
          // for), so that no spelling of the directive slips through.
          std::istringstream       in(file_text);
          std::string              raw, logical;
          std::vector<std::string> physical;
          unsigned int             first_line = 1;
          for (unsigned int n = 1; std::getline(in, raw); ++n)
            {
              if (physical.empty())
                first_line = n;
              physical.push_back(raw);
              std::string trimmed   = fold_whitespace(raw);
              const bool  continued = !trimmed.empty() && trimmed.back() == '\\';
              if (continued)
                trimmed.pop_back();
              logical += trimmed;
              if (continued)
                continue;
              const std::string statement =
                fold_whitespace(logical.substr(0, logical.find('#')));
              logical.clear();
              if (starts_with(statement, "include ") ||
                  starts_with(statement, "INCLUDE "))
                {
                  const std::string included = statement.substr(8);
                  const std::string at =
                    shown + ", line " + std::to_string(first_line);
                  if (chain.size() > max_include_depth)
                    throw InputError(at + " -> " + included,
                                     "includes are nested more than " +
                                       std::to_string(max_include_depth) +
                                       " deep");
                  // Relative to the file that has the include line.
                  std::filesystem::path target(included);
                  if (target.is_relative())
                    target = path.parent_path() / target;
                  add_file(at + " -> " + included, target, chain);
                }
              else
                for (unsigned int k = 0; k < physical.size(); ++k)
                  {
                    text += physical[k];
                    text += '\n';
                    origins.push_back({file_index, first_line + k});
                  }
              physical.clear();
            }
          chain.pop_back();
        }

        /**
         * An included file must close every subsection it opens and no
         * other: its entries land in the subsection of its include line,
         * as with ParameterHandler's own `include`.
         */
        static void
        check_balanced(const std::string &shown, const FileLines &file)
        {
          if (!file.open_path.empty())
            throw InputError(shown,
                             "subsection '" +
                               file.open_path.substr(0,
                                                     file.open_path.size() -
                                                       1) +
                               "' is not closed in this included file: an "
                               "included file closes what it opens");
          int depth = 0;
          for (unsigned int n = 1; n <= file.size(); ++n)
            {
              const ParsedLine line = file.line(n);
              if (line.kind == ParsedLine::Kind::subsection)
                ++depth;
              else if (line.kind == ParsedLine::Kind::end && --depth < 0)
                throw InputError(shown,
                                 "line " + std::to_string(n) +
                                   ": this 'end' closes a subsection the "
                                   "included file did not open");
            }
        }
      };



      /** The part of @p text between @p begin and @p end. */
      std::string
      between(const std::string &text,
              const std::size_t  begin,
              const std::size_t  end)
      {
        return text.substr(begin, end - begin);
      }

      /**
       * The message of a parse error of @p filename, with the full path of
       * the entry or subsection it is about where ParameterHandler gives
       * only its name ("Line <7> of file <f>: The entry value -5 for the
       * entry named Impactor mass does not match ...").
       */
      std::string
      parse_error_message(const std::string  &filename,
                          const FileLines    &file,
                          const ExpandedText &expanded,
                          const std::string  &text,
                          const std::set<std::string> &listed_paths,
                          std::string        &file_chain)
      {
        if (starts_with(text,
                        "There are unequal numbers of 'subsection' "
                        "and 'end' statements"))
          {
            std::string open = file.open_path;
            if (!open.empty())
              return "subsection '" + open.substr(0, open.size() - 1) +
                     "' is not closed: an 'end' is missing before the end "
                     "of the file";
            return "the numbers of 'subsection' and 'end' lines differ";
          }

        // "Line <N> of file <F>: ..." (deal.II 9.4 omits the '>' after
        // the file name in some messages).
        const std::string line_prefix = "Line <";
        if (!starts_with(text, line_prefix))
          return text;
        const std::size_t digits_end  = text.find('>', line_prefix.size());
        const std::string file_prefix = "> of file <" + filename;
        if (digits_end == std::string::npos ||
            text.compare(digits_end, file_prefix.size(), file_prefix) != 0)
          return text;
        const std::string number =
          between(text, line_prefix.size(), digits_end);
        if (number.empty() ||
            number.find_first_not_of("0123456789") != std::string::npos ||
            number.size() > 9)
          return text;
        const unsigned int line = std::stoul(number);
        std::string        rest = text.substr(digits_end + file_prefix.size());
        if (starts_with(rest, ">"))
          rest.erase(0, 1);
        if (starts_with(rest, ": "))
          rest.erase(0, 2);

        const std::string path  = file.path_at(line);
        // The line as the user wrote it: in the file given, or in the
        // included file (@p file_chain) it came from.
        file_chain              = expanded.file_of(line);
        const std::string where =
          "line " + std::to_string(expanded.line_in_file(line)) + ", ";

        // The value may hold anything, so the fixed phrases around it are
        // found from the right. An empty value leaves one space between
        // "value" and "for" once whitespace is folded.
        const std::string value_prefix   = "The entry value ";
        const std::string name_separator = " for the entry named ";
        const std::string pattern_separator =
          " does not match the given pattern: ";
        if (starts_with(rest, value_prefix))
          {
            const std::size_t p2 = rest.rfind(pattern_separator);
            const std::size_t p1 =
              (p2 == std::string::npos ? p2 : rest.rfind(name_separator, p2));
            if (p1 != std::string::npos && p1 + 1 >= value_prefix.size())
              return where + "entry '" + path +
                     between(rest, p1 + name_separator.size(), p2) +
                     "': the value '" +
                     (p1 < value_prefix.size() ?
                        std::string() :
                        abridged(between(rest, value_prefix.size(), p1))) +
                     "' is not allowed; allowed: " +
                     rest.substr(p2 + pattern_separator.size());
          }

        const std::string undeclared_prefix = "No entry with name <";
        const std::string undeclared_suffix =
          "> was declared in the current subsection";
        const std::size_t undeclared_end = rest.find(undeclared_suffix);
        if (starts_with(rest, undeclared_prefix) &&
            undeclared_end != std::string::npos)
          return where + "entry '" + path +
                 abridged(
                   between(rest, undeclared_prefix.size(), undeclared_end)) +
                 "': no such entry is declared (misspelt, or in the wrong "
                 "subsection?)";

        const std::string no_subsection = "no such subsection to be entered: ";
        const std::size_t no_subsection_at = rest.find(no_subsection);
        if (no_subsection_at != std::string::npos)
          {
            std::string name =
              rest.substr(no_subsection_at + no_subsection.size());
            if (ends_with(name, "."))
              name.pop_back();
            // deal.II names the subsection by its full path with '.'
            // between the levels ("Parts.rubbr"); keep the last level only,
            // as path (with '/') names the others.
            std::string dotted = path;
            std::replace(dotted.begin(), dotted.end(), '/', '.');
            if (!dotted.empty() && starts_with(name, dotted))
              name.erase(0, dotted.size());
            // Under a subsection whose members are named in its `Names`
            // entry (Parts, Boundary conditions, ...), a member not named
            // there is what the user most likely wrote.
            if (!path.empty() && listed_paths.count(path) > 0)
              return where + "subsection '" + path + abridged(name) +
                     "': no such subsection is declared: a subsection of '" +
                     path.substr(0, path.size() - 1) +
                     "' must be listed in its entry '" + path +
                     "Names' (add '" + abridged(name) + "' there)";
            return where + "subsection '" + path + abridged(name) +
                   "': no such subsection is declared";
          }

        // Any other complaint about a line (no '=' after 'set', an 'end'
        // too many, a line that is no statement): name what the line
        // tries to be, or else the subsection it is in.
        const ParsedLine parsed = file.line(line);
        if (rest.find("no subsection to leave") != std::string::npos)
          rest = "this 'end' closes no subsection";
        else if (rest.find("Invalid format of 'set'") != std::string::npos)
          rest = "a 'set' line needs the form 'set NAME = VALUE'";
        else if (rest.find("could not be parsed") != std::string::npos)
          rest = "cannot read '" + abridged(parsed.text) +
                 "': expected 'set NAME = VALUE', 'subsection NAME' or 'end'";
        if (parsed.kind == ParsedLine::Kind::set)
          return where + "entry '" + path + abridged(parsed.name) +
                 "': " + abridged(rest, 200);
        if (parsed.kind == ParsedLine::Kind::subsection)
          return where + "subsection '" + path + abridged(parsed.name) +
                 "': " + abridged(rest, 200);
        return where +
               (path.empty() ?
                  std::string("at the top level") :
                  "in subsection '" + path.substr(0, path.size() - 1) + "'") +
               ": " + abridged(rest, 200);
      }

      /** Undo ParameterHandler's mangling of names ("_20" for ' ', ...). */
      std::string
      demangle(const std::string &s)
      {
        std::string result;
        // Only '_' followed by two hex digits is a mangled character: a
        // subsection named by the user (e.g. "bottom_plate") reaches here
        // as it was written.
        for (unsigned int i = 0; i < s.size(); ++i)
          if (s[i] == '_' && i + 2 < s.size() &&
              std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
              std::isxdigit(static_cast<unsigned char>(s[i + 2])))
            {
              result += static_cast<char>(std::stoi(s.substr(i + 1, 2),
                                                    nullptr,
                                                    16));
              i += 2;
            }
          else
            result += s[i];
        return result;
      }

      /** The declared parameters of @p prm as a property tree. */
      boost::property_tree::ptree
      parameter_tree(const dealii::ParameterHandler &prm)
      {
        std::stringstream json;
        prm.print_parameters(json,
                             dealii::ParameterHandler::OutputStyle(
                               dealii::ParameterHandler::JSON |
                               dealii::ParameterHandler::KeepDeclarationOrder));
        boost::property_tree::ptree tree;
        boost::property_tree::read_json(json, tree);
        return tree;
      }

      /**
       * The subsection paths ("Parts/") of @p tree that declare a `Names`
       * entry: their subsections are the names listed there.
       */
      std::set<std::string>
      paths_with_names_entry(const boost::property_tree::ptree &tree,
                             const std::string                 &path)
      {
        std::set<std::string> result;
        for (const auto &child : tree)
          if (!child.second.get_optional<std::string>("value"))
            {
              const std::set<std::string> below =
                paths_with_names_entry(child.second,
                                       path + demangle(child.first) + '/');
              result.insert(below.begin(), below.end());
            }
          else if (demangle(child.first) == "Names")
            result.insert(path);
        return result;
      }



      /**
       * Refuse a value of a floating-point entry that the pattern lets
       * through but no computation can use: NaN and infinity (which
       * deal.II's Patterns::Double accepts when written as "nan" or
       * "inf"), and numbers that do not fit a double as a normal number
       * (1e-320 is a denormal, 1e-400 underflows to 0). @p path is the
       * subsection path of @p tree ("A/B/").
       */
      void
      check_floating_point_values(const ExpandedText                &expanded,
                                  const FileLines                   &file,
                                  const boost::property_tree::ptree &tree,
                                  const std::string                 &path)
      {
        for (const auto &child : tree)
          {
            const auto value = child.second.get_optional<std::string>("value");
            if (!value)
              {
                check_floating_point_values(expanded,
                                            file,
                                            child.second,
                                            path + demangle(child.first) + '/');
                continue;
              }
            // A number, or a list of numbers (a point, a vector).
            const std::string pattern =
              child.second.get<std::string>("pattern_description", "");
            std::vector<std::string> numbers;
            if (starts_with(pattern, "[Double"))
              numbers.push_back(*value);
            else if (starts_with(pattern, "[List of <[Double"))
              numbers = dealii::Utilities::split_string_list(*value, ',');
            double x           = 0.;
            bool   range_error = false;
            for (const std::string &number : numbers)
              {
                errno       = 0;
                char *end   = nullptr;
                x           = std::strtod(number.c_str(), &end);
                range_error = (errno == ERANGE);
                if (!parameter_tools::is_usable_number(x) || range_error)
                  break;
              }
            if (parameter_tools::is_usable_number(x) && !range_error)
              continue;
            const std::string  name = path + demangle(child.first);
            const unsigned int line = file.line_setting(name);
            throw InputError(
              expanded.file_of(line),
              (line > 0 ? "line " + std::to_string(expanded.line_in_file(line)) +
                            ", " :
                          std::string()) +
                "entry '" + name + "': the value '" + abridged(*value) +
                "' is not allowed: " +
                (std::isnan(x) ?
                   "not a number" :
                 std::isinf(x) ?
                   "infinite" :
                 x == 0. ?
                   "too small for a double (it underflows to 0)" :
                 std::abs(x) > 1. ?
                   "too large for a double" :
                   "too small for a double: a denormal number (below "
                   "2.2e-308 in magnitude), which loses precision; write 0 "
                   "or a larger value"));
          }
      }

      void
      print_comment(const std::string &text,
                    const std::string &indent,
                    std::ostream      &out)
      {
        // Each line of the text on its own, wrapped at about 78 columns.
        std::istringstream lines(text);
        std::string        paragraph;
        while (std::getline(lines, paragraph))
          {
            std::istringstream words(paragraph);
            std::string        word, line;
            while (words >> word)
              {
                if (!line.empty() &&
                    indent.size() + 2 + line.size() + 1 + word.size() > 78)
                  {
                    out << indent << "# " << line << '\n';
                    line = "  ";
                  }
                line += (line.empty() || line == "  " ? "" : " ") + word;
              }
            if (!line.empty())
              out << indent << "# " << line << '\n';
          }
      }

      void
      print_tree(const boost::property_tree::ptree &tree,
                 const unsigned int                 depth,
                 std::ostream                      &out)
      {
        const std::string indent(2 * depth, ' ');
        // Entries first, then subsections, each in declaration order.
        for (const auto &child : tree)
          if (child.second.get_optional<std::string>("value"))
            {
              const auto &entry = child.second;
              out << '\n';
              print_comment(entry.get<std::string>("documentation", ""),
                            indent,
                            out);
              print_comment("Allowed: " + entry.get<std::string>(
                                            "pattern_description", ""),
                            indent,
                            out);
              out << indent << "set " << demangle(child.first) << " = "
                  << entry.get<std::string>("default_value") << '\n';
            }
        for (const auto &child : tree)
          if (!child.second.get_optional<std::string>("value"))
            {
              out << '\n'
                  << indent << "subsection " << demangle(child.first) << '\n';
              print_tree(child.second, depth + 1, out);
              out << indent << "end\n";
            }
      }
    } // namespace



    void
    read_parameter_file(dealii::ParameterHandler &prm,
                        const std::string        &filename)
    {
      const ExpandedText expanded(filename);
      const FileLines    file(expanded.text);

      std::istringstream stream(expanded.text);
      try
        {
          prm.parse_input(stream, filename, "", false);
        }
      catch (const dealii::ExceptionBase &exception)
        {
          std::string       where = filename;
          const std::string message =
            parse_error_message(filename,
                                file,
                                expanded,
                                message_of(exception),
                                paths_with_names_entry(parameter_tree(prm), ""),
                                where);
          throw InputError(where, message);
        }
      check_floating_point_values(expanded, file, parameter_tree(prm), "");
    }



    namespace
    {
      std::string
      trim(const std::string &text)
      {
        const auto first = text.find_first_not_of(" \t\r");
        if (first == std::string::npos)
          return "";
        const auto last = text.find_last_not_of(" \t\r");
        return text.substr(first, last - first + 1);
      }
    } // namespace



    std::string
    file_setting_entry(const std::string &filename,
                       const std::string &entry_path)
    {
      const ExpandedText expanded(filename);
      const FileLines    file(expanded.text);
      const unsigned int line = file.line_setting(entry_path);
      return line == 0 ? filename : expanded.path_of(line).string();
    }



    std::map<std::string, std::vector<std::string>>
    read_listed_names(const std::string &filename)
    {
      std::map<std::string, std::vector<std::string>> result;
      // The file with what it includes. A file that cannot be read (or an
      // include that cannot) gives no names: read_parameter_file() then
      // reports it, naming the file and the chain.
      std::string text;
      try
        {
          text = ExpandedText(filename).text;
        }
      catch (const InputError &)
        {
          return result;
        }
      std::istringstream       file(text);
      std::vector<std::string> path;
      std::string              line, logical;
      while (std::getline(file, line))
        {
          // Continuation lines end in a backslash.
          if (!line.empty() && line.back() == '\\')
            {
              logical += line.substr(0, line.size() - 1);
              continue;
            }
          logical += line;
          std::string text = trim(logical.substr(0, logical.find('#')));
          logical.clear();
          if (text.rfind("subsection ", 0) == 0)
            path.push_back(trim(text.substr(11)));
          else if (text == "end")
            {
              if (!path.empty())
                path.pop_back();
            }
          else if (text.rfind("set ", 0) == 0)
            {
              const auto equals = text.find('=');
              if (equals == std::string::npos ||
                  trim(text.substr(4, equals - 4)) != "Names")
                continue;
              std::string where;
              for (const std::string &name : path)
                where += (where.empty() ? "" : "/") + name;
              std::vector<std::string> names;
              std::istringstream       list(text.substr(equals + 1));
              std::string              name;
              while (std::getline(list, name, ','))
                {
                  name = trim(name);
                  if (name.empty())
                    continue;
                  for (const char c : name)
                    if (!(std::isalnum(static_cast<unsigned char>(c)) ||
                          c == '_' || c == '-'))
                      throw InputError(where + "/Names",
                                       "the name '" + name.substr(0, 40) +
                                         "' may hold only letters, digits, "
                                         "'_' and '-' (it names output "
                                         "columns)");
                  for (const std::string &other : names)
                    if (other == name)
                      throw InputError(where + "/Names",
                                       "the name '" + name +
                                         "' is used twice");
                  names.push_back(name);
                }
              result[where] = names;
            }
        }
      return result;
    }



    namespace
    {
      void
      collect_changed_entries(const boost::property_tree::ptree &tree,
                              const std::string                 &path,
                              std::vector<std::string>          &changed)
      {
        for (const auto &child : tree)
          {
            const auto value = child.second.get_optional<std::string>("value");
            if (!value)
              collect_changed_entries(child.second,
                                      path + demangle(child.first) + '/',
                                      changed);
            else if (*value != child.second.get<std::string>("default_value",
                                                             *value))
              changed.push_back(path + demangle(child.first));
          }
      }
    } // namespace



    std::vector<std::string>
    entries_changed_from_default(const dealii::ParameterHandler &prm)
    {
      std::vector<std::string> changed;
      collect_changed_entries(parameter_tree(prm), "", changed);
      return changed;
    }



    std::vector<std::string>
    subsection_names(const dealii::ParameterHandler &prm)
    {
      std::vector<std::string> names;
      for (const auto &child : parameter_tree(prm))
        if (!child.second.get_optional<std::string>("value"))
          names.push_back(demangle(child.first));
      return names;
    }



    void
    print_documented_parameters(const dealii::ParameterHandler &prm,
                                std::ostream                   &out)
    {
      out << "# rubberdyn parameter file: every parameter with its "
             "documentation,\n"
             "# allowed values and default. Units: mm, ms, kg, kN, GPa "
             "(energy in J = kN mm).\n"
             "# Written by 'rubberdyn --print-parameters'.\n";
      print_tree(parameter_tree(prm), 0, out);
    }
  } // namespace io
} // namespace rubberdyn
