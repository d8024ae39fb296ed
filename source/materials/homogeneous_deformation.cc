#include <rubberdyn/materials/homogeneous_deformation.h>

#include <cmath>
#include <stdexcept>

namespace rubberdyn
{
  namespace materials
  {
    namespace homogeneous_deformation
    {
      std::string
      mode_names()
      {
        return "uniaxial stress|equibiaxial stress|pure shear|simple shear|"
               "dilatation";
      }



      Mode
      mode_from_name(const std::string &name)
      {
        if (name == "uniaxial stress")
          return Mode::uniaxial_stress;
        if (name == "equibiaxial stress")
          return Mode::equibiaxial_stress;
        if (name == "pure shear")
          return Mode::pure_shear;
        if (name == "simple shear")
          return Mode::simple_shear;
        if (name == "dilatation")
          return Mode::dilatation;
        throw std::invalid_argument("unknown deformation mode '" + name +
                                    "'; valid: " + mode_names());
      }



      Tensor<2, 3>
      deformation_gradient(const Mode mode, const double load, const double mu)
      {
        Tensor<2, 3> F;
        switch (mode)
          {
            case Mode::uniaxial_stress:
              F[0][0] = load;
              F[1][1] = F[2][2] = mu;
              break;
            case Mode::equibiaxial_stress:
              F[0][0] = F[1][1] = load;
              F[2][2]           = mu;
              break;
            case Mode::pure_shear:
              F[0][0] = load;
              F[1][1] = 1.;
              F[2][2] = mu;
              break;
            case Mode::simple_shear:
              F[0][0] = F[1][1] = F[2][2] = 1.;
              F[0][1]                     = load;
              break;
            case Mode::dilatation:
              F[0][0] = F[1][1] = F[2][2] = load;
              break;
          }
        return F;
      }



      double
      incompressible_lateral_stretch(const Mode mode, const double load)
      {
        switch (mode)
          {
            case Mode::uniaxial_stress:
              return 1. / std::sqrt(load);
            case Mode::equibiaxial_stress:
              return 1. / (load * load);
            case Mode::pure_shear:
              return 1. / load;
            default:
              return 1.;
          }
      }



      double
      solve(const MaterialModel<3> &       material,
            const Mode                     mode,
            const double                   load,
            double                         mu,
            const ArrayView<const double> &state_old,
            const ArrayView<double> &      state_new,
            MaterialResponse<3> &          response)
      {
        const bool has_free_stretch =
          (mode == Mode::uniaxial_stress || mode == Mode::equibiaxial_stress ||
           mode == Mode::pure_shear);
        // The stress-free component and the direction of the free stretch.
        const unsigned int free_component =
          (mode == Mode::uniaxial_stress ? 1 : 2);
        Tensor<2, 3> dF;
        dF[2][2] = 1.;
        if (mode == Mode::uniaxial_stress)
          dF[1][1] = 1.;

        // Newton's method with backtracking: a step is halved until the
        // stress residual decreases (and the stretch stays positive).
        const auto residual_at = [&](const double m) {
          const Tensor<2, 3> F = deformation_gradient(mode, load, m);
          material.evaluate(F, state_old, state_new, true, response);
          return response.kirchhoff_stress[free_component][free_component];
        };
        double residual = residual_at(mu);
        if (!has_free_stretch)
          return mu;
        for (unsigned int iteration = 0; iteration < 50; ++iteration)
          {
            const double scale =
              response.kirchhoff_stress.norm() + material.shear_modulus();
            // Relative 1e-13, plus the round-off floor of the volumetric
            // stress K (J - 1), which cancels to the residual.
            if (std::abs(residual) <=
                1e-13 * scale + 1e-14 * material.bulk_modulus())
              return mu;

            const Tensor<2, 3> F = deformation_gradient(mode, load, mu);
            const double       slope =
              internal::kirchhoff_stress_derivative(response, F, dF)
                [free_component][free_component];
            double step = -residual / slope;
            for (unsigned int halving = 0; halving < 40; ++halving, step /= 2.)
              if (mu + step > 0.)
                {
                  const double new_residual = residual_at(mu + step);
                  if (std::abs(new_residual) < std::abs(residual))
                    {
                      residual = new_residual;
                      break;
                    }
                }
            mu += step;
          }
        throw std::runtime_error(
          "homogeneous deformation: Newton's method for the free lateral "
          "stretch did not converge");
      }
    } // namespace homogeneous_deformation
  }   // namespace materials
} // namespace rubberdyn
