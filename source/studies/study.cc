#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/registry.h>
#include <rubberdyn/io/parameter_file.h>
#include <rubberdyn/parameters/contact_parameters.h>
#include <rubberdyn/parameters/output_parameters.h>
#include <rubberdyn/parameters/time_integration_parameters.h>
#include <rubberdyn/studies/study.h>

#include <algorithm>
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



        /**
         * The parameter groups every study shares (Time integration,
         * Contact, Output), declared by the registry, not by a study.
         */
        void
        declare_shared_groups(dealii::ParameterHandler &prm)
        {
          parameters::TimeIntegration::declare_parameters(prm);
          parameters::Contact::declare_parameters(prm);
          parameters::Output::declare_parameters(prm);
        }



        /**
         * Refuse an entry set in the file (a value other than its default)
         * in a top-level subsection that only studies other than @p chosen
         * declare: a Model file without `set Study = Model` ran as the
         * default drop test and ignored the whole model.
         *
         * @throws InputError naming the entry, its studies and the chosen one.
         */
        void
        refuse_entries_of_other_studies(const dealii::ParameterHandler &prm,
                                        const std::string              &chosen)
        {
          // Which studies declare each top-level subsection. The shared
          // groups belong to none, even where a study adds entries to one.
          dealii::ParameterHandler shared;
          declare_shared_groups(shared);
          const std::vector<std::string> shared_groups =
            io::subsection_names(shared);
          std::map<std::string, std::vector<std::string>> studies_of;
          studies().for_each([&](const std::string &study, const Entry &entry) {
            dealii::ParameterHandler scratch;
            entry.declare(scratch, {});
            for (const std::string &subsection : io::subsection_names(scratch))
              if (std::find(shared_groups.begin(),
                            shared_groups.end(),
                            subsection) == shared_groups.end())
                studies_of[subsection].push_back(study);
          });
          for (const std::string &path : io::entries_changed_from_default(prm))
            {
              const std::size_t slash = path.find('/');
              if (slash == std::string::npos)
                continue;
              const auto owners = studies_of.find(path.substr(0, slash));
              if (owners == studies_of.end() ||
                  std::find(owners->second.begin(),
                            owners->second.end(),
                            chosen) != owners->second.end())
                continue;
              std::string listed;
              for (const std::string &study : owners->second)
                listed += (listed.empty() ? "'" : "' or '") + study;
              throw InputError(
                path,
                "this entry belongs to the " + listed + "' study, but the "
                  "study is '" + chosen + "'" +
                  (chosen == "Drop test" ?
                     " (the default: is 'set Study = " + owners->second[0] +
                       "' missing?)" :
                     std::string()) +
                  "; set Study to the study the file describes, or remove the "
                  "entry");
            }
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

        declare_shared_groups(prm);

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
        refuse_entries_of_other_studies(prm, name);
        return entry->create(prm, parameter_file);
      }
    } // namespace registry
  }   // namespace studies
} // namespace rubberdyn
