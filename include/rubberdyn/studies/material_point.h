#ifndef rubberdyn_studies_material_point_h
#define rubberdyn_studies_material_point_h

#include <rubberdyn/materials/homogeneous_deformation.h>
#include <rubberdyn/materials/material_model.h>
#include <rubberdyn/studies/study.h>

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

    private:
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
