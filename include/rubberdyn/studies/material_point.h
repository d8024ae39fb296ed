#ifndef rubberdyn_studies_material_point_h
#define rubberdyn_studies_material_point_h

#include <rubberdyn/materials/homogeneous_deformation.h>
#include <rubberdyn/materials/material_model.h>
#include <rubberdyn/studies/study.h>

#include <functional>
#include <memory>
#include <string>

namespace rubberdyn
{
  namespace studies
  {
    /**
     * The "Material point" study: one material point of the part
     * `Materials/Specimen` taken through a homogeneous deformation (uniaxial,
     * equibiaxial, pure shear, simple shear or dilatation), optionally
     * unloaded again. Writes `material_point.csv` in the output directory:
     * the deformation gradient, Cauchy and nominal stress, stored energy,
     * equivalent plastic strain and wave speed at every step.
     *
     * It is how a user checks a material card before putting it in a
     * structure, and how the constitutive library is exercised end to end.
     */
    class MaterialPoint : public Study
    {
    public:
      /** Read and check the parameters. */
      explicit MaterialPoint(dealii::ParameterHandler &prm);

      /** Declare `Material point/...` and `Materials/Specimen/...`. */
      static void
      declare_parameters(dealii::ParameterHandler &   prm,
                         const registry::ListedNames &names);

      void
      run(std::ostream &log) override;

      /**
       * Take the specimen through the whole load path without writing
       * anything (it is cheap).
       *
       * @throws InputError naming `Material point/Final stretch` if a state
       *   cannot be computed (the homogeneous solve fails, the material
       *   inverts) or a result is not finite.
       */
      void
      check(std::ostream &log) override;

    private:
      /** The state at one step of the load path. */
      struct Row
      {
        unsigned int                  step = 0;
        double                        load = 0.;
        dealii::Tensor<2, 3>          F;
        double                        J = 1.;
        dealii::SymmetricTensor<2, 3> tau;
        dealii::Tensor<2, 3>          P;
        double                        strain_energy_density     = 0.;
        double                        equivalent_plastic_strain = 0.;
        double                        wave_speed                = 0.;
      };

      /**
       * Take the specimen through the load path, calling @p row at every
       * step (loading, then unloading if asked).
       *
       * @throws InputError as check().
       */
      void
      compute(const std::function<void(const Row &)> &row) const;

      std::unique_ptr<materials::MaterialModel<3>> material;
      materials::homogeneous_deformation::Mode     mode;
      double                                       final_load;
      unsigned int                                 n_steps;
      bool                                         unload;
      std::string                                  output_directory;
    };
  } // namespace studies
} // namespace rubberdyn

#endif
