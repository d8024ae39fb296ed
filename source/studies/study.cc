#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/parameters/contact_parameters.h>
#include <rubberdyn/parameters/output_parameters.h>
#include <rubberdyn/parameters/time_integration_parameters.h>
#include <rubberdyn/studies/study.h>

#include <ostream>

#include <map>
#include <sstream>

namespace rubberdyn
{
  namespace studies
  {
    void
    Study::check(std::ostream &)
    {}



    namespace registry
    {
      namespace
      {
        struct Entry
        {
          std::string     description;
          DeclareFunction declare;
          CreateFunction  create;
        };

        std::map<std::string, Entry> &
        entries()
        {
          static std::map<std::string, Entry> map;
          return map;
        }
      } // namespace


      int
      register_study(const std::string &    name,
                     const std::string &    description,
                     const DeclareFunction &declare,
                     const CreateFunction & create)
      {
        entries()[name] = Entry{description, declare, create};
        return 0;
      }



      std::vector<std::string>
      names()
      {
        std::vector<std::string> result;
        for (const auto &entry : entries())
          result.push_back(entry.first);
        return result;
      }



      void
      declare_parameters(dealii::ParameterHandler &prm, const ListedNames &names)
      {
        std::ostringstream doc;
        std::string        pattern;
        doc << "The study to run. One of:";
        for (const auto &entry : entries())
          {
            doc << "\n'" << entry.first << "': " << entry.second.description;
            pattern += (pattern.empty() ? "" : "|") + entry.first;
          }
        prm.declare_entry("Study",
                          "Drop test",
                          dealii::Patterns::Selection(pattern),
                          doc.str());

        parameters::TimeIntegration::declare_parameters(prm);
        parameters::Contact::declare_parameters(prm);
        parameters::Output::declare_parameters(prm);

        for (const auto &entry : entries())
          entry.second.declare(prm, names);
      }



      std::unique_ptr<Study>
      create(dealii::ParameterHandler &prm, const std::string &parameter_file)
      {
        const std::string name = prm.get("Study");
        const auto        it   = entries().find(name);
        if (it == entries().end())
          throw InputError("Study", "unknown study '" + name + "'");
        // Every study writes below it: an empty name would put the results
        // in the root directory ("" + "/file").
        prm.enter_subsection("Output");
        const bool no_directory = prm.get("Output directory").empty();
        prm.leave_subsection();
        if (no_directory)
          throw InputError("Output/Output directory",
                           "must not be empty (use '.' for the working "
                           "directory)");
        return it->second.create(prm, parameter_file);
      }
    } // namespace registry
  }   // namespace studies
} // namespace rubberdyn
