#ifndef rubberdyn_source_studies_model_study_parsing_h
#define rubberdyn_source_studies_model_study_parsing_h

// Private to source/studies: what the Model study's parsers share (the
// listed names and their subsections, lists of ids) and the parsers of
// its groups that live in files of their own.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/studies/study.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace model
  {
    class Model;
  }
  namespace studies
  {
    namespace model_study_parsing
    {
      using namespace dealii;

      /** The name of the subsection that documents the per-name entries. */
      const std::string template_name = "<name>";

      /** The names listed under @p path, plus the documenting template. */
      inline std::vector<std::string>
      names_with_template(const registry::ListedNames &names,
                          const std::string           &path)
      {
        std::vector<std::string> result = {template_name};
        const auto               listed = names.find(path);
        if (listed != names.end())
          for (const std::string &name : listed->second)
            if (name != template_name)
              result.push_back(name);
        return result;
      }

      /** The names of `<path>/Names` as parsed. */
      inline std::vector<std::string>
      listed_names(ParameterHandler &prm)
      {
        return Utilities::split_string_list(prm.get("Names"), ',');
      }

      /** A list of ids (0-255 for boundary ids). */
      template <typename Id>
      std::set<Id>
      parse_ids(const std::string &text,
                const std::string &path,
                const unsigned int largest)
      {
        std::set<Id> ids;
        for (const std::string &item : Utilities::split_string_list(text, ','))
          {
            int value = -1;
            try
              {
                value = Utilities::string_to_int(item);
              }
            catch (...)
              {
                throw InputError(path,
                                 "'" + item.substr(0, 40) +
                                   "' is not a whole number");
              }
            if (value < 0 || static_cast<unsigned int>(value) > largest)
              throw InputError(path,
                               "the id " + item.substr(0, 40) +
                                 " is outside 0 to " + std::to_string(largest));
            ids.insert(static_cast<Id>(value));
          }
        if (ids.empty())
          throw InputError(path, "lists no id");
        return ids;
      }


      /** Checks that every id of a set names boundary faces of the mesh
       * (throws InputError naming the entry). */
      using BoundaryIdCheck =
        std::function<void(const std::set<types::boundary_id> &,
                           const std::string &)>;

      /** Declare `Contact pairs`: the names, then one subsection each. */
      void
      declare_contact_pairs(ParameterHandler            &prm,
                            const registry::ListedNames &names);

      /**
       * Read `Contact pairs` into @p m, and `Contact/Initial penetration`
       * into the rigid surfaces already in @p m.
       *
       * @throws InputError naming the pair's entry: a boundary id absent
       *   from the mesh (through @p require_boundary_ids), a negative
       *   friction coefficient or decay, FD > FS, slave and master ids that
       *   overlap without being the same, a slave surface of two pairs
       *   with different types, or an Initial penetration other than
       *   'report' on a tied pair.
       */
      void
      parse_contact_pairs(ParameterHandler      &prm,
                          const BoundaryIdCheck &require_boundary_ids,
                          model::Model          &m);
    } // namespace model_study_parsing
  }   // namespace studies
} // namespace rubberdyn

#endif
