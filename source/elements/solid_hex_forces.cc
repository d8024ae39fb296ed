#include <rubberdyn/elements/solid_hex_elements.h>

#include "hex_lanes.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

// The explicit hot loop: internal forces, energy, bulk viscosity and stable
// step of the hexahedra, eight elements per pass (see doc/theory.md, section
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

      // What a block evaluation returns per lane. Every member is written
      // for every lane (padding lanes report no failure), also when the
      // evaluation fails; force, energy, power and step only when it
      // succeeds.
      struct BlockResult
      {
        double      force[n_nodes][3][L];
        double      energy[L];
        double      bulk_viscosity_power[L];
        double      time_step[L];
        // The same without bulk viscosity (Q = 0), for the assembled
        // estimate's damping factor (time_integration::AssembledStepEstimate).
        double      undamped_time_step[L];
        // Smallest J_q / J0 of the lane's Gauss points (F-bar), else 1.
        double      min_volume_ratio[L];
        FailureKind failure[L];
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
        /** Reference density of the block's group (kg/mm^3). */
        double                           density;
        double                           bulk_viscosity_linear;
        double                           bulk_viscosity_quadratic;
        /** kappa of the F-bar volumetric stabilisation (GPa), 0: none. */
        double                           stabilization_modulus;
        /** F-bar collapse threshold on J_q / J0, 0: no check. */
        double                           collapse_ratio;
        /**
         * The block's section offsets [node][component][lane] (mm), added
         * to the gathered displacements, or nullptr (no section cuts it).
         */
        const double *offsets;
      };

      // What the force pass needs of the kinematics pass, for the lanes of
      // one chunk of a block (V: one double per lane).
      template <typename V>
      struct ChunkKinematics
      {
        // g0_a = F0^{-T} grad_X N_a(centre).
        V g0[n_nodes][3];
        // F^{-T} and J = det F at the Gauss points.
        V G[n_q][3][3];
        V J[n_q];
        // dxi/dX [k][c] and the Gauss weight times det(dX/dxi) at the
        // Gauss points (lanes_of::reference_jacobians()).
        V inverse_jacobian[n_q][3][3];
        V JxW[n_q];
        // F-bar: r_q = J_q / J0 and its minimum over q.
        V volume_ratio[n_q];
        V min_ratio;
        V J0;
        // div v at the centre, sum_a v_a . g0_a.
        V volumetric_rate;
      };



      // Pass 1 on the lanes first_lane, ..., first_lane + width<V> - 1 of
      // a block: the kinematics; F-bar = (J0/J)^(1/3) F into the law's
      // layout (point q L + l); the smallest volume ratio into
      // result.min_volume_ratio; the inversion and F-bar collapse checks
      // (doc/theory.md section 8.1) of the active lanes into
      // result.failure. Returns whether an active lane failed.
      template <bool fbar, typename V>
      inline __attribute__((always_inline)) bool
      chunk_kinematics(const HexBlock &    block,
                       const BlockContext &context,
                       const unsigned int  first_lane,
                       double *            F_bar,
                       ChunkKinematics<V> &kinematics,
                       BlockResult &       result)
      {
        using namespace lanes_of;
        const unsigned int               h         = first_lane;
        const internal::ReferenceShapes &reference = *context.reference;
        V ue[n_nodes][3], ve[n_nodes][3];
        gather(block, h, context.u, ue);
        gather(block, h, context.v, ve);
        if (context.offsets != nullptr)
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              ue[a][d] += load<V>(context.offsets + (3 * a + d) * L + h);

        // The reference geometry, from X.
        V inverse_jacobian_centre[3][3];
        reference_jacobians(block,
                            h,
                            kinematics.inverse_jacobian,
                            kinematics.JxW,
                            inverse_jacobian_centre);
        // (QGauss(2) on the unit cube: every weight is 1/8.)
        for (unsigned int q = 0; q < n_q; ++q)
          kinematics.JxW[q] *= 0.125;

        // Centre: F0, J0, g0_a = F0^{-T} grad_X N_a(centre), volumetric
        // strain rate div v = sum_a v_a . g0_a.
        V H[n_q][3][3], H0[3][3];
        reference_gradients(ue, H, H0);
        V  F0[3][3], G0[3][3];
        V &J0 = kinematics.J0;
        deformation_gradient(H0, inverse_jacobian_centre, F0);
        determinant_and_inverse_transpose(F0, J0, G0);
        // M0 = G0 (dxi/dX)^T at the centre, so that g0_a = M0 dN_a/dxi.
        V M0[3][3];
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int k = 0; k < 3; ++k)
            M0[r][k] = G0[r][0] * inverse_jacobian_centre[k][0] +
                       G0[r][1] * inverse_jacobian_centre[k][1] +
                       G0[r][2] * inverse_jacobian_centre[k][2];
        V(&g0)[n_nodes][3] = kinematics.g0;
        V volumetric_rate  = {};
        for (unsigned int a = 0; a < n_nodes; ++a)
          for (unsigned int r = 0; r < 3; ++r)
            {
              g0[a][r] = M0[r][0] * reference.centre[a][0] +
                         M0[r][1] * reference.centre[a][1] +
                         M0[r][2] * reference.centre[a][2];
              volumetric_rate += ve[a][r] * g0[a][r];
            }
        kinematics.volumetric_rate = volumetric_rate;

        // Gauss points: F, J, F^{-T}, and F-bar.
        V min_J     = J0;
        V min_ratio = broadcast<V>(std::numeric_limits<double>::max());
        for (unsigned int q = 0; q < n_q; ++q)
          {
            V F[3][3];
            deformation_gradient(H[q], kinematics.inverse_jacobian[q], F);
            determinant_and_inverse_transpose(F,
                                              kinematics.J[q],
                                              kinematics.G[q]);
            const V J_q = kinematics.J[q];
            // NaN-safe minima: a NaN makes them NaN.
            min_J = (J_q > min_J) ? min_J : J_q;
            // (One store loop for both formulations: GCC unrolls this one,
            // but not a bare copy loop, which costs 100 instructions per
            // element.)
            V scale = broadcast<V>(1.);
            if constexpr (fbar)
              {
                const V ratio              = J_q / J0;
                kinematics.volume_ratio[q] = ratio;
                min_ratio = (ratio > min_ratio) ? min_ratio : ratio;
                scale     = inverse_cube_root(ratio);
              }
            for (unsigned int r = 0; r < 3; ++r)
              for (unsigned int c = 0; c < 3; ++c)
                store(scale * F[r][c],
                      &F_bar[(3 * r + c) * n_points + q * L + h]);
          }
        kinematics.min_ratio = min_ratio;
        if constexpr (fbar)
          store(min_ratio, result.min_volume_ratio + h);
        else
          store(broadcast<V>(1.), result.min_volume_ratio + h);

        // Inversion, then the F-bar collapse, for the active lanes only.
        bool failed = false;
        for (unsigned int l = 0; l < width<V>; ++l)
          {
            FailureKind kind = FailureKind::none;
            if (h + l < block.n_active)
              {
                if (!(J0[l] > 0.))
                  kind = FailureKind::inverted_centre;
                else if (!(min_J[l] > 0.))
                  kind = FailureKind::inverted_gauss_point;
                else if (fbar && !(min_ratio[l] >= context.collapse_ratio))
                  kind = FailureKind::fbar_collapse;
              }
            result.failure[h + l] = kind;
            failed |= (kind != FailureKind::none);
          }
        return failed;
      }



      // The displacement element's sum_q w_q J_q div_q v (the power of its
      // bulk viscosity over -q), div_q v = (dv/dxi dxi/dX) : F^{-T}; 0 where
      // no lane of the chunk compresses (bulk_pressure = 0), without
      // gathering v.
      template <typename V>
      inline __attribute__((always_inline)) V
      weighted_divergence(const HexBlock &          block,
                          const BlockContext &      context,
                          const unsigned int        first_lane,
                          const V &                 bulk_pressure,
                          const ChunkKinematics<V> &kinematics)
      {
        using namespace lanes_of;
        bool any_compressing = false;
        for (unsigned int l = 0; l < width<V>; ++l)
          any_compressing |= (bulk_pressure[l] != 0.);
        V sum = {};
        if (!any_compressing)
          return sum;
        V ve[n_nodes][3], Hv[n_q][3][3], Hv0[3][3];
        gather(block, first_lane, context.v, ve);
        reference_gradients(ve, Hv, Hv0);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const V(&inverse_jacobian)[3][3] = kinematics.inverse_jacobian[q];
            V divergence                     = {};
            for (unsigned int r = 0; r < 3; ++r)
              for (unsigned int c = 0; c < 3; ++c)
                divergence += kinematics.G[q][r][c] *
                              (Hv[q][r][0] * inverse_jacobian[0][c] +
                               Hv[q][r][1] * inverse_jacobian[1][c] +
                               Hv[q][r][2] * inverse_jacobian[2][c]);
            sum += kinematics.JxW[q] * kinematics.J[q] * divergence;
          }
        return sum;
      }



      // Pass 2 on the lanes of pass 1, after the law (tau, energy and wave
      // speed in its layout): energy, bulk viscosity, stable step and
      // forces into result.
      template <bool fbar, typename V>
      inline __attribute__((always_inline)) void
      chunk_forces(const HexBlock &          block,
                   const BlockContext &      context,
                   const unsigned int        first_lane,
                   const double              density_scaling[L],
                   const double *            tau,
                   const double *            energy,
                   const double *            wave_speed,
                   const ChunkKinematics<V> &kinematics,
                   BlockResult &             result)
      {
        using namespace lanes_of;
        const unsigned int h = first_lane;
        const V(&G)[n_q][3][3] = kinematics.G;
        const V(&J)[n_q]       = kinematics.J;
        const V(&g0)[n_nodes][3] = kinematics.g0;
        const V &J0              = kinematics.J0;
        const V &volumetric_rate = kinematics.volumetric_rate;
        const V(&inverse_jacobian)[n_q][3][3] = kinematics.inverse_jacobian;

        // Energy, current volume, largest wave speed; length scale, bulk
        // viscosity and stable step.
        V element_energy = {}, volume = {}, max_wave_speed = {};
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const V JxW = kinematics.JxW[q];
            element_energy += load<V>(&energy[q * L + h]) * JxW;
            volume += J[q] * JxW;
            max_wave_speed =
              max(max_wave_speed, load<V>(&wave_speed[q * L + h]));
          }
        // l of the bound omega_max <= 2 c / l with the current g0
        // (hex_lanes.h; doc/theory.md section 8.3).
        const V length =
          characteristic_length(g0, block.inverse_mass_fraction, h);
        const V scaling = load<V>(density_scaling + h);
        const V c       = max_wave_speed / sqrt(scaling);
        // Compression rate (positive in compression, else 0); Q and the
        // bulk viscosity act in compression only.
        const V compressing =
          volumetric_rate < 0. ? broadcast<V>(1.) : broadcast<V>(0.);
        const V rate = -compressing * volumetric_rate;
        const V Q    = compressing * (context.bulk_viscosity_linear * c +
                                   context.bulk_viscosity_quadratic *
                                     length * rate);
        // q = rho l (C_q l rate^2 + C_l c rate) = rho l Q rate, with rho =
        // rho0 / J0 the current density (mass scaling included).
        const V bulk_pressure =
          context.density * scaling / J0 * length * Q * rate;
        // F-bar volumetric stabilisation: U(r) = kappa/2 (r + 1/r - 2) per
        // unit reference volume, r = J_q / J0 (doc/theory.md, section 8.1);
        // its Kirchhoff pressure r U'(r) = kappa/2 (r - 1/r) enters the
        // forces below, and its longitudinal modulus r^2 U''(r) = kappa / r
        // the wave speed of the stable step (section 8.3): rho0 c^2 +=
        // kappa / r_c with r_c the collapse ratio, a bound for every state
        // the element accepts (r >= r_c). Not the current min_q r_q: that
        // oscillates with the very mode it bounds, and a step modulated at
        // that frequency pumps energy into it (seen: +75 % in 8000 steps).
        // Without a collapse check (r_c = 0), min_q r_q is all there is.
        const double kappa = fbar ? context.stabilization_modulus : 0.;
        V            stabilization_pressure[n_q];
        V            step_wave_speed = c;
        if constexpr (fbar)
          if (kappa > 0.)
            {
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  const V r                 = kinematics.volume_ratio[q];
                  const V inverse_r         = 1. / r;
                  stabilization_pressure[q] = 0.5 * kappa * (r - inverse_r);
                  element_energy += kinematics.JxW[q] *
                                    (0.5 * kappa * (r + inverse_r - 2.));
                }
              step_wave_speed =
                sqrt(c * c + kappa / (context.density * scaling *
                                      (context.collapse_ratio > 0. ?
                                         broadcast<V>(context.collapse_ratio) :
                                         kinematics.min_ratio)));
            }
        store(element_energy, result.energy + h);
        // The step counts a compression rate only from 1e-10 of the
        // element's frequency scale c / l on: the round-off of a rigid
        // motion's div v, about 1e-16 |v| / l (1e-17 1/ms seen in a falling
        // block), would otherwise switch Q on and the step down by C_l =
        // 6 % at random. Below it the viscous pressure (kept: it is
        // continuous in the rate, so that mirror-image elements stay
        // mirror images) is below 1e-10 C_l rho c^2, and a mode that grew
        // under the undamped step would be caught at that amplitude.
        const V Q_step = rate * length > 1e-10 * c ? Q : broadcast<V>(0.);
        store(length / (Q_step + sqrt(Q_step * Q_step +
                                      step_wave_speed * step_wave_speed)),
              result.time_step + h);
        store(length / step_wave_speed, result.undamped_time_step + h);

        // Power of the viscous force actually applied, sum_a f_a . v_a. Its
        // force is -q sum_q w_q J_q g_a(q). F-bar: the pressure's deviator
        // vanishes, so f_a = -q V g0_a and the power is q V rate. The
        // displacement element takes div v at the Gauss points,
        // div_q v = (dv/dxi dxi/dX) : F^{-T}.
        if constexpr (fbar)
          store(bulk_pressure * rate * volume,
                result.bulk_viscosity_power + h);
        else
          store(-bulk_pressure * weighted_divergence(block, context, h,
                                                     bulk_pressure,
                                                     kinematics),
                result.bulk_viscosity_power + h);

        // Forces f_a = sum_q B_q dN_a/dxi(q) + S g0_a (see the class
        // documentation); 1/3 of the trace and S with F-bar only.
        V S = {};
        V B[n_q][3][3];
        for (unsigned int q = 0; q < n_q; ++q)
          {
            // Bulk viscosity as an added Kirchhoff pressure q J.
            const V qJ = bulk_pressure * J[q];
            V       A[3][3];
            A[0][0] = load<V>(&tau[0 * n_points + q * L + h]) - qJ;
            A[1][1] = load<V>(&tau[1 * n_points + q * L + h]) - qJ;
            A[2][2] = load<V>(&tau[2 * n_points + q * L + h]) - qJ;
            A[0][1] = A[1][0] = load<V>(&tau[3 * n_points + q * L + h]);
            A[0][2] = A[2][0] = load<V>(&tau[4 * n_points + q * L + h]);
            A[1][2] = A[2][1] = load<V>(&tau[5 * n_points + q * L + h]);
            const V w = kinematics.JxW[q];
            if constexpr (fbar)
              {
                // (1/3 tr tau - p_stab) replaces 1/3 tr tau: the
                // stabilisation force is sum_q w_q p_stab (g_a - g0_a).
                V third_trace = (1. / 3.) * (A[0][0] + A[1][1] + A[2][2]);
                if (kappa > 0.)
                  third_trace -= stabilization_pressure[q];
                S += w * third_trace;
                for (unsigned int r = 0; r < 3; ++r)
                  A[r][r] -= third_trace;
              }
            // B = w A F^{-T} (dxi/dX)^T.
            V AG[3][3];
            for (unsigned int r = 0; r < 3; ++r)
              for (unsigned int k = 0; k < 3; ++k)
                AG[r][k] = w * (A[r][0] * G[q][0][k] + A[r][1] * G[q][1][k] +
                                A[r][2] * G[q][2][k]);
            for (unsigned int r = 0; r < 3; ++r)
              for (unsigned int k = 0; k < 3; ++k)
                B[q][r][k] = AG[r][0] * inverse_jacobian[q][k][0] +
                             AG[r][1] * inverse_jacobian[q][k][1] +
                             AG[r][2] * inverse_jacobian[q][k][2];
          }
        V force[n_nodes][3] = {};
        add_reference_divergence(B, force);
        // S = 0 for the displacement element (a bare copy loop would not
        // be unrolled).
        for (unsigned int a = 0; a < n_nodes; ++a)
          for (unsigned int r = 0; r < 3; ++r)
            store(force[a][r] + S * g0[a][r], result.force[a][r] + h);
      }



      // One block of one formulation, in chunks of W lanes (W doubles: one
      // register of the instruction set the caller is compiled for).
      // Returns false if an active lane failed (result.failure says which
      // and why); padding lanes (l >= block.n_active) never fail: their
      // failure is masked, and the law sees F = I there, so that its first
      // failing point is always an active lane's. The law takes all chunks
      // at once (one batch of n_points).
      template <bool fbar, unsigned int W>
      inline __attribute__((always_inline)) bool
      evaluate_block_of(const HexBlock &    block,
                        const BlockContext &context,
                        const double        density_scaling[L],
                        BlockResult &       result)
      {
        typedef typename lanes_of::VectorOf<W>::type V;
        static_assert(L % W == 0, "a block must be whole chunks");
        constexpr unsigned int n_chunks = L / W;

        double             F_bar[9 * n_points];
        ChunkKinematics<V> kinematics[n_chunks];
        bool               failed = false;
        for (unsigned int k = 0; k < n_chunks; ++k)
          failed |= chunk_kinematics<fbar>(
            block, context, k * W, F_bar, kinematics[k], result);
        if (failed)
          return false;

        // Padding lanes: the law at F = I.
        for (unsigned int l = block.n_active; l < L; ++l)
          for (unsigned int q = 0; q < n_q; ++q)
            for (unsigned int r = 0; r < 3; ++r)
              for (unsigned int c = 0; c < 3; ++c)
                F_bar[(3 * r + c) * n_points + q * L + l] = (r == c ? 1. : 0.);

        // The law at all points of the block at once.
        double tau[6 * n_points], energy[n_points], wave_speed[n_points];
        const unsigned int failed_point =
          context.kernel->evaluate(n_points, F_bar, context.history_old,
                                   context.history_new, tau, energy,
                                   wave_speed);
        if (failed_point < n_points)
          {
            Assert(failed_point % L < block.n_active, ExcInternalError());
            result.failure[failed_point % L] = FailureKind::law_failed;
            return false;
          }

        for (unsigned int k = 0; k < n_chunks; ++k)
          chunk_forces<fbar>(block, context, k * W, density_scaling, tau,
                             energy, wave_speed, kinematics[k], result);
        return true;
      }



      // The formulation is chosen per block (all lanes of a block belong
      // to one group); both are compiled into each version.
      template <unsigned int W>
      inline __attribute__((always_inline)) bool
      evaluate_block_in_chunks_of(const HexBlock &    block,
                                  const bool          fbar,
                                  const BlockContext &context,
                                  const double        density_scaling[L],
                                  BlockResult &       result)
      {
        return fbar ? evaluate_block_of<true, W>(block, context,
                                                 density_scaling, result) :
                      evaluate_block_of<false, W>(block, context,
                                                  density_scaling, result);
      }



#if RUBBERDYN_HAVE_VECTOR_CLONES
      // One version per instruction set, chosen at load time as with
      // RUBBERDYN_VECTOR_CLONES, but written out (GCC's function
      // multiversioning) so that each takes the block in chunks of its own
      // register width: 8 doubles with AVX-512, 4 with AVX2 and in the
      // baseline (two SSE2 instructions each, as before AVX-512).
      __attribute__((target("arch=x86-64-v4"))) bool
      evaluate_block(const HexBlock &    block,
                     const bool          fbar,
                     const BlockContext &context,
                     const double        density_scaling[L],
                     BlockResult &       result)
      {
        return evaluate_block_in_chunks_of<8>(block, fbar, context,
                                              density_scaling, result);
      }

      __attribute__((target("arch=x86-64-v3"))) bool
      evaluate_block(const HexBlock &    block,
                     const bool          fbar,
                     const BlockContext &context,
                     const double        density_scaling[L],
                     BlockResult &       result)
      {
        return evaluate_block_in_chunks_of<4>(block, fbar, context,
                                              density_scaling, result);
      }

      __attribute__((target("default"))) bool
      evaluate_block(const HexBlock &    block,
                     const bool          fbar,
                     const BlockContext &context,
                     const double        density_scaling[L],
                     BlockResult &       result)
      {
        return evaluate_block_in_chunks_of<4>(block, fbar, context,
                                              density_scaling, result);
      }
#else
      bool
      evaluate_block(const HexBlock &    block,
                     const bool          fbar,
                     const BlockContext &context,
                     const double        density_scaling[L],
                     BlockResult &       result)
      {
        return evaluate_block_in_chunks_of<4>(block, fbar, context,
                                              density_scaling, result);
      }
#endif

      // N_s += g_e . f_e for the lanes of a block that sections cut
      // (SolidHexElements::SectionCut, a private type: deduced).
      template <typename Cut>
      void
      add_section_forces(const Cut          &cut,
                         const unsigned int  n_active,
                         const BlockResult  &block_result,
                         std::vector<double> &section_force)
      {
        for (unsigned int l = 0; l < n_active; ++l)
          if (cut.section[l] != numbers::invalid_unsigned_int)
            for (unsigned int a = 0; a < n_nodes; ++a)
              for (unsigned int d = 0; d < 3; ++d)
                section_force[cut.section[l]] +=
                  cut.direction[a][d][l] * block_result.force[a][d][l];
      }



      /**
       * The kernel on single blocks for output (section_forces(),
       * section_resultants()): without bulk viscosity (their forces are
       * the stress's), with the accepted history, the new history written
       * into scratch.
       */
      class OutputEvaluator
      {
      public:
        OutputEvaluator(const internal::ReferenceShapes &reference,
                        const double                    *u)
        {
          context.reference                = &reference;
          context.u                        = u;
          context.v                        = u; // unused: no viscosity
          context.bulk_viscosity_linear    = 0.;
          context.bulk_viscosity_quadratic = 0.;
          context.collapse_ratio           = 0.;
          std::fill(no_scaling, no_scaling + L, 1.);
        }

        /**
         * The forces of @p block (of @p group, SolidHexElements::GroupData:
         * deduced), its section offsets @p offsets or nullptr; nullptr if
         * an element failed.
         */
        template <typename Group>
        const BlockResult *
        evaluate(const internal::HexBlock &block,
                 const Group              &group,
                 const double             *history_old,
                 const double             *offsets)
        {
          context.offsets               = offsets;
          context.kernel                = group.kernel.get();
          context.density               = group.density;
          context.stabilization_modulus = group.stabilization_modulus;
          context.history_old           = history_old;
          scratch.resize(n_q * L * group.law->n_state_variables());
          context.history_new = scratch.data();
          if (!evaluate_block(block,
                              group.formulation == Formulation::fbar,
                              context,
                              no_scaling,
                              result))
            return nullptr;
          return &result;
        }

      private:
        BlockContext        context;
        BlockResult         result;
        std::vector<double> scratch;
        double              no_scaling[L];
      };



      // The user's message for a failed element; a collapse's ends with
      // the caller's advice (ElementGroup::collapse_advice).
      std::string
      failure_message(const FailureKind      kind,
                      const double           volume_ratio,
                      const ElementSettings &settings,
                      const std::string     &collapse_advice)
      {
        const auto number = [](const double x) {
          std::ostringstream s;
          s << std::setprecision(3) << x;
          return s.str();
        };
        switch (kind)
          {
            case FailureKind::inverted_centre:
              return "det F <= 0 at the element centre";
            case FailureKind::inverted_gauss_point:
              return "det F <= 0 at a Gauss point";
            case FailureKind::law_failed:
              return "the material law failed (det F <= 0 or not finite)";
            case FailureKind::fbar_collapse:
              return "F-bar hull collapse: the volume J of a Gauss point "
                     "is " +
                     number(volume_ratio) + " of the element centre's (limit " +
                     number(settings.fbar_collapse_ratio) +
                     "), the results are no longer physical" +
                     (collapse_advice.empty() ? std::string() :
                                                "; " + collapse_advice);
            case FailureKind::none:
              break;
          }
        return "";
      }
    } // namespace



    void
    SolidHexElements::compute_forces(const VectorType &         u,
                                     const VectorType &         v,
                                     const std::vector<double> &density_scaling,
                                     VectorType &               f,
                                     ElementStepResult &        result)
    {
      result.internal_energy = 0.;
      result.internal_energy_by_group.assign(groups.size(), 0.);
      result.bulk_viscosity_power = 0.;
      result.bulk_viscosity_power_by_group.assign(groups.size(), 0.);
      result.min_time_step        = std::numeric_limits<double>::max();
      result.min_undamped_time_step = std::numeric_limits<double>::max();
      result.min_damping_factor     = 1.;
      result.min_volume_ratio     = 1.;
      result.failure.failed       = false;
      result.failure.kind         = FailureKind::none;
      result.failure.cell_id.clear();
      result.failure.position = Point<3>();
      result.failure.message.clear();
      result.section_force.assign(shortenings.size(), 0.);

      BlockContext context;
      context.reference                = &reference;
      context.u                        = u.begin();
      context.v                        = v.begin();
      context.bulk_viscosity_linear    = settings.bulk_viscosity_linear;
      context.bulk_viscosity_quadratic = settings.bulk_viscosity_quadratic;
      context.collapse_ratio           = settings.fbar_collapse_ratio;
      double *const force = f.begin();

      BlockResult block_result;
      double      offsets[n_nodes][3][L];
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          const internal::HexBlock &block = blocks[b];
          const GroupData &group        = groups[block.group];
          // (Without sections, one predictable test per block.)
          context.offsets =
            !cuts.empty() && block_offsets(b, offsets) ? &offsets[0][0][0] :
                                                         nullptr;
          context.kernel                = group.kernel.get();
          context.density               = group.density;
          context.stabilization_modulus = group.stabilization_modulus;
          context.history_old = history_old.data() + block.history_offset;
          context.history_new = history_new.data() + block.history_offset;
          double scaling[L];
          for (unsigned int l = 0; l < L; ++l)
            scaling[l] = density_scaling[block.element[l]];

          const bool ok = evaluate_block(block,
                                         group.formulation == Formulation::fbar,
                                         context,
                                         scaling,
                                         block_result);
          for (unsigned int l = 0; l < block.n_active; ++l)
            result.min_volume_ratio = std::min(result.min_volume_ratio,
                                               block_result.min_volume_ratio[l]);
          if (!ok)
            {
              // Report the first failed element; this block adds nothing.
              for (unsigned int l = 0;
                   l < block.n_active && !result.failure.failed;
                   ++l)
                if (block_result.failure[l] != FailureKind::none)
                  {
                    const ElementInfo &element = elements[block.element[l]];
                    result.failure.failed      = true;
                    result.failure.kind        = block_result.failure[l];
                    result.failure.cell_id     = element.cell_id;
                    result.failure.position    = element.centre;
                    result.failure.message =
                      failure_message(block_result.failure[l],
                                      block_result.min_volume_ratio[l],
                                      settings,
                                      group.collapse_advice);
                  }
              continue;
            }

          double group_energy = 0., group_viscous_power = 0.;
          for (unsigned int l = 0; l < block.n_active; ++l)
            {
              result.internal_energy += block_result.energy[l];
              group_energy += block_result.energy[l];
              result.bulk_viscosity_power +=
                block_result.bulk_viscosity_power[l];
              group_viscous_power += block_result.bulk_viscosity_power[l];
              result.min_time_step = std::min(
                result.min_time_step,
                time_step_factors.empty() ?
                  block_result.time_step[l] :
                  block_result.time_step[l] *
                    time_step_factors[block.element[l]]);
              // The assembled estimate's inputs: the step without bulk
              // viscosity and the viscosity's factor on it, sqrt(1 + xi^2)
              // - xi with xi = Q / c (doc/theory.md section 8.3).
              result.min_undamped_time_step =
                std::min(result.min_undamped_time_step,
                         time_step_factors.empty() ?
                           block_result.undamped_time_step[l] :
                           block_result.undamped_time_step[l] *
                             time_step_factors[block.element[l]]);
              result.min_damping_factor =
                std::min(result.min_damping_factor,
                         block_result.time_step[l] /
                           block_result.undamped_time_step[l]);
              for (unsigned int a = 0; a < n_nodes; ++a)
                for (unsigned int d = 0; d < 3; ++d)
                  force[block.dofs[a][d][l]] += block_result.force[a][d][l];
            }
          if (context.offsets != nullptr)
            add_section_forces(cuts[cut_of_block[b]],
                               block.n_active,
                               block_result,
                               result.section_force);
          result.internal_energy_by_group[block.group] += group_energy;
          result.bulk_viscosity_power_by_group[block.group] +=
            group_viscous_power;
        }
    }



    std::vector<double>
    SolidHexElements::section_forces(const VectorType &u) const
    {
      // The kernel on the cut blocks only.
      std::vector<double> force(shortenings.size(), 0.);
      OutputEvaluator     evaluator(reference, u.begin());
      double              offsets[n_nodes][3][L];
      for (const SectionCut &cut : cuts)
        {
          const internal::HexBlock &block = blocks[cut.block];
          block_offsets(cut.block, offsets);
          if (const BlockResult *result =
                evaluator.evaluate(block,
                                   groups[block.group],
                                   history_old.data() + block.history_offset,
                                   &offsets[0][0][0]))
            add_section_forces(cut, block.n_active, *result, force);
        }
      return force;
    }



    std::vector<SectionResultant>
    SolidHexElements::section_resultants(
      const VectorType                &u,
      const std::vector<SectionPlane> &planes) const
    {
      std::vector<SectionResultant> result(planes.size());
      if (planes.empty())
        return result;
      // The kernel on the blocks with a cut lane.
      OutputEvaluator evaluator(reference, u.begin());
      double          offsets[n_nodes][3][L];
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          const internal::HexBlock &block = blocks[b];
          // Which plane cuts each lane (as cut_sections(): nodes strictly
          // on both sides), and which of its nodes lie on the normal's side.
          unsigned int plane_of_lane[L];
          bool         far_side[n_nodes][L];
          bool         any = false;
          for (unsigned int l = 0; l < L; ++l)
            {
              plane_of_lane[l] = numbers::invalid_unsigned_int;
              if (l >= block.n_active)
                continue;
              for (unsigned int s = 0; s < planes.size(); ++s)
                {
                  if (planes[s].group != block.group)
                    continue;
                  bool far[n_nodes];
                  if (!plane_cuts_element(block, l, planes[s], far))
                    continue;
                  // (An element cut by two planes counts for the first.)
                  plane_of_lane[l] = s;
                  any              = true;
                  for (unsigned int a = 0; a < n_nodes; ++a)
                    far_side[a][l] = far[a];
                  break;
                }
            }
          if (!any)
            continue;
          const BlockResult *block_result = evaluator.evaluate(
            block,
            groups[block.group],
            history_old.data() + block.history_offset,
            block_offsets(b, offsets) ? &offsets[0][0][0] : nullptr);
          if (block_result == nullptr)
            continue;
          for (unsigned int l = 0; l < block.n_active; ++l)
            if (plane_of_lane[l] != numbers::invalid_unsigned_int)
              {
                SectionResultant &r = result[plane_of_lane[l]];
                ++r.n_cut;
                for (unsigned int a = 0; a < n_nodes; ++a)
                  {
                    Tensor<1, 3> x, f;
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        x[d] =
                          block.X[a][d][l] + u.begin()[block.dofs[a][d][l]];
                        f[d] = block_result->force[a][d][l];
                      }
                    r.centre_sum += x / double(n_nodes);
                    if (far_side[a][l])
                      {
                        r.force += f;
                        r.moment_about_origin += cross_product_3d(x, f);
                      }
                  }
              }
        }
      return result;
    }
  } // namespace elements
} // namespace rubberdyn
