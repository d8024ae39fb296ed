#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/base/registry.h>
#include <rubberdyn/materials/material_registry.h>

#include <map>
#include <sstream>

namespace rubberdyn
{
  namespace materials
  {
    namespace registry
    {
      namespace
      {
        /** What a law registers: how to declare and create it. */
        struct Entry
        {
          DeclareFunction   declare;
          CreateFunction<2> create_2d;
          CreateFunction<3> create_3d;
        };

        Registry<Entry> &
        laws()
        {
          return Registry<Entry>::instance();
        }

        template <int dim>
        const CreateFunction<dim> &
        factory(const Entry &entry);

        template <>
        const CreateFunction<2> &
        factory<2>(const Entry &entry)
        {
          return entry.create_2d;
        }

        template <>
        const CreateFunction<3> &
        factory<3>(const Entry &entry)
        {
          return entry.create_3d;
        }
      } // namespace


      int
      register_material(const std::string &      name,
                        const std::string &      description,
                        const DeclareFunction &  declare,
                        const CreateFunction<2> &create_2d,
                        const CreateFunction<3> &create_3d)
      {
        return laws().add(name, description,
                          Entry{declare, create_2d, create_3d});
      }



      std::vector<std::string>
      names()
      {
        return laws().names();
      }



      std::string
      pattern_string()
      {
        return laws().pattern();
      }



      void
      declare_part_parameters(
        ParameterHandler &  prm,
        const PartDefaults &defaults,
        const std::vector<std::pair<std::string, std::string>>
          &additional_models)
      {
        std::ostringstream doc;
        doc << laws().documentation("Constitutive law of this part. One of:");
        std::string pattern = pattern_string();
        for (const auto &model : additional_models)
          {
            doc << "\n'" << model.first << "': " << model.second;
            pattern += "|" + model.first;
          }
        prm.declare_entry("Model",
                          defaults.model,
                          Patterns::Selection(pattern),
                          doc.str());
        prm.declare_entry("Density",
                          parameter_tools::format_number(defaults.density),
                          Patterns::Double(0.),
                          "Mass density in the reference configuration "
                          "(kg/mm^3). Must be positive. Rubber: 1.1e-6, "
                          "steel: 7.85e-6, aluminium: 2.7e-6.");
        prm.declare_entry(
          "Poisson's ratio",
          parameter_tools::format_number(defaults.poissons_ratio),
          Patterns::Double(0., 0.5),
          "Small-strain Poisson's ratio, in [0, 0.5). For 'Yeoh' it sets "
          "the bulk modulus when 'Volumetric model = Poisson's ratio'; for "
          "'Elastic' and 'J2 plasticity' it is the elastic Poisson's ratio. "
          "Nearly incompressible rubber: 0.499.");
        prm.declare_entry("Young's modulus",
                          "210",
                          Patterns::Double(0.),
                          "Small-strain Young's modulus E (GPa) of 'Elastic' "
                          "and 'J2 plasticity'. Steel: 210, aluminium: 70.");
        laws().for_each([&prm](const std::string &, const Entry &entry) {
          entry.declare(prm);
        });
      }



      template <int dim>
      std::unique_ptr<MaterialModel<dim>>
      create(const ParameterHandler &prm, const std::string &path)
      {
        const std::string name = prm.get("Model");
        const Entry      *entry = laws().find(name);
        if (entry == nullptr)
          throw InputError(path + "/Model",
                           "unknown material model '" + name +
                             "'; valid names are " + pattern_string());
        std::unique_ptr<MaterialModel<dim>> law =
          factory<dim>(*entry)(prm, path);
        // Every law, also one added later, has its moduli, wave speed and
        // whatever else it derives checked here, before anything runs.
        check_derived_constants(*law, path);
        return law;
      }

      template std::unique_ptr<MaterialModel<2>>
      create<2>(const ParameterHandler &, const std::string &);
      template std::unique_ptr<MaterialModel<3>>
      create<3>(const ParameterHandler &, const std::string &);
    } // namespace registry
  }   // namespace materials
} // namespace rubberdyn
