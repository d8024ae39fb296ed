#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/full_matrix.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/elements/mixed_up_elements.h>

#include <cmath>
#include <map>
#include <stdexcept>

// The mixed u-p hexahedron (doc/theory.md, section 11): Q2 displacement,
// P1 pressure and dilatation discontinuous per cell and condensed. The
// condensation is explicit: with both fields in the same space, tilde J is
// the cell-wise L2 projection of J and tilde p the projection of the
// Cauchy pressure of the law at tilde F, so residual and tangent are
// written directly in the displacement dofs, without a local solve.

namespace rubberdyn
{
  namespace elements
  {
    namespace
    {
      // (Named apart from the Q1 files' n_nodes and n_q, which a unity
      // build may put into the same translation unit.)
      constexpr unsigned int q2_nodes  = MixedUPElements::n_nodes;
      constexpr unsigned int q2_points = MixedUPElements::n_q;
      constexpr unsigned int p1_modes  = MixedUPElements::n_p;
    } // namespace



    /** The kinematics and the law of one element at one displacement. */
    struct MixedUPElements::State
    {
      /** g_a = F^{-T} grad_X N_a at each Gauss point, [q][a]. */
      Tensor<1, 3> g[q2_points][q2_nodes];
      double       J[q2_points];
      /** The projected dilatation and pressure at the Gauss points. */
      double J_tilde[q2_points];
      double p_tilde[q2_points];
      /** tau(tilde F), its spatial tangent, and tr(tau)/3. */
      Tensor<2, 3>          tau[q2_points];
      SymmetricTensor<4, 3> c[q2_points];
      double                p_tau[q2_points];
      /** Strain energy sum_q w_q W(tilde F) (J). */
      double energy;
    };



    namespace
    {
      /**
       * The cell-wise L2 projection onto P1 of a field given at the Gauss
       * points, evaluated back at the Gauss points: (Pi f)_q = phi_q^T
       * M^{-1} sum_q' w_q' phi_q' f_q'.
       */
      template <typename Element>
      void
      project(const Element &e, const double *f, double *result)
      {
        double moments[p1_modes] = {0., 0., 0., 0.};
        for (unsigned int q = 0; q < q2_points; ++q)
          for (unsigned int k = 0; k < p1_modes; ++k)
            moments[k] += e.JxW[q] * e.phi[q][k] * f[q];
        double theta[p1_modes] = {0., 0., 0., 0.};
        for (unsigned int k = 0; k < p1_modes; ++k)
          for (unsigned int l = 0; l < p1_modes; ++l)
            theta[k] += e.mass_inverse[k][l] * moments[l];
        for (unsigned int q = 0; q < q2_points; ++q)
          {
            result[q] = 0.;
            for (unsigned int k = 0; k < p1_modes; ++k)
              result[q] += e.phi[q][k] * theta[k];
          }
      }
    } // namespace



    void
    MixedUPElements::initialize(
      const DoFHandler<3, 3>                                   &dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const std::vector<ElementGroup>                          &groups)
    {
      elements.clear();
      group_laws.clear();
      std::map<types::material_id, unsigned int> group_of_id;
      for (unsigned int g = 0; g < groups.size(); ++g)
        {
          const ElementGroup &group = groups[g];
          if (group.law == nullptr)
            throw std::invalid_argument("MixedUPElements: element group " +
                                        std::to_string(g) +
                                        " has no material law");
          if (group.formulation != Formulation::mixed_up)
            throw std::invalid_argument("MixedUPElements: element group " +
                                        std::to_string(g) +
                                        " is not of the mixed u-p formulation");
          if (group.law->n_state_variables() > 0)
            throw std::invalid_argument(
              "MixedUPElements: element group " + std::to_string(g) +
              " has a law with history (" + group.law->name() +
              "); the mixed u-p element takes hyperelastic laws only");
          for (const types::material_id id : group.material_ids)
            if (!group_of_id.emplace(id, g).second)
              throw std::invalid_argument("MixedUPElements: material id " +
                                          std::to_string(id) +
                                          " is in two element groups");
          group_laws.push_back(group.law);
        }

      const FiniteElement<3> &fe = dof_handler.get_fe();
      if (fe.n_components() != 3 || fe.n_dofs_per_cell() != 3 * q2_nodes ||
          fe.degree != 2)
        throw std::invalid_argument(
          "MixedUPElements needs FESystem(FE_Q(2), 3)");
      const QGauss<3> gauss(3);
      AssertThrow(gauss.size() == q2_points, ExcInternalError());
      const MappingQ1<3>                   mapping;
      FEValues<3>                          fe_values(mapping,
                            fe,
                            gauss,
                            update_gradients | update_JxW_values |
                              update_quadrature_points);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const auto group = group_of_id.find(cell->material_id());
          if (group == group_of_id.end())
            continue;
          fe_values.reinit(cell);
          cell->get_dof_indices(dof_indices);
          Element e;
          e.group   = group->second;
          e.cell_id           = cell->id().to_string();
          e.centre            = cell->center();
          e.active_cell_index = cell->active_cell_index();
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto ci = fe.system_to_component_index(i);
              e.dofs[3 * ci.second + ci.first] =
                partitioner->global_to_local(dof_indices[i]);
              if (ci.first == 0)
                for (unsigned int q = 0; q < q2_points; ++q)
                  {
                    const Tensor<1, 3> grad =
                      fe_values.shape_grad_component(i, q, 0);
                    for (unsigned int c = 0; c < 3; ++c)
                      e.grad[q][ci.second][c] = grad[c];
                  }
            }
          // The P1 basis in the reference coordinates X (not mapped from
          // the unit cell: the unmapped space keeps its approximation
          // order on distorted cells, doc/theory.md section 11.1), centred
          // and scaled by the cell's diameter for conditioning.
          const double h = cell->diameter();
          for (unsigned int q = 0; q < q2_points; ++q)
            {
              e.JxW[q]    = fe_values.JxW(q);
              e.phi[q][0] = 1.;
              for (unsigned int d = 0; d < 3; ++d)
                e.phi[q][1 + d] =
                  (fe_values.quadrature_point(q)[d] - e.centre[d]) / h;
            }
          FullMatrix<double> mass(p1_modes, p1_modes), inverse(p1_modes, p1_modes);
          for (unsigned int q = 0; q < q2_points; ++q)
            for (unsigned int k = 0; k < p1_modes; ++k)
              for (unsigned int l = 0; l < p1_modes; ++l)
                mass(k, l) += e.JxW[q] * e.phi[q][k] * e.phi[q][l];
          inverse.invert(mass);
          for (unsigned int k = 0; k < p1_modes; ++k)
            for (unsigned int l = 0; l < p1_modes; ++l)
              e.mass_inverse[k][l] = inverse(k, l);
          elements.push_back(e);
        }
    }



    bool
    MixedUPElements::evaluate(const Element &e,
                              const double  *u_local,
                              const bool     with_tangent,
                              State         &s,
                              std::string   &message) const
    {
      Tensor<1, 3> ue[q2_nodes];
      for (unsigned int a = 0; a < q2_nodes; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          ue[a][i] = u_local[e.dofs[3 * a + i]];
      Tensor<2, 3> F[q2_points];
      for (unsigned int q = 0; q < q2_points; ++q)
        {
          for (unsigned int d = 0; d < 3; ++d)
            F[q][d][d] = 1.;
          for (unsigned int a = 0; a < q2_nodes; ++a)
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int c = 0; c < 3; ++c)
                F[q][i][c] += ue[a][i] * e.grad[q][a][c];
          s.J[q] = determinant(F[q]);
          if (!(s.J[q] > 0.) || !std::isfinite(s.J[q]))
            {
              message = "det F = " + std::to_string(s.J[q]) +
                        " at a Gauss point (inverted element)";
              return false;
            }
          const Tensor<2, 3> F_inverse_transpose = transpose(invert(F[q]));
          for (unsigned int a = 0; a < q2_nodes; ++a)
            {
              Tensor<1, 3> grad;
              for (unsigned int c = 0; c < 3; ++c)
                grad[c] = e.grad[q][a][c];
              s.g[q][a] = F_inverse_transpose * grad;
            }
        }
      project(e, s.J, s.J_tilde);
      const materials::MaterialModel<3> &law = *group_laws[e.group];
      double                             pressure_over_J[q2_points];
      s.energy = 0.;
      for (unsigned int q = 0; q < q2_points; ++q)
        {
          if (!(s.J_tilde[q] > 0.))
            {
              message = "the projected dilatation is " +
                        std::to_string(s.J_tilde[q]) +
                        " at a Gauss point (inverted element)";
              return false;
            }
          materials::MaterialResponse<3> response;
          try
            {
              law.evaluate(std::cbrt(s.J_tilde[q] / s.J[q]) * F[q],
                           ArrayView<const double>(),
                           ArrayView<double>(),
                           with_tangent,
                           response);
            }
          catch (const InvertedMaterialError &error)
            {
              message = std::string("the law fails: ") + error.what();
              return false;
            }
          s.tau[q] = response.kirchhoff_stress;
          if (with_tangent)
            s.c[q] = response.spatial_tangent;
          s.p_tau[q]         = trace(s.tau[q]) / 3.;
          pressure_over_J[q] = s.p_tau[q] / s.J_tilde[q];
          s.energy += e.JxW[q] * response.strain_energy_density;
        }
      project(e, pressure_over_J, s.p_tilde);
      return true;
    }



    void
    MixedUPElements::compute_residual(const VectorType  &u,
                                      VectorType        &f,
                                      ElementStepResult &result)
    {
      result = ElementStepResult();
      result.internal_energy_by_group.assign(n_groups(), 0.);
      const double *const u_local = u.begin();
      State               s;
      std::string         message;
      for (const Element &e : elements)
        {
          if (!evaluate(e, u_local, false, s, message))
            {
              if (!result.failure.failed)
                {
                  result.failure.failed   = true;
                  result.failure.kind     = FailureKind::inverted_gauss_point;
                  result.failure.cell_id  = e.cell_id;
                  result.failure.position = e.centre;
                  result.failure.message  = message;
                }
              continue;
            }
          // f_a = sum_q w_q [tau - p_tau I + J p_tilde I] g_a.
          for (unsigned int q = 0; q < q2_points; ++q)
            {
              Tensor<2, 3> A = s.tau[q];
              for (unsigned int d = 0; d < 3; ++d)
                A[d][d] += s.J[q] * s.p_tilde[q] - s.p_tau[q];
              A *= e.JxW[q];
              for (unsigned int a = 0; a < q2_nodes; ++a)
                {
                  const Tensor<1, 3> fa = A * s.g[q][a];
                  for (unsigned int i = 0; i < 3; ++i)
                    f.local_element(e.dofs[3 * a + i]) += fa[i];
                }
            }
          result.internal_energy += s.energy;
          result.internal_energy_by_group[e.group] += s.energy;
        }
    }



    void
    MixedUPElements::compute_tangents(
      const VectorType                                                     &u,
      const std::function<void(const unsigned int *dofs, const double *K)> &add)
      const
    {
      constexpr unsigned int n_dofs  = 3 * q2_nodes;
      const double *const    u_local = u.begin();
      std::vector<double>    K(n_dofs * n_dofs);
      State                  s;
      std::string            message;
      Tensor<2, 3>           A[q2_points];
      for (const Element &e : elements)
        {
          if (!evaluate(e, u_local, true, s, message))
            throw InvertedMaterialError(0.);
          for (unsigned int q = 0; q < q2_points; ++q)
            {
              A[q] = s.tau[q];
              for (unsigned int d = 0; d < 3; ++d)
                A[q][d][d] += s.J[q] * s.p_tilde[q] - s.p_tau[q];
            }
          std::fill(K.begin(), K.end(), 0.);
          // Column (b, j): dF = e_j (x) grad_X N_b, l = e_j (x) g_b,
          // dJ/J = g_b[j], d tilde J = Pi(dJ), l_tilde = l + (d tilde J /
          // tilde J - dJ/J)/3 I, d tau = c : sym(l_tilde) + l_tilde tau +
          // tau l_tilde^T, d(p_tau / tilde J) = d p_tau / tilde J - p_tau
          // d tilde J / tilde J^2, d tilde p = Pi(d(p_tau / tilde J)),
          // dA = d tau - d p_tau I + (dJ tilde p + J d tilde p) I,
          // df_a = sum_q w_q [dA g_a - g_a[j] A g_b].
          double       dJ[q2_points], dJ_tilde[q2_points], ds[q2_points], dp_tilde[q2_points];
          Tensor<2, 3> d_tau[q2_points];
          for (unsigned int b = 0; b < q2_nodes; ++b)
            for (unsigned int j = 0; j < 3; ++j)
              {
                for (unsigned int q = 0; q < q2_points; ++q)
                  dJ[q] = s.J[q] * s.g[q][b][j];
                project(e, dJ, dJ_tilde);
                for (unsigned int q = 0; q < q2_points; ++q)
                  {
                    Tensor<2, 3> l;
                    for (unsigned int n = 0; n < 3; ++n)
                      l[j][n] = s.g[q][b][n];
                    const double volumetric =
                      (dJ_tilde[q] / s.J_tilde[q] - s.g[q][b][j]) / 3.;
                    for (unsigned int d = 0; d < 3; ++d)
                      l[d][d] += volumetric;
                    d_tau[q] = Tensor<2, 3>(s.c[q] * symmetrize(l)) +
                               l * s.tau[q] + s.tau[q] * transpose(l);
                    ds[q] =
                      trace(d_tau[q]) / (3. * s.J_tilde[q]) -
                      s.p_tau[q] * dJ_tilde[q] / (s.J_tilde[q] * s.J_tilde[q]);
                  }
                project(e, ds, dp_tilde);
                const unsigned int column = 3 * b + j;
                for (unsigned int q = 0; q < q2_points; ++q)
                  {
                    Tensor<2, 3> dA         = d_tau[q];
                    const double volumetric = -trace(d_tau[q]) / 3. +
                                              dJ[q] * s.p_tilde[q] +
                                              s.J[q] * dp_tilde[q];
                    for (unsigned int d = 0; d < 3; ++d)
                      dA[d][d] += volumetric;
                    dA *= e.JxW[q];
                    const Tensor<1, 3> A_gb = e.JxW[q] * (A[q] * s.g[q][b]);
                    for (unsigned int a = 0; a < q2_nodes; ++a)
                      {
                        const Tensor<1, 3> df =
                          dA * s.g[q][a] - s.g[q][a][j] * A_gb;
                        for (unsigned int i = 0; i < 3; ++i)
                          K[(3 * a + i) * n_dofs + column] += df[i];
                      }
                  }
              }
          add(e.dofs, K.data());
        }
    }



    void
    MixedUPElements::condensed_fields(const VectorType        &u,
                                      const unsigned int       e,
                                      std::array<double, q2_points> &dilatation,
                                      std::array<double, q2_points> &pressure) const
    {
      State       s;
      std::string message;
      if (!evaluate(elements[e], u.begin(), false, s, message))
        throw std::runtime_error("MixedUPElements: " + message);
      for (unsigned int q = 0; q < q2_points; ++q)
        {
          dilatation[q] = s.J_tilde[q];
          pressure[q]   = s.p_tilde[q];
        }
    }



    CellAverages
    MixedUPElements::cell_averages(const VectorType  &u,
                                   const unsigned int n_active_cells) const
    {
      CellAverages averages(n_active_cells);
      constexpr unsigned int row[6] = {0, 1, 2, 0, 0, 1};
      constexpr unsigned int col[6] = {0, 1, 2, 1, 2, 2};
      State                  s;
      std::string            message;
      for (const Element &e : elements)
        {
          // (A failing element, e.g. inverted, is left at zero.)
          if (!evaluate(e, u.begin(), false, s, message))
            continue;
          double volume = 0., cauchy[6] = {}, mises = 0., p = 0., J = 0.;
          for (unsigned int q = 0; q < q2_points; ++q)
            {
              // The stress the residual integrates, A = tau - p_tau 1 +
              // J tilde p 1 (Kirchhoff), over J.
              Tensor<2, 3> A = s.tau[q];
              for (unsigned int d = 0; d < 3; ++d)
                A[d][d] += s.J[q] * s.p_tilde[q] - s.p_tau[q];
              const SymmetricTensor<2, 3> sigma =
                symmetrize(A) / s.J[q];
              const double w = e.JxW[q];
              for (unsigned int k = 0; k < 6; ++k)
                cauchy[k] += w * sigma[row[k]][col[k]];
              mises += w * std::sqrt(1.5) * deviator(sigma).norm();
              p -= w * trace(sigma) / 3.;
              J += w * s.J[q];
              volume += w;
            }
          const unsigned int cell = e.active_cell_index;
          for (unsigned int k = 0; k < 6; ++k)
            averages.cauchy_stress[k][cell] = cauchy[k] / volume;
          averages.von_mises[cell] = mises / volume;
          averages.pressure[cell]  = p / volume;
          averages.jacobian[cell]  = J / volume;
        }
      return averages;
    }
  } // namespace elements
} // namespace rubberdyn
