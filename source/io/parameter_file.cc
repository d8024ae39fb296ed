#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/io/parameter_file.h>

#include <fstream>
#include <regex>
#include <sstream>

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
          throw InputError(filename, message_of(exception));
        }
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
