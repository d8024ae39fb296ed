#ifndef rubberdyn_source_studies_model_study_parsing_h
#define rubberdyn_source_studies_model_study_parsing_h

// Private to source/studies: what the Model study's parsers share (the
// listed names and their subsections, lists of ids, vectors, functions;
// model_study_parsing.cc) and the sections of the Model study, each
// declared and parsed in a file of its own: model_study_mesh.cc,
// model_study_parts.cc, model_study_boundary_conditions.cc,
// model_study_rigid_surfaces.cc, model_study_part_sections.cc (pretension
// and cross sections), model_study_contact_pairs.cc. `Time integration`,
// `Contact` and `Output` are shared with the other studies and live in
// parameters/.

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/parameters/contact_parameters.h>
#include <rubberdyn/parameters/time_integration_parameters.h>
#include <rubberdyn/studies/study.h>

#include <functional>
#include <memory>
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

      /**
       * The pattern of an entry of three numbers x, y, z (a point, a
       * direction, a velocity), what parse_vector() reads.
       */
      inline Patterns::List
      vector_pattern()
      {
        return Patterns::List(Patterns::Double(), 3, 3, ",");
      }

      /**
       * The pattern of a list of ids (Gmsh physical tags) such as "1, 3";
       * empty is allowed by the pattern so that the declared default is
       * valid, and refused by parse_ids().
       */
      inline Patterns::List
      ids_pattern()
      {
        return Patterns::List(Patterns::Integer(0),
                              0,
                              Patterns::List::max_int_value,
                              ",");
      }

      /**
       * The three numbers "a, b, c" of an entry declared with
       * vector_pattern() (which has checked them).
       */
      Tensor<1, 3>
      parse_vector(const std::string &text);

      /**
       * Directions "x, z" of an entry declared with
       * MultipleSelection("x|y|z") as 0, 2.
       *
       * @throws InputError naming @p path: a direction listed twice, or
       *   none.
       */
      std::vector<unsigned int>
      parse_components(const std::string &text, const std::string &path);

      /** Whether @p expression uses one of the variables x, y, z. */
      bool
      uses_position(const std::string &expression);

      /**
       * A deal.II FunctionParser of x, y, z, t with @p n_components
       * components separated by ';', from the entry @p path/@p entry, with
       * the constants of @p constants_text ("a = 1, b = 2"; the entry
       * @p path/Function constants). @p which says in a message what the
       * components are.
       */
      std::shared_ptr<FunctionParser<3>>
      make_function(const std::string &expression,
                    const std::string &constants_text,
                    const unsigned int n_components,
                    const std::string &path,
                    const std::string &which = "one per listed component",
                    const std::string &entry = "Function expression");

      /**
       * What the model's mesh holds, for the sections that name its ids:
       * parse_mesh() fills it, the others check their ids against it.
       */
      struct MeshContents
      {
        /** The mesh file as opened (mm), named in messages. */
        std::string file;
        /** The material ids of the cells, over all ranks. */
        std::set<types::material_id> material_ids;
        /** The boundary ids of the boundary faces, over all ranks. */
        std::set<types::boundary_id> boundary_ids;

        /**
         * @throws InputError naming @p path if an id of @p ids has no
         *   boundary face in the mesh.
         */
        void
        require_boundary_ids(const std::set<types::boundary_id> &ids,
                             const std::string                  &path) const;
      };

      /** Declare `Mesh` (model_study_mesh.cc). */
      void
      declare_mesh(ParameterHandler &prm);

      /**
       * Read `Mesh` into @p m's triangulation: the file relative to the
       * folder of @p parameter_file, scaled and refined.
       *
       * @throws InputError naming the entry: no file, a file that does not
       *   read as a hexahedral Gmsh mesh, a scale <= 0.
       */
      MeshContents
      parse_mesh(ParameterHandler  &prm,
                 const std::string &parameter_file,
                 model::Model      &m);

      /** Declare `Parts`: the names, then one subsection each. */
      void
      declare_parts(ParameterHandler &prm, const registry::ListedNames &names);

      /**
       * Read `Parts` into @p m. A part's F-bar beta is resolved here: its
       * own, or @p time's model-wide one.
       *
       * @throws InputError naming the entry: a material id absent from the
       *   mesh, entries of rigid parts on deformable ones (and back), a
       *   mixed u-p part in an explicit run, no part at all.
       */
      void
      parse_parts(ParameterHandler                  &prm,
                  const parameters::TimeIntegration &time,
                  const MeshContents                &mesh,
                  model::Model                      &m);

      /** Declare `Boundary conditions`: the names, then one subsection each. */
      void
      declare_boundary_conditions(ParameterHandler            &prm,
                                  const registry::ListedNames &names);

      /**
       * Read `Boundary conditions` into @p m.
       *
       * @throws InputError naming the entry: a boundary id absent from the
       *   mesh, a function with the wrong number of components or that does
       *   not parse, a function or components given to a type that does not
       *   use them.
       */
      void
      parse_boundary_conditions(ParameterHandler   &prm,
                                const MeshContents &mesh,
                                model::Model       &m);

      /** Declare `Rigid surfaces`: the names, then one subsection each. */
      void
      declare_rigid_surfaces(ParameterHandler            &prm,
                             const registry::ListedNames &names);

      /**
       * Read `Rigid surfaces` into @p m (after its parts), each with its
       * penalty scale resolved (its own or @p contact's) and @p contact's
       * choice for initial penetrations (`Contact/Initial penetration`).
       *
       * @throws InputError naming the entry: a zero direction, a cylinder
       *   without radius, a boundary id absent from the mesh, a carrying
       *   part that is not rigid, own motion entries on a carried surface,
       *   free directions without mass, a velocity function of position.
       */
      void
      parse_rigid_surfaces(ParameterHandler          &prm,
                           const parameters::Contact &contact,
                           const MeshContents        &mesh,
                           model::Model              &m);

      /** Declare `Pretension sections` and `Cross sections`. */
      void
      declare_part_sections(ParameterHandler            &prm,
                            const registry::ListedNames &names);

      /**
       * Read `Pretension sections` and `Cross sections` into @p m (after
       * its parts).
       *
       * @throws InputError naming the entry: an unknown, rigid or mixed u-p
       *   part, a zero normal, a pretension target <= 0 or lock time
       *   outside the load path, a section in a scheme that does not use
       *   it.
       */
      void
      parse_part_sections(ParameterHandler                  &prm,
                          const parameters::TimeIntegration &time,
                          model::Model                      &m);

      /** Declare `Contact pairs`: the names, then one subsection each. */
      void
      declare_contact_pairs(ParameterHandler            &prm,
                            const registry::ListedNames &names);

      /**
       * Read `Contact pairs` into @p m.
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
