#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/elements/solid_hex_elements.h>

#include <vector>

#include "hex_lanes.h"

// The consistent tangent of the hexahedra's internal force, for Newton's
// method (doc/theory.md, section 10). Scalar code, one element at a time,
// on the geometry the force kernel uses (internal::HexBlock): reference
// Jacobians, Gauss weights, dof indices and history. The force it
// differentiates is solid_hex_forces.cc's at zero velocity,
//   f_a = sum_q w_q [ tau_bar g_a + t (g0_a - g_a) ],
//   t = tr(tau_bar)/3 - p_stab (F-bar; t = 0 and tau_bar = tau otherwise),
// and the tangent is its directional derivative for each of the 24 unit
// nodal displacements: no term is approximated or dropped.

namespace rubberdyn
{
  namespace elements
  {
    namespace
    {
      using internal::n_nodes;
      using internal::n_q;

      // dN_a/dxi_k of the trilinear shape functions of the reference cell
      // [0,1]^3 at Gauss point q, in FE_Q(1)'s lexicographic vertex order
      // (a = i + 2 j + 4 k) and QGauss's x-fastest point order, the orders
      // SolidHexElements::initialize() checks.
      struct GaussGradients
      {
        double value[n_q][n_nodes][3];
        GaussGradients()
        {
          for (unsigned int q = 0; q < n_q; ++q)
            for (unsigned int a = 0; a < n_nodes; ++a)
              for (unsigned int k = 0; k < 3; ++k)
                {
                  double product = 1.;
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      const double xi = ((q >> d) & 1) ? lanes_of::gauss_high :
                                                         lanes_of::gauss_low;
                      const bool   high = (a >> d) & 1;
                      if (d == k)
                        product *= high ? 1. : -1.;
                      else
                        product *= high ? xi : 1. - xi;
                    }
                  value[q][a][k] = product;
                }
        }
      };

      const GaussGradients gauss_gradients;
    } // namespace



    void
    SolidHexElements::compute_residual(const VectorType  &u,
                                       VectorType        &f,
                                       ElementStepResult &result)
    {
      // Zero velocity (no bulk viscosity) and no mass scaling.
      VectorType zero_velocity;
      zero_velocity.reinit(u, false);
      const std::vector<double> no_scaling(n_elements(), 1.);
      compute_forces(u, zero_velocity, no_scaling, f, result);
    }



    bool
    SolidHexElements::has_history() const
    {
      for (const GroupData &group : groups)
        if (group.law->n_state_variables() > 0)
          return true;
      return false;
    }



    void
    SolidHexElements::element_tangent(const unsigned int e,
                                      const double      *u_local,
                                      unsigned int      *dofs,
                                      double            *K) const
    {
      const ElementInfo &element = elements[e];
      // The section offsets of the element's nodes (zero without a cut).
      double offsets[n_nodes][3][lanes] = {};
      block_offsets(element.block, offsets);
      const internal::HexBlock &block = blocks[element.block];
      const unsigned int        l     = element.lane;
      const GroupData          &group = groups[block.group];
      const bool   fbar  = (group.formulation == Formulation::fbar);
      const double kappa = fbar ? group.stabilization_modulus : 0.;
      const materials::MaterialModel<3> &law     = *group.law;
      const unsigned int                 n_state = law.n_state_variables();
      std::vector<double>                state_scratch(n_state);

      Tensor<1, 3> ue[n_nodes];
      for (unsigned int a = 0; a < n_nodes; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          {
            dofs[3 * a + i] = block.dofs[a][i][l];
            ue[a][i]        = u_local[block.dofs[a][i][l]] + offsets[a][i][l];
          }

      // Reference gradients grad_X N_a at the Gauss points and the
      // centre, and F = I + sum_a u_a (x) grad_X N_a.
      const auto deformation_gradient =
        [&](const Tensor<1, 3>(&grad_N)[n_nodes]) {
          Tensor<2, 3> F;
          for (unsigned int d = 0; d < 3; ++d)
            F[d][d] = 1.;
          for (unsigned int a = 0; a < n_nodes; ++a)
            F += outer_product(ue[a], grad_N[a]);
          return F;
        };
      Tensor<1, 3> grad_N0[n_nodes];
      for (unsigned int a = 0; a < n_nodes; ++a)
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int k = 0; k < 3; ++k)
            grad_N0[a][c] += reference.centre[a][k] *
                             block.inverse_jacobian_centre[k][c][l];
      const Tensor<2, 3> F0 = deformation_gradient(grad_N0);
      const double       J0 = determinant(F0);
      const Tensor<2, 3> F0_inverse_transpose = transpose(invert(F0));
      // g0_a = F0^{-T} grad_X N_a(centre).
      Tensor<1, 3> g0[n_nodes];
      for (unsigned int a = 0; a < n_nodes; ++a)
        g0[a] = F0_inverse_transpose * grad_N0[a];

      std::fill(K, K + 9 * n_nodes * n_nodes, 0.);
      for (unsigned int q = 0; q < n_q; ++q)
        {
          Tensor<1, 3> grad_N[n_nodes];
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int k = 0; k < 3; ++k)
                grad_N[a][c] += gauss_gradients.value[q][a][k] *
                                block.inverse_jacobian[q][k][c][l];
          const Tensor<2, 3> F = deformation_gradient(grad_N);
          const double       J = determinant(F);
          const Tensor<2, 3> F_inverse_transpose = transpose(invert(F));
          Tensor<1, 3>       g[n_nodes];
          for (unsigned int a = 0; a < n_nodes; ++a)
            g[a] = F_inverse_transpose * grad_N[a];

          // The law at F-bar = (J0/J)^(1/3) F (F-bar) or F.
          const double                   r = fbar ? J / J0 : 1.;
          materials::MaterialResponse<3> response;
          const double                  *state_old =
            n_state == 0 ? nullptr :
                                            history_old.data() + block.history_offset +
                             (q * lanes + l) * n_state;
          law.evaluate(fbar ? std::cbrt(1. / r) * F : F,
                       ArrayView<const double>(state_old, n_state),
                       ArrayView<double>(state_scratch.data(), n_state),
                       true,
                       response);
          const Tensor<2, 3>           tau = response.kirchhoff_stress;
          const SymmetricTensor<4, 3> &c   = response.spatial_tangent;
          // F-bar: t = tr(tau)/3 - p_stab with the stabilisation's
          // pressure p_stab = kappa/2 (r - 1/r) and its derivative
          // d p_stab = kappa/2 (r + 1/r) dr/r.
          const double t =
            fbar ? trace(tau) / 3. - 0.5 * kappa * (r - 1. / r) : 0.;
          const double stab_slope = 0.5 * kappa * (r + 1. / r);
          const double w          = block.JxW[q][l];

          // One column per unit displacement of node b, component j:
          // dF = e_j (x) grad_X N_b, l = dF F^{-1} = e_j (x) g_b,
          // l0 = e_j (x) g0_b; dr/r = tr l - tr l0 = g_b[j] - g0_b[j];
          // l_bar = l - (dr/r)/3 I; d tau_bar = c : sym(l_bar) +
          // l_bar tau_bar + tau_bar l_bar^T; d g_a = -l^T g_a =
          // -g_a[j] g_b and d g0_a = -g0_a[j] g0_b.
          for (unsigned int b = 0; b < n_nodes; ++b)
            for (unsigned int j = 0; j < 3; ++j)
              {
                Tensor<2, 3> l_bar;
                for (unsigned int n = 0; n < 3; ++n)
                  l_bar[j][n] = g[b][n];
                const double dr = fbar ? g[b][j] - g0[b][j] : 0.;
                if (fbar)
                  for (unsigned int d = 0; d < 3; ++d)
                    l_bar[d][d] -= dr / 3.;
                const Tensor<2, 3> d_tau =
                  Tensor<2, 3>(c * symmetrize(l_bar)) + l_bar * tau +
                  tau * transpose(l_bar);
                const double d_t =
                  fbar ? trace(d_tau) / 3. - stab_slope * dr : 0.;
                const unsigned int column = 3 * b + j;
                for (unsigned int a = 0; a < n_nodes; ++a)
                  {
                    // d f_a = d tau g_a + tau d g_a
                    //   + d t (g0_a - g_a) + t (d g0_a - d g_a).
                    Tensor<1, 3> df = d_tau * g[a] - g[a][j] * (tau * g[b]);
                    if (fbar)
                      df += d_t * (g0[a] - g[a]) +
                            t * (-g0[a][j] * g0[b] + g[a][j] * g[b]);
                    for (unsigned int i = 0; i < 3; ++i)
                      K[(3 * a + i) * 3 * n_nodes + column] += w * df[i];
                  }
              }
        }
    }



    void
    SolidHexElements::compute_tangents(
      const VectorType                                                     &u,
      const std::function<void(const unsigned int *dofs, const double *K)> &add)
      const
    {
      unsigned int        dofs[3 * n_nodes];
      // Rows 3 a + i, columns 3 b + j.
      std::vector<double> K(9 * n_nodes * n_nodes);
      for (unsigned int e = 0; e < elements.size(); ++e)
        {
          element_tangent(e, u.begin(), dofs, K.data());
          add(dofs, K.data());
        }
    }



    void
    SolidHexElements::compute_section_couplings(
      const VectorType &u,
      const std::function<void(const unsigned int *dofs,
                               const unsigned int  section,
                               const double       *K_g,
                               const double       *KT_g,
                               const double        gKg)> &add) const
    {
      constexpr unsigned int n = 3 * n_nodes;
      unsigned int           dofs[n];
      std::vector<double>    K(n * n);
      double                 K_g[n], KT_g[n], g[n];
      for (const SectionCut &cut : cuts)
        {
          const internal::HexBlock &block = blocks[cut.block];
          for (unsigned int l = 0; l < block.n_active; ++l)
            if (cut.section[l] != numbers::invalid_unsigned_int)
              {
                element_tangent(block.element[l], u.begin(), dofs, K.data());
                for (unsigned int a = 0; a < n_nodes; ++a)
                  for (unsigned int d = 0; d < 3; ++d)
                    g[3 * a + d] = cut.direction[a][d][l];
                double gKg = 0.;
                for (unsigned int i = 0; i < n; ++i)
                  {
                    K_g[i]  = 0.;
                    KT_g[i] = 0.;
                    for (unsigned int j = 0; j < n; ++j)
                      {
                        K_g[i] += K[n * i + j] * g[j];
                        KT_g[i] += K[n * j + i] * g[j];
                      }
                    gKg += g[i] * K_g[i];
                  }
                add(dofs, cut.section[l], K_g, KT_g, gKg);
              }
        }
    }
  } // namespace elements
} // namespace rubberdyn
