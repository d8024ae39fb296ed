#include <rubberdyn/elements/solid_hex_elements.h>

#include "hex_lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>

// The explicit hot loop: internal forces, energy, bulk viscosity and stable
// step of the hexahedra, four elements per pass (see doc/theory.md, section
// on the explicit element, and benchmarks/explicit_element).

namespace rubberdyn
{
  namespace elements
  {
    namespace
    {
      using internal::HexBlock;
      using internal::n_nodes;
      using internal::n_q;
      constexpr unsigned int L = internal::lanes;
      constexpr unsigned int n_points = n_q * L;
      static_assert(n_points == materials::StressKernel::batch_size,
                    "a block's Gauss points must fill one law batch");

      // What a block evaluation returns per lane.
      struct BlockResult
      {
        double force[n_nodes][3][L];
        double energy[L];
        double bulk_viscosity_power[L];
        double time_step[L];
        // 0: fine; 1: J0 <= 0 at the centre; 2: J <= 0 at a Gauss point;
        // 3: the law failed.
        unsigned int failure[L];
      };

      // Settings of one call, gathered to keep the kernel's argument list
      // short.
      struct BlockContext
      {
        const internal::ReferenceShapes *reference;
        const materials::StressKernel *  kernel;
        const double *                   u;
        const double *                   v;
        const double *                   history_old;
        double *                         history_new;
        double                           density;
        double                           bulk_viscosity_linear;
        double                           bulk_viscosity_quadratic;
        bool                             fbar;
        /** kappa of the F-bar volumetric stabilisation (GPa), 0: none. */
        double                           stabilization_modulus;
      };

      RUBBERDYN_VECTOR_CLONES void
      evaluate_block(const HexBlock &    block,
                     const BlockContext &context,
                     const double        density_scaling[L],
                     BlockResult &       result)
      {
        using namespace lanes_of;
        const internal::ReferenceShapes &reference = *context.reference;
        Lanes ue[n_nodes][3], ve[n_nodes][3];
        gather(block, context.u, ue);
        gather(block, context.v, ve);

        // Centre: F0, J0, g0_a = F0^{-T} grad_X N_a(centre), volumetric
        // strain rate div v = sum_a v_a . g0_a.
        Lanes H[n_q][3][3], H0[3][3];
        reference_gradients(ue, H, H0);
        Lanes F0[3][3], G0[3][3], J0;
        deformation_gradient(H0, block.inverse_jacobian_centre, F0);
        determinant_and_inverse_transpose(F0, J0, G0);
        // M0 = G0 (dxi/dX)^T at the centre, so that g0_a = M0 dN_a/dxi.
        Lanes M0[3][3];
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int k = 0; k < 3; ++k)
            M0[r][k] = G0[r][0] * load(block.inverse_jacobian_centre[k][0]) +
                       G0[r][1] * load(block.inverse_jacobian_centre[k][1]) +
                       G0[r][2] * load(block.inverse_jacobian_centre[k][2]);
        Lanes g0[n_nodes][3];
        Lanes volumetric_rate = {};
        for (unsigned int a = 0; a < n_nodes; ++a)
          for (unsigned int r = 0; r < 3; ++r)
            {
              g0[a][r] = M0[r][0] * reference.centre[a][0] +
                         M0[r][1] * reference.centre[a][1] +
                         M0[r][2] * reference.centre[a][2];
              volumetric_rate += ve[a][r] * g0[a][r];
            }

        // Gauss points: F, J, F^{-T}, and F-bar = (J0/J)^(1/3) F in the
        // law's layout (point q L + l).
        double F_bar[9 * n_points];
        Lanes  G[n_q][3][3], J[n_q];
        // J_q / J0: the F-bar scale and the stabilisation's measure.
        Lanes volume_ratio[n_q];
        Lanes  min_J = J0;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            Lanes F[3][3];
            deformation_gradient(H[q], block.inverse_jacobian[q], F);
            determinant_and_inverse_transpose(F, J[q], G[q]);
            // NaN-safe minimum: a NaN J makes min_J NaN.
            min_J = (J[q] > min_J) ? min_J : J[q];
            volume_ratio[q] = J[q] / J0;
            const Lanes scale = context.fbar ?
                                  inverse_cube_root(volume_ratio[q]) :
                                  broadcast(1.);
            for (unsigned int r = 0; r < 3; ++r)
              for (unsigned int c = 0; c < 3; ++c)
                store(scale * F[r][c], &F_bar[(3 * r + c) * n_points + q * L]);
          }

        bool any_failure = false;
        for (unsigned int l = 0; l < L; ++l)
          {
            result.failure[l] = !(J0[l] > 0.) ? 1 : !(min_J[l] > 0.) ? 2 : 0;
            any_failure |= (result.failure[l] != 0);
          }
        if (any_failure)
          return;

        // The law at all points of the block at once.
        double tau[6 * n_points], energy[n_points], wave_speed[n_points];
        const unsigned int failed_point =
          context.kernel->evaluate(n_points, F_bar, context.history_old,
                                   context.history_new, tau, energy,
                                   wave_speed);
        if (failed_point < n_points)
          {
            result.failure[failed_point % L] = 3;
            return;
          }

        // Energy, current volume, largest wave speed; length scale, bulk
        // viscosity and stable step.
        Lanes element_energy = {}, volume = {}, max_wave_speed = {};
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Lanes JxW = load(block.JxW[q]);
            element_energy += load(&energy[q * L]) * JxW;
            volume += J[q] * JxW;
            max_wave_speed = max(max_wave_speed, load(&wave_speed[q * L]));
          }
        Lanes x[n_nodes][3];
        for (unsigned int a = 0; a < n_nodes; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            x[a][d] = load(block.X[a][d]) + ue[a][d];
        const Lanes length = characteristic_length(x, volume);
        const Lanes scaling = load(density_scaling);
        const Lanes c       = max_wave_speed / sqrt(scaling);
        // Compression rate (positive in compression, else 0); Q and the
        // bulk viscosity act in compression only.
        const Lanes compressing = volumetric_rate < 0. ? broadcast(1.) :
                                                        broadcast(0.);
        const Lanes rate = -compressing * volumetric_rate;
        const Lanes Q    = compressing * (context.bulk_viscosity_linear * c +
                                       context.bulk_viscosity_quadratic *
                                         length * rate);
        // q = rho l (C_q l rate^2 + C_l c rate) = rho l Q rate, with rho =
        // rho0 / J0 the current density (mass scaling included).
        const Lanes bulk_pressure =
          context.density * scaling / J0 * length * Q * rate;
        // F-bar volumetric stabilisation: U(r) = kappa/2 (r + 1/r - 2) per
        // unit reference volume, r = J_q / J0 (doc/theory.md, section 8.1);
        // its Kirchhoff pressure r U'(r) = kappa/2 (r - 1/r) enters the
        // forces below.
        const double kappa = context.fbar ? context.stabilization_modulus : 0.;
        Lanes stabilization_pressure[n_q];
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Lanes r             = volume_ratio[q];
            const Lanes inverse_r     = 1. / r;
            stabilization_pressure[q] = 0.5 * kappa * (r - inverse_r);
            element_energy +=
              load(block.JxW[q]) * (0.5 * kappa * (r + inverse_r - 2.));
          }
        store(element_energy, result.energy);
        store(bulk_pressure * rate * volume, result.bulk_viscosity_power);
        store(length / (Q + sqrt(Q * Q + c * c)), result.time_step);

        // Forces f_a = sum_q B_q dN_a/dxi(q) + S g0_a (see the class
        // documentation); 1/3 of the trace enters with F-bar only.
        const double third = context.fbar ? 1. / 3. : 0.;
        Lanes        S     = {};
        Lanes        B[n_q][3][3];
        for (unsigned int q = 0; q < n_q; ++q)
          {
            // Bulk viscosity as an added Kirchhoff pressure q J.
            const Lanes qJ = bulk_pressure * J[q];
            Lanes       A[3][3];
            A[0][0] = load(&tau[0 * n_points + q * L]) - qJ;
            A[1][1] = load(&tau[1 * n_points + q * L]) - qJ;
            A[2][2] = load(&tau[2 * n_points + q * L]) - qJ;
            A[0][1] = A[1][0] = load(&tau[3 * n_points + q * L]);
            A[0][2] = A[2][0] = load(&tau[4 * n_points + q * L]);
            A[1][2] = A[2][1] = load(&tau[5 * n_points + q * L]);
            // (1/3 tr tau - p_stab) replaces 1/3 tr tau: the stabilisation
            // force is sum_q w_q p_stab (g_a - g0_a).
            const Lanes third_trace = third * (A[0][0] + A[1][1] + A[2][2]) -
                                      stabilization_pressure[q];
            const Lanes w           = load(block.JxW[q]);
            S += w * third_trace;
            for (unsigned int r = 0; r < 3; ++r)
              A[r][r] -= third_trace;
            // B = w A F^{-T} (dxi/dX)^T.
            Lanes AG[3][3];
            for (unsigned int r = 0; r < 3; ++r)
              for (unsigned int k = 0; k < 3; ++k)
                AG[r][k] = w * (A[r][0] * G[q][0][k] + A[r][1] * G[q][1][k] +
                                A[r][2] * G[q][2][k]);
            for (unsigned int r = 0; r < 3; ++r)
              for (unsigned int k = 0; k < 3; ++k)
                B[q][r][k] = AG[r][0] * load(block.inverse_jacobian[q][k][0]) +
                          AG[r][1] * load(block.inverse_jacobian[q][k][1]) +
                          AG[r][2] * load(block.inverse_jacobian[q][k][2]);
          }
        Lanes force[n_nodes][3] = {};
        add_reference_divergence(B, force);
        for (unsigned int a = 0; a < n_nodes; ++a)
          for (unsigned int r = 0; r < 3; ++r)
            store(force[a][r] + S * g0[a][r], result.force[a][r]);
      }
    } // namespace



    void
    SolidHexElements::compute_forces(const VectorType &         u,
                                     const VectorType &         v,
                                     const std::vector<double> &density_scaling,
                                     VectorType &               f,
                                     ElementStepResult &        result)
    {
      BlockContext context;
      context.reference                = &reference;
      context.u                        = u.begin();
      context.v                        = v.begin();
      context.bulk_viscosity_linear    = settings.bulk_viscosity_linear;
      context.bulk_viscosity_quadratic = settings.bulk_viscosity_quadratic;
      context.fbar = (settings.formulation == Formulation::fbar);
      double *const force = f.begin();

      BlockResult block_result;
      for (const internal::HexBlock &block : blocks)
        {
          context.kernel      = kernels[block.law].get();
          context.density     = laws[block.law]->density();
          context.stabilization_modulus =
            settings.fbar_stabilization * laws[block.law]->bulk_modulus();
          context.history_old = history_old.data() + block.history_offset;
          context.history_new = history_new.data() + block.history_offset;
          double scaling[L];
          for (unsigned int l = 0; l < L; ++l)
            scaling[l] = density_scaling[block.element[l]];

          evaluate_block(block, context, scaling, block_result);

          bool failed = false;
          for (unsigned int l = 0; l < block.n_active && !failed; ++l)
            if (block_result.failure[l] != 0)
              {
                static const char *what[4] = {
                  "",
                  "det F <= 0 at the element centre",
                  "det F <= 0 at a Gauss point",
                  "the material law failed (det F <= 0 or not finite)"};
                const ElementInfo &element = elements[block.element[l]];
                result.failure = {true,
                                  element.cell_id,
                                  element.centre,
                                  what[block_result.failure[l]]};
                failed         = true;
              }
          if (failed)
            continue;

          for (unsigned int l = 0; l < block.n_active; ++l)
            {
              result.internal_energy += block_result.energy[l];
              result.bulk_viscosity_power +=
                block_result.bulk_viscosity_power[l];
              result.min_time_step =
                std::min(result.min_time_step, block_result.time_step[l]);
              for (unsigned int a = 0; a < n_nodes; ++a)
                for (unsigned int d = 0; d < 3; ++d)
                  force[block.dofs[a][d][l]] += block_result.force[a][d][l];
            }
        }
    }
  } // namespace elements
} // namespace rubberdyn
