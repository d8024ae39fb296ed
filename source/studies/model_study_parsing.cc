#include "model_study_parsing.h"

#include <deal.II/base/function_parser.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>

#include <cctype>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

// What the Model study's section parsers share: vectors, directions and
// functions of x, y, z, t as written in an entry, and the mesh's ids.

namespace rubberdyn
{
  namespace studies
  {
    namespace model_study_parsing
    {
      Tensor<1, 3>
      parse_vector(const std::string &text)
      {
        // vector_pattern() has accepted three numbers, and the parameter
        // reader has refused NaN, infinity and denormals among them.
        const std::vector<std::string> items =
          Utilities::split_string_list(text, ',');
        AssertDimension(items.size(), 3);
        Tensor<1, 3> result;
        for (unsigned int d = 0; d < 3; ++d)
          result[d] = Utilities::string_to_double(items[d]);
        return result;
      }



      std::vector<unsigned int>
      parse_components(const std::string &text, const std::string &path)
      {
        std::vector<unsigned int> components;
        for (const std::string &item : Utilities::split_string_list(text, ','))
          {
            // (MultipleSelection("x|y|z") has accepted each item.)
            const unsigned int d = item[0] - 'x';
            for (const unsigned int c : components)
              if (c == d)
                throw InputError(path, "lists " + item + " twice");
            components.push_back(d);
          }
        if (components.empty())
          throw InputError(path, "lists no direction");
        return components;
      }

      /** Whether @p expression uses one of the variables x, y, z. */
      bool
      uses_position(const std::string &expression)
      {
        for (std::size_t i = 0; i < expression.size();)
          if (std::isalpha(static_cast<unsigned char>(expression[i])) ||
              expression[i] == '_')
            {
              std::size_t j = i;
              while (j < expression.size() &&
                     (std::isalnum(static_cast<unsigned char>(expression[j])) ||
                      expression[j] == '_'))
                ++j;
              const std::string word = expression.substr(i, j - i);
              if (word == "x" || word == "y" || word == "z")
                return true;
              i = j;
            }
          else
            ++i;
        return false;
      }

      /**
       * A deal.II FunctionParser of x, y, z, t with @p n_components
       * components separated by ';', from the entry @p path/@p entry.
       */
      std::shared_ptr<FunctionParser<3>>
      make_function(const std::string &expression,
                    const std::string &constants_text,
                    const unsigned int n_components,
                    const std::string &path,
                    const std::string &which,
                    const std::string &entry)
      {
        const std::vector<std::string> parts =
          Utilities::split_string_list(expression, ';');
        if (parts.size() != n_components)
          throw InputError(path + "/" + entry,
                           "has " + std::to_string(parts.size()) +
                             " components (separated by ';'), but " +
                             std::to_string(n_components) +
                             (n_components == 1 ? " is" : " are") +
                             " needed, " + which);
        std::map<std::string, double> constants;
        for (const std::string &item :
             Utilities::split_string_list(constants_text, ','))
          {
            const auto equals = item.find('=');
            if (equals == std::string::npos)
              throw InputError(path + "/Function constants",
                               "'" + item.substr(0, 40) +
                                 "' is not of the form name = value");
            try
              {
                constants[Utilities::trim(item.substr(0, equals))] =
                  Utilities::string_to_double(
                    Utilities::trim(item.substr(equals + 1)));
              }
            catch (...)
              {
                throw InputError(path + "/Function constants",
                                 "'" + item.substr(0, 40) +
                                   "' has no numeric value");
              }
          }
        // pi is always known (as in deal.II's own parsed functions).
        constants.emplace("pi", numbers::PI);
        auto function = std::make_shared<FunctionParser<3>>(n_components);
        // deal.II prints muparser's diagnosis to std::cerr before it
        // throws; the InputError below says it in one line instead.
        std::ostringstream    diagnosis;
        std::streambuf *const cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
        try
          {
            function->initialize("x,y,z,t", parts, constants, true);
            // Evaluate once: an undefined name shows only here.
            function->set_time(0.);
            for (unsigned int c = 0; c < n_components; ++c)
              function->value(Point<3>(), c);
            std::cerr.rdbuf(cerr_buffer);
          }
        catch (const ExceptionBase &error)
          {
            std::cerr.rdbuf(cerr_buffer);
            std::ostringstream message;
            error.print_info(message);
            std::string text = message.str();
            for (char &c : text)
              if (c == '\n')
                c = ' ';
            // One space between words.
            std::string folded;
            for (const char c : text)
              if (!(c == ' ' && (folded.empty() || folded.back() == ' ')))
                folded += c;
            throw InputError(path + "/" + entry,
                             "'" + expression.substr(0, 80) +
                               "' does not parse: " + folded.substr(0, 200));
          }
        catch (...)
          {
            std::cerr.rdbuf(cerr_buffer);
            throw InputError(path + "/" + entry,
                             "'" + expression.substr(0, 80) +
                               "' does not parse");
          }
        return function;
      }



      void
      MeshContents::require_boundary_ids(
        const std::set<types::boundary_id> &ids,
        const std::string                  &path) const
      {
        for (const types::boundary_id id : ids)
          if (boundary_ids.count(id) == 0)
            throw InputError(path,
                             "the mesh " + file +
                               " has no boundary face with id " +
                               std::to_string(id));
      }
    } // namespace model_study_parsing
  }   // namespace studies
} // namespace rubberdyn
