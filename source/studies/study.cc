#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/registry.h>
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
        /** What a study registers: how to declare and create it. */
        struct Entry
        {
          DeclareFunction declare;
          CreateFunction  create;
        };

        Registry<Entry> &
        studies()
        {
          return Registry<Entry>::instance();
        }
      } // namespace


      int
      register_study(const std::string &    name,
                     const std::string &    description,
                     const DeclareFunction &declare,
                     const CreateFunction & create)
      {
        return studies().add(name, description, Entry{declare, create});
      }



      std::vector<std::string>
      names()
      {
        return studies().names();
      }



      void
      declare_parameters(dealii::ParameterHandler &prm, const ListedNames &names)
      {
        prm.declare_entry("Study",
                          "Drop test",
                          dealii::Patterns::Selection(studies().pattern()),
                          studies().documentation("The study to run. One of:"));

        parameters::TimeIntegration::declare_parameters(prm);
        parameters::Contact::declare_parameters(prm);
        parameters::Output::declare_parameters(prm);

        studies().for_each([&](const std::string &, const Entry &entry) {
          entry.declare(prm, names);
        });
      }



      std::unique_ptr<Study>
      create(dealii::ParameterHandler &prm, const std::string &parameter_file)
      {
        const std::string name = prm.get("Study");
        const Entry      *entry = studies().find(name);
        if (entry == nullptr)
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
        return entry->create(prm, parameter_file);
      }
    } // namespace registry
  }   // namespace studies
} // namespace rubberdyn
