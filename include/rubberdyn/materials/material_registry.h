#ifndef rubberdyn_materials_material_registry_h
#define rubberdyn_materials_material_registry_h

#include <rubberdyn/materials/material_model.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Defaults of a part's material subsection, chosen by the study that
     * declares the part (a rubber part defaults to Yeoh with rubber's
     * density, a bolt to J2 plasticity with steel's).
     */
    struct PartDefaults
    {
      /** Registered model name, e.g. "Yeoh". */
      std::string model;
      /** Mass density (kg/mm^3). */
      double density;
      /** Poisson's ratio. */
      double poissons_ratio;
    };


    /**
     * The registry of constitutive laws. Each law registers itself (one
     * line at the end of its .cc file, see RUBBERDYN_REGISTER_MATERIAL) with
     * its name, a one-paragraph description, a function that declares its
     * own parameters and factories for 2D and 3D. The list of valid
     * `Model` names in every material subsection comes from here.
     *
     * A part's material subsection holds `Model`, the entries every model
     * shares (`Density`, `Poisson's ratio`) and the entries of every
     * registered model; the chosen model reads the ones it needs.
     */
    namespace registry
    {
      /** Declares the model-specific entries in the current subsection. */
      using DeclareFunction = std::function<void(ParameterHandler &)>;

      /**
       * Creates a law from the current subsection; the second argument is
       * the subsection's full path, for error messages.
       */
      template <int dim>
      using CreateFunction =
        std::function<std::unique_ptr<MaterialModel<dim>>(
          const ParameterHandler &,
          const std::string &)>;

      /**
       * Add a law to the registry. Returns a dummy value so it can
       * initialize a static variable.
       */
      int
      register_material(const std::string &    name,
                        const std::string &    description,
                        const DeclareFunction &declare,
                        const CreateFunction<2> &create_2d,
                        const CreateFunction<3> &create_3d);

      /** The registered names, sorted. */
      std::vector<std::string>
      names();

      /** The registered names joined by '|', for Patterns::Selection. */
      std::string
      pattern_string();

      /**
       * Declare a part's whole material subsection (the caller has entered
       * it): `Model`, `Density`, `Poisson's ratio` and every registered
       * model's own entries. @p additional_models (name, description)
       * are further values of `Model` that the caller handles itself
       * (the Model study's `Rigid`).
       */
      void
      declare_part_parameters(
        ParameterHandler &  prm,
        const PartDefaults &defaults,
        const std::vector<std::pair<std::string, std::string>>
          &additional_models = {});

      /**
       * Create the law chosen by `Model` in the current subsection, whose
       * full path (e.g. "Materials/Rubber") is @p path.
       *
       * @throws InputError if a value is invalid.
       */
      template <int dim>
      std::unique_ptr<MaterialModel<dim>>
      create(const ParameterHandler &prm, const std::string &path);
    } // namespace registry
  }   // namespace materials
} // namespace rubberdyn

/**
 * Register a constitutive law @p classname (a class template on dim with a
 * static `declare_parameters(ParameterHandler&)` and a constructor
 * `(const ParameterHandler&, const std::string &path)`) under @p name.
 */
#define RUBBERDYN_REGISTER_MATERIAL(classname, name, description)          \
  namespace                                                                \
  {                                                                        \
    const int dummy_register_##classname =                                 \
      ::rubberdyn::materials::registry::register_material(                 \
        name,                                                              \
        description,                                                       \
        &classname<3>::declare_parameters,                                 \
        [](const ::dealii::ParameterHandler &prm, const std::string &path) \
          -> std::unique_ptr<::rubberdyn::materials::MaterialModel<2>> {   \
          return std::make_unique<classname<2>>(prm, path);                \
        },                                                                 \
        [](const ::dealii::ParameterHandler &prm, const std::string &path) \
          -> std::unique_ptr<::rubberdyn::materials::MaterialModel<3>> {   \
          return std::make_unique<classname<3>>(prm, path);                \
        });                                                                \
  }

#endif
