#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/elements/solid_hex_elements.h>

#include <cmath>

namespace rubberdyn
{
  namespace elements
  {
    namespace
    {
      // Faces of a hexahedron in deal.II's lexicographic vertex order, each
      // as (v0, v1, v2, v3) with diagonals v0-v3 and v1-v2.
      constexpr unsigned int face_vertices[6][4] = {{0, 2, 4, 6},
                                                    {1, 3, 5, 7},
                                                    {0, 1, 4, 5},
                                                    {2, 3, 6, 7},
                                                    {0, 1, 2, 3},
                                                    {4, 5, 6, 7}};

      inline double
      det3(const double F[3][3])
      {
        return F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1]) -
               F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0]) +
               F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]);
      }

      // F^{-T} = cof(F) / det F.
      inline void
      inverse_transpose(const double F[3][3], const double J, double G[3][3])
      {
        const double s = 1. / J;
        G[0][0]        = s * (F[1][1] * F[2][2] - F[1][2] * F[2][1]);
        G[0][1]        = s * (F[1][2] * F[2][0] - F[1][0] * F[2][2]);
        G[0][2]        = s * (F[1][0] * F[2][1] - F[1][1] * F[2][0]);
        G[1][0]        = s * (F[0][2] * F[2][1] - F[0][1] * F[2][2]);
        G[1][1]        = s * (F[0][0] * F[2][2] - F[0][2] * F[2][0]);
        G[1][2]        = s * (F[0][1] * F[2][0] - F[0][0] * F[2][1]);
        G[2][0]        = s * (F[0][1] * F[1][2] - F[0][2] * F[1][1]);
        G[2][1]        = s * (F[0][2] * F[1][0] - F[0][0] * F[1][2]);
        G[2][2]        = s * (F[0][0] * F[1][1] - F[0][1] * F[1][0]);
      }

      // F = I + sum_a u_a (x) grad N_a.
      inline void
      deformation_gradient(const double u[8][3],
                           const double grad[8][3],
                           double       F[3][3])
      {
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int c = 0; c < 3; ++c)
            {
              double sum = (r == c ? 1. : 0.);
              for (unsigned int a = 0; a < 8; ++a)
                sum += u[a][r] * grad[a][c];
              F[r][c] = sum;
            }
      }

      // Volume / largest face area of the hexahedron with nodes x.
      inline double
      characteristic_length(const double x[8][3], const double volume)
      {
        double max_area = 0.;
        for (const auto &face : face_vertices)
          {
            double d1[3], d2[3];
            for (unsigned int i = 0; i < 3; ++i)
              {
                d1[i] = x[face[3]][i] - x[face[0]][i];
                d2[i] = x[face[2]][i] - x[face[1]][i];
              }
            const double c0 = d1[1] * d2[2] - d1[2] * d2[1];
            const double c1 = d1[2] * d2[0] - d1[0] * d2[2];
            const double c2 = d1[0] * d2[1] - d1[1] * d2[0];
            max_area =
              std::max(max_area, 0.5 * std::sqrt(c0 * c0 + c1 * c1 + c2 * c2));
          }
        return volume / max_area;
      }
    } // namespace



    void
    SolidHexElements::initialize(
      const DoFHandler<3, 3> &                                   dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const std::map<types::material_id, const materials::MaterialModel<3> *>
        &                    material_by_id,
      const ElementSettings &settings_in)
    {
      settings = settings_in;
      laws.clear();
      std::map<types::material_id, unsigned int> law_index;
      for (const auto &entry : material_by_id)
        {
          law_index[entry.first] = laws.size();
          laws.push_back(entry.second);
        }

      const FiniteElement<3> &fe = dof_handler.get_fe();
      AssertThrow(fe.n_dofs_per_cell() == 24 && fe.n_components() == 3,
                  ExcMessage("SolidHexElements needs FESystem(FE_Q(1), 3)"));
      const QGauss<3>    gauss(2);
      const Quadrature<3> centre(Point<3>(0.5, 0.5, 0.5));
      MappingQ1<3>       mapping;
      FEValues<3>        fe_values(mapping,
                            fe,
                            gauss,
                            update_gradients | update_JxW_values |
                              update_quadrature_points);
      FEValues<3> fe_centre(mapping, fe, centre, update_gradients);
      std::vector<types::global_dof_index> dof_indices(24);

      elements.clear();
      unsigned int history_size = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto law = law_index.find(cell->material_id());
            if (law == law_index.end())
              throw InputError("mesh",
                               "no material law for material id " +
                                 std::to_string(cell->material_id()));
            fe_values.reinit(cell);
            fe_centre.reinit(cell);
            cell->get_dof_indices(dof_indices);

            ElementData e;
            for (unsigned int i = 0; i < 24; ++i)
              {
                const auto         ci = fe.system_to_component_index(i);
                const unsigned int d = ci.first, a = ci.second;
                e.dofs[a][d] = partitioner->global_to_local(dof_indices[i]);
                if (d == 0)
                  {
                    for (unsigned int q = 0; q < n_q; ++q)
                      for (unsigned int k = 0; k < 3; ++k)
                        e.grad[q][a][k] = fe_values.shape_grad(i, q)[k];
                    for (unsigned int k = 0; k < 3; ++k)
                      e.grad_centre[a][k] = fe_centre.shape_grad(i, 0)[k];
                  }
              }
            for (unsigned int q = 0; q < n_q; ++q)
              e.JxW[q] = fe_values.JxW(q);
            for (unsigned int a = 0; a < n_nodes; ++a)
              for (unsigned int k = 0; k < 3; ++k)
                e.X[a][k] = cell->vertex(a)[k];
            e.law               = law->second;
            e.history_offset    = history_size;
            e.active_cell_index = cell->active_cell_index();
            e.cell_id           = cell->id().to_string();
            e.centre            = cell->center();
            history_size += n_q * laws[e.law]->n_state_variables();
            elements.push_back(e);
          }

      history_old.assign(history_size, 0.);
      for (const ElementData &e : elements)
        {
          const unsigned int n_state = laws[e.law]->n_state_variables();
          for (unsigned int q = 0; q < n_q; ++q)
            laws[e.law]->initialize_state(ArrayView<double>(
              history_old.data() + e.history_offset + q * n_state, n_state));
        }
      history_new = history_old;
    }



    unsigned int
    SolidHexElements::n_elements() const
    {
      return elements.size();
    }



    void
    SolidHexElements::add_lumped_mass(
      VectorType &               mass,
      const std::vector<double> &density_scaling) const
    {
      // Row sum of the consistent mass: rho * integral of N_a, which for
      // trilinear hexahedra is positive at every node.
      for (unsigned int i = 0; i < elements.size(); ++i)
        {
          const ElementData &e   = elements[i];
          const double       rho = laws[e.law]->density() * density_scaling[i];
          // integral of N_a over the element = sum_q N_a(x_q) JxW_q; at the
          // 2x2x2 Gauss points of a trilinear element N_a takes the values
          // ((1 +- 1/sqrt3)/2)^k products; compute them directly.
          const double g[2] = {0.5 * (1. + 1. / std::sqrt(3.)),
                               0.5 * (1. - 1. / std::sqrt(3.))};
          for (unsigned int a = 0; a < n_nodes; ++a)
            {
              double integral = 0.;
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  // Gauss point q and node a in lexicographic order: the
                  // factor in direction k is g[0] if their bits agree.
                  double N = 1.;
                  for (unsigned int k = 0; k < 3; ++k)
                    N *= (((a >> k) & 1) == ((q >> k) & 1) ? g[0] : g[1]);
                  integral += N * e.JxW[q];
                }
              for (unsigned int d = 0; d < 3; ++d)
                mass.local_element(e.dofs[a][d]) += rho * integral;
            }
        }
    }



    std::vector<double>
    SolidHexElements::reference_time_steps() const
    {
      std::vector<double> steps(elements.size());
      for (unsigned int i = 0; i < elements.size(); ++i)
        {
          const ElementData &e      = elements[i];
          double             volume = 0.;
          for (unsigned int q = 0; q < n_q; ++q)
            volume += e.JxW[q];
          steps[i] = characteristic_length(e.X, volume) /
                     laws[e.law]->reference_wave_speed();
        }
      return steps;
    }



    void
    SolidHexElements::compute_forces(const VectorType &         u,
                                     const VectorType &         v,
                                     const std::vector<double> &density_scaling,
                                     VectorType &               f,
                                     ElementStepResult &        result)
    {
      const bool fbar = (settings.formulation == Formulation::fbar);
      materials::MaterialResponse<3> response;

      for (unsigned int i = 0; i < elements.size(); ++i)
        {
          const ElementData &e = elements[i];
          const materials::MaterialModel<3> &law     = *laws[e.law];
          const unsigned int                 n_state = law.n_state_variables();

          double ue[n_nodes][3], ve[n_nodes][3], x[n_nodes][3];
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              {
                ue[a][d] = u.local_element(e.dofs[a][d]);
                ve[a][d] = v.local_element(e.dofs[a][d]);
                x[a][d]  = e.X[a][d] + ue[a][d];
              }

          // Centre: F0, J0, g0 = F0^{-T} grad N(centre), volumetric rate.
          double F0[3][3];
          deformation_gradient(ue, e.grad_centre, F0);
          const double J0 = det3(F0);
          if (!(J0 > 0.))
            {
              result.failure = {true, e.cell_id, e.centre,
                                "element centre with det F = " +
                                  std::to_string(J0) + " <= 0"};
              continue;
            }
          double G0[3][3];
          inverse_transpose(F0, J0, G0);
          double g0[n_nodes][3];
          double volumetric_rate = 0.;
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int r = 0; r < 3; ++r)
              {
                g0[a][r] = G0[r][0] * e.grad_centre[a][0] +
                           G0[r][1] * e.grad_centre[a][1] +
                           G0[r][2] * e.grad_centre[a][2];
                volumetric_rate += ve[a][r] * g0[a][r];
              }

          double fe[n_nodes][3] = {};
          double max_wave_speed = 0., current_volume = 0.;
          double energy         = 0.;
          // Kirchhoff stress and F^{-T} of each Gauss point, kept for the
          // bulk viscosity pass.
          double tau_q[n_q][3][3], G_q[n_q][3][3], J_q[n_q];
          bool   failed = false;
          for (unsigned int q = 0; q < n_q && !failed; ++q)
            {
              double F[3][3];
              deformation_gradient(ue, e.grad[q], F);
              const double J = det3(F);
              if (!(J > 0.))
                {
                  result.failure = {true, e.cell_id, e.centre,
                                    "Gauss point with det F = " +
                                      std::to_string(J) + " <= 0"};
                  failed = true;
                  break;
                }
              J_q[q] = J;
              inverse_transpose(F, J, G_q[q]);
              const double scale = (fbar ? std::cbrt(J0 / J) : 1.);
              Tensor<2, 3> F_bar;
              for (unsigned int r = 0; r < 3; ++r)
                for (unsigned int c = 0; c < 3; ++c)
                  F_bar[r][c] = scale * F[r][c];
              try
                {
                  law.evaluate(
                    F_bar,
                    ArrayView<const double>(history_old.data() +
                                              e.history_offset + q * n_state,
                                            n_state),
                    ArrayView<double>(history_new.data() + e.history_offset +
                                        q * n_state,
                                      n_state),
                    false,
                    response);
                }
              catch (const InvertedMaterialError &error)
                {
                  result.failure = {true, e.cell_id, e.centre, error.what()};
                  failed         = true;
                  break;
                }
              for (unsigned int r = 0; r < 3; ++r)
                for (unsigned int c = 0; c < 3; ++c)
                  tau_q[q][r][c] = response.kirchhoff_stress[r][c];
              energy += response.strain_energy_density * e.JxW[q];
              current_volume += J * e.JxW[q];
              max_wave_speed =
                std::max(max_wave_speed, response.dilatational_wave_speed);
            }
          if (failed)
            continue;

          // Stable step and bulk viscosity from the element's length scale.
          const double length = characteristic_length(x, current_volume);
          const double wave_speed =
            max_wave_speed / std::sqrt(density_scaling[i]);
          double Q = 0., q_visc = 0.;
          if (volumetric_rate < 0.)
            {
              const double rate = -volumetric_rate;
              Q                 = settings.bulk_viscosity_linear * wave_speed +
                  settings.bulk_viscosity_quadratic * length * rate;
              // q = rho l (C_q l rate^2 + C_l c rate) = rho l Q rate, with
              // rho = rho0 / J0 the current density (mass scaling included).
              const double rho = law.density() * density_scaling[i] / J0;
              q_visc           = rho * length * Q * rate;
              result.bulk_viscosity_power += q_visc * rate * current_volume;
            }
          result.min_time_step =
            std::min(result.min_time_step,
                     length / (Q + std::sqrt(Q * Q + wave_speed * wave_speed)));
          result.internal_energy += energy;

          for (unsigned int q = 0; q < n_q; ++q)
            {
              // Bulk viscosity as an added Kirchhoff pressure q J.
              for (unsigned int r = 0; r < 3; ++r)
                tau_q[q][r][r] -= q_visc * J_q[q];
              const double third_trace =
                fbar ? (tau_q[q][0][0] + tau_q[q][1][1] + tau_q[q][2][2]) / 3. :
                       0.;
              for (unsigned int a = 0; a < n_nodes; ++a)
                {
                  double g[3];
                  for (unsigned int r = 0; r < 3; ++r)
                    g[r] = G_q[q][r][0] * e.grad[q][a][0] +
                           G_q[q][r][1] * e.grad[q][a][1] +
                           G_q[q][r][2] * e.grad[q][a][2];
                  for (unsigned int r = 0; r < 3; ++r)
                    fe[a][r] += e.JxW[q] *
                                (tau_q[q][r][0] * g[0] + tau_q[q][r][1] * g[1] +
                                 tau_q[q][r][2] * g[2] +
                                 third_trace * (g0[a][r] - g[r]));
                }
            }
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              f.local_element(e.dofs[a][d]) += fe[a][d];
        }
    }



    void
    SolidHexElements::accept_history()
    {
      history_old.swap(history_new);
    }



    std::vector<double> &
    SolidHexElements::history()
    {
      return history_old;
    }



    SolidHexElements::CellAverages
    SolidHexElements::cell_averages(const VectorType & u,
                                    const unsigned int n_active_cells) const
    {
      CellAverages averages;
      for (auto &component : averages.cauchy_stress)
        component.assign(n_active_cells, 0.f);
      averages.von_mises.assign(n_active_cells, 0.f);
      averages.pressure.assign(n_active_cells, 0.f);
      averages.jacobian.assign(n_active_cells, 0.f);
      constexpr unsigned int row[6] = {0, 1, 2, 0, 0, 1};
      constexpr unsigned int col[6] = {0, 1, 2, 1, 2, 2};
      const bool fbar = (settings.formulation == Formulation::fbar);
      std::vector<double>            scratch;
      materials::MaterialResponse<3> response;
      for (const ElementData &e : elements)
        {
          const materials::MaterialModel<3> &law     = *laws[e.law];
          const unsigned int                 n_state = law.n_state_variables();
          scratch.resize(n_state);
          double ue[n_nodes][3], F0_raw[3][3];
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              ue[a][d] = u.local_element(e.dofs[a][d]);
          deformation_gradient(ue, e.grad_centre, F0_raw);
          const double J0 = det3(F0_raw);
          double       mises = 0., p = 0., J_mean = 0., cauchy[6] = {};
          for (unsigned int q = 0; q < n_q; ++q)
            {
              double F_raw[3][3];
              deformation_gradient(ue, e.grad[q], F_raw);
              Tensor<2, 3> F;
              for (unsigned int r = 0; r < 3; ++r)
                for (unsigned int c = 0; c < 3; ++c)
                  F[r][c] = F_raw[r][c];
              const double J = det3(F_raw);
              if (!(J > 0.) || !(J0 > 0.))
                continue;
              const Tensor<2, 3> F_bar =
                (fbar ? std::cbrt(J0 / J) : 1.) * F;
              try
                {
                  law.evaluate(F_bar,
                               ArrayView<const double>(history_old.data() +
                                                         e.history_offset +
                                                         q * n_state,
                                                       n_state),
                               make_array_view(scratch),
                               false,
                               response);
                }
              catch (const InvertedMaterialError &)
                {
                  continue;
                }
              const double                  J_bar = determinant(F_bar);
              const SymmetricTensor<2, 3> sigma =
                response.kirchhoff_stress / J_bar;
              for (unsigned int k = 0; k < 6; ++k)
                cauchy[k] += sigma[row[k]][col[k]] / n_q;
              mises += std::sqrt(1.5) * deviator(sigma).norm() / n_q;
              p -= trace(sigma) / 3. / n_q;
              J_mean += J / n_q;
            }
          for (unsigned int k = 0; k < 6; ++k)
            averages.cauchy_stress[k][e.active_cell_index] = cauchy[k];
          averages.von_mises[e.active_cell_index] = mises;
          averages.pressure[e.active_cell_index]  = p;
          averages.jacobian[e.active_cell_index]  = J_mean;
        }
      return averages;
    }
  } // namespace elements
} // namespace rubberdyn
