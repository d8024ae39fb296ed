#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/io/parameter_file.h>

#include <cctype>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace rubberdyn
{
  namespace io
  {
    namespace
    {
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
        std::string text =
          std::regex_replace(info.str(), std::regex("\\s+"), " ");
        text = std::regex_replace(text, std::regex("^ +| +$"), "");
        return text;
      }

      /**
       * The subsection path ("A/B/") in force at line @p line_number of
       * @p filename, found by replaying its 'subsection' and 'end' lines:
       * ParameterHandler's own path is private, and its messages name an
       * offending entry without the subsections it lives in.
       */
      std::string
      subsection_path_at(const std::string &filename,
                         const unsigned int line_number)
      {
        std::ifstream            file(filename);
        std::vector<std::string> path;
        std::string              line;
        for (unsigned int n = 1; n < line_number && std::getline(file, line);
             ++n)
          {
            line = line.substr(0, line.find('#'));
            line = std::regex_replace(line, std::regex("\\s+"), " ");
            line = std::regex_replace(line, std::regex("^ +| +$"), "");
            if (line.rfind("subsection ", 0) == 0)
              path.push_back(line.substr(11));
            else if (line == "end" && !path.empty())
              path.pop_back();
          }
        std::string result;
        for (const std::string &name : path)
          result += name + '/';
        return result;
      }

      /**
       * The message of a parse error of @p filename, with the full path of
       * the entry or subsection it is about where ParameterHandler gives
       * only its name ("Line <7> of file <f>: The entry value -5 for the
       * entry named Impactor mass does not match ...").
       */
      std::string
      parse_error_message(const std::string &filename, const std::string &text)
      {
        // The file name may hold regex metacharacters: match it literally.
        // (deal.II 9.4 omits the '>' after it in some messages.)
        std::smatch line_match;
        if (!std::regex_search(text,
                               line_match,
                               std::regex("^Line <([0-9]+)> of file <")))
          return text;
        std::string rest = line_match.suffix();
        if (rest.rfind(filename, 0) != 0)
          return text;
        rest.erase(0, filename.size());
        rest = std::regex_replace(rest, std::regex("^>?: "), "");
        const unsigned int line  = std::stoul(line_match[1]);
        const std::string  path  = subsection_path_at(filename, line);
        const std::string  where = "line " + std::to_string(line) + ", ";
        std::smatch        m;
        if (std::regex_search(rest,
                              m,
                              std::regex("^The entry value (.*) for the entry "
                                         "named (.*) does not match the given "
                                         "pattern: (.*)$")))
          return where + "entry '" + path + m[2].str() + "': the value '" +
                 m[1].str() + "' is not allowed; allowed: " + m[3].str();
        if (std::regex_search(rest,
                              m,
                              std::regex("^No entry with name <(.*)> was "
                                         "declared in the current subsection")))
          return where + "entry '" + path + m[1].str() +
                 "': no such entry is declared (misspelt, or in the wrong "
                 "subsection?)";
        if (std::regex_search(rest,
                              m,
                              std::regex("no such subsection to be entered: "
                                         "(.*)$")))
          return where + "subsection '" + path +
                 std::regex_replace(m[1].str(), std::regex("\\.$"), "") +
                 "': no such subsection is declared";
        return where + rest;
      }

      /** Undo ParameterHandler's mangling of names ("_20" for ' ', ...). */
      std::string
      demangle(const std::string &s)
      {
        std::string result;
        for (unsigned int i = 0; i < s.size(); ++i)
          if (s[i] == '_' && i + 2 < s.size())
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

      void
      print_comment(const std::string &text,
                    const std::string &indent,
                    std::ostream &     out)
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
                 std::ostream &                     out)
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
                        const std::string &       filename)
    {
      std::ifstream file(filename);
      if (!file)
        throw InputError(filename, "cannot open the parameter file");
      try
        {
          prm.parse_input(file, filename, "", false);
        }
      catch (const dealii::ExceptionBase &exception)
        {
          throw InputError(filename,
                           parse_error_message(filename,
                                               message_of(exception)));
        }
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



    std::map<std::string, std::vector<std::string>>
    read_listed_names(const std::string &filename)
    {
      std::map<std::string, std::vector<std::string>> result;
      std::ifstream file(filename);
      if (!file)
        return result;
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



    void
    print_documented_parameters(const dealii::ParameterHandler &prm,
                                std::ostream &                  out)
    {
      std::stringstream json;
      prm.print_parameters(json,
                           dealii::ParameterHandler::OutputStyle(
                             dealii::ParameterHandler::JSON |
                             dealii::ParameterHandler::KeepDeclarationOrder));
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      out << "# rubberdyn parameter file: every parameter with its "
             "documentation,\n"
             "# allowed values and default. Units: mm, ms, kg, kN, GPa "
             "(energy in J = kN mm).\n"
             "# Written by 'rubberdyn --print-parameters'.\n";
      print_tree(tree, 0, out);
    }
  } // namespace io
} // namespace rubberdyn
