#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/elements/solid_hex_elements.h>

#include "hex_lanes.h"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

// Set-up, lumped mass, reference steps and output averages of the
// hexahedra; the per-step force kernel is in solid_hex_forces.cc.

namespace rubberdyn
{
  namespace elements
  {
    namespace
    {
      /**
       * Throw if element group @p group (number @p g) has no law, shares a
       * material id with an earlier group (@p group_of_id: the groups of
       * the ids so far, to which its ids are added), is of the mixed u-p
       * formulation, or has an F-bar stabilisation it cannot use.
       */
      void
      check_group(const ElementGroup                         &group,
                  const unsigned int                          g,
                  std::map<types::material_id, unsigned int> &group_of_id)
      {
        if (group.law == nullptr)
          throw std::invalid_argument("SolidHexElements: element group " +
                                      std::to_string(g) +
                                      " has no material law");
        for (const types::material_id id : group.material_ids)
          {
            const auto inserted = group_of_id.emplace(id, g);
            if (!inserted.second)
              throw std::invalid_argument(
                "SolidHexElements: material id " + std::to_string(id) +
                " is in element groups " +
                std::to_string(inserted.first->second) + " and " +
                std::to_string(g));
          }
        if (group.formulation == Formulation::mixed_up)
          throw std::invalid_argument(
            "SolidHexElements: element group " + std::to_string(g) +
            " is of the mixed u-p formulation (MixedUPElements)");
        const bool fbar = (group.formulation == Formulation::fbar);
        if (group.fbar_stabilization != 0. && !fbar)
          throw std::invalid_argument(
            "SolidHexElements: element group " + std::to_string(g) +
            " has an F-bar stabilization but is not of the F-bar "
            "formulation");
        if (!(group.fbar_stabilization >= 0. && group.fbar_stabilization <= 1.))
          throw std::invalid_argument(
            "SolidHexElements: element group " + std::to_string(g) +
            " has an F-bar stabilization outside [0, 1]");
      }



      /**
       * Reference-cell shapes at the @p gauss points and the @p centre:
       * FE_Q(1)'s shape function a is the one of vertex a, as in the
       * FESystem's base element.
       */
      void
      set_reference_shapes(const Quadrature<3>       &gauss,
                           const Quadrature<3>       &centre,
                           internal::ReferenceShapes &reference)
      {
        const FE_Q<3> q1(1);
        for (unsigned int a = 0; a < internal::n_nodes; ++a)
          {
            for (unsigned int q = 0; q < internal::n_q; ++q)
              {
                reference.values[q][a] = q1.shape_value(a, gauss.point(q));
                // The force kernel's sum factorisation assumes FE_Q(1)'s
                // lexicographic shape functions and QGauss's x-fastest point
                // order (source/elements/hex_lanes.h); check it once here.
                const Point<3> &xi = gauss.point(q);
                for (unsigned int d = 0; d < 3; ++d)
                  AssertThrow(std::abs(xi[d] - (((q >> d) & 1) ?
                                                  lanes_of::gauss_high :
                                                  lanes_of::gauss_low)) < 1e-15,
                              ExcInternalError());
              }
            for (unsigned int k = 0; k < 3; ++k)
              reference.centre[a][k] = q1.shape_grad(a, centre.point(0))[k];
          }
      }



      /**
       * Lane @p l of @p block: the local dofs of the cell with the global
       * @p dof_indices, and its geometry from @p fe_values and @p fe_centre
       * (reinitialised on @p cell).
       */
      template <typename CellIterator>
      void
      set_lane(const FiniteElement<3>                     &fe,
               const Utilities::MPI::Partitioner          &partitioner,
               const std::vector<types::global_dof_index> &dof_indices,
               const FEValues<3>                          &fe_values,
               const FEValues<3>                          &fe_centre,
               const CellIterator                         &cell,
               const internal::ReferenceShapes            &reference,
               const unsigned int                          l,
               internal::HexBlock                         &block)
      {
        for (unsigned int i = 0; i < 24; ++i)
          {
            const auto ci = fe.system_to_component_index(i);
            block.dofs[ci.second][ci.first][l] =
              partitioner.global_to_local(dof_indices[i]);
          }
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int c = 0; c < 3; ++c)
            {
              for (unsigned int q = 0; q < internal::n_q; ++q)
                block.inverse_jacobian[q][k][c][l] =
                  fe_values.inverse_jacobian(q)[k][c];
              block.inverse_jacobian_centre[k][c][l] =
                fe_centre.inverse_jacobian(0)[k][c];
            }
        for (unsigned int q = 0; q < internal::n_q; ++q)
          block.JxW[q][l] = fe_values.JxW(q);
        for (unsigned int a = 0; a < internal::n_nodes; ++a)
          for (unsigned int k = 0; k < 3; ++k)
            block.X[a][k][l] = cell->vertex(a)[k];
        // V / int N_a dV, with the integral of add_lumped_mass().
        double volume = 0.;
        for (unsigned int q = 0; q < internal::n_q; ++q)
          volume += block.JxW[q][l];
        for (unsigned int a = 0; a < internal::n_nodes; ++a)
          {
            double integral = 0.;
            for (unsigned int q = 0; q < internal::n_q; ++q)
              integral += reference.values[q][a] * block.JxW[q][l];
            block.inverse_mass_fraction[a][l] = volume / integral;
          }
      }
    } // namespace



    void
    SolidHexElements::initialize(
      const DoFHandler<3, 3> &                                   dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const std::vector<ElementGroup> &                          groups_in,
      const ElementSettings &                                    settings_in)
    {
      settings = settings_in;
      groups.clear();
      std::map<types::material_id, unsigned int> group_of_id;
      for (unsigned int g = 0; g < groups_in.size(); ++g)
        {
          const ElementGroup &group = groups_in[g];
          check_group(group, g, group_of_id);
          const double stabilization = group.fbar_stabilization;
          groups.push_back({group.law,
                            group.formulation,
                            materials::create_stress_kernel(*group.law),
                            group.law->density(),
                            stabilization,
                            stabilization * group.law->bulk_modulus(),
                            group.collapse_advice});
        }

      const FiniteElement<3> &fe = dof_handler.get_fe();
      AssertThrow(fe.n_dofs_per_cell() == 24 && fe.n_components() == 3,
                  ExcMessage("SolidHexElements needs FESystem(FE_Q(1), 3)"));
      const QGauss<3>     gauss(2);
      const Quadrature<3> centre(Point<3>(0.5, 0.5, 0.5));

      set_reference_shapes(gauss, centre, reference);

      MappingQ1<3> mapping;
      FEValues<3>  fe_values(mapping,
                            fe,
                            gauss,
                            update_inverse_jacobians | update_JxW_values);
      FEValues<3>  fe_centre(mapping, fe, centre, update_inverse_jacobians);
      std::vector<types::global_dof_index> dof_indices(24);

      // The cells of each group, in the order of the cell iterator; cells
      // of material ids in no group (rigid parts) get no element.
      std::vector<std::vector<typename DoFHandler<3>::active_cell_iterator>>
        cells_of_group(groups.size());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto group = group_of_id.find(cell->material_id());
            if (group != group_of_id.end())
              cells_of_group[group->second].push_back(cell);
          }

      blocks.clear();
      elements.clear();
      unsigned int history_size = 0;
      for (unsigned int group = 0; group < groups.size(); ++group)
        for (unsigned int first = 0; first < cells_of_group[group].size();
             first += lanes)
          {
            internal::HexBlock block;
            block.group          = group;
            block.history_offset = history_size;
            block.n_active       = std::min<unsigned int>(
              lanes, cells_of_group[group].size() - first);
            history_size +=
              n_q * lanes * groups[group].law->n_state_variables();
            for (unsigned int l = 0; l < lanes; ++l)
              {
                // Unused lanes repeat the block's first element (finite
                // arithmetic only; the kernel ignores them).
                const auto &cell =
                  cells_of_group[group][first + (l < block.n_active ? l : 0)];
                fe_values.reinit(cell);
                fe_centre.reinit(cell);
                cell->get_dof_indices(dof_indices);
                set_lane(fe,
                         *partitioner,
                         dof_indices,
                         fe_values,
                         fe_centre,
                         cell,
                         reference,
                         l,
                         block);
                if (l < block.n_active)
                  {
                    block.element[l] = elements.size();
                    elements.push_back({static_cast<unsigned int>(blocks.size()),
                                        l,
                                        cell->active_cell_index(),
                                        cell->id().to_string(),
                                        cell->center()});
                  }
                else
                  block.element[l] = block.element[0];
              }
            blocks.push_back(block);
          }

      cut_of_block.assign(blocks.size(), numbers::invalid_unsigned_int);
      cuts.clear();
      shortenings.clear();

      history_old.assign(history_size, 0.);
      for (const internal::HexBlock &block : blocks)
        {
          const materials::MaterialModel<3> &law = *groups[block.group].law;
          const unsigned int n_state = law.n_state_variables();
          for (unsigned int p = 0; p < n_q * lanes; ++p)
            law.initialize_state(ArrayView<double>(
              history_old.data() + block.history_offset + p * n_state,
              n_state));
        }
      history_new = history_old;
    }



    std::vector<unsigned int>
    SolidHexElements::cut_sections(const std::vector<SectionPlane> &sections)
    {
      AssertThrow(shortenings.empty(),
                  ExcMessage("The sections are cut only once"));
      std::vector<unsigned int> n_cut(sections.size(), 0);
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          const internal::HexBlock &block = blocks[b];
          SectionCut                cut;
          cut.block                   = b;
          bool                      any = false;
          for (unsigned int l = 0; l < lanes; ++l)
            {
              cut.section[l] = numbers::invalid_unsigned_int;
              for (unsigned int a = 0; a < n_nodes; ++a)
                for (unsigned int d = 0; d < 3; ++d)
                  cut.direction[a][d][l] = 0.;
            }
          for (unsigned int l = 0; l < block.n_active; ++l)
            for (unsigned int s = 0; s < sections.size(); ++s)
              {
                if (sections[s].group != block.group)
                  continue;
                bool far_side[n_nodes];
                if (!plane_cuts_element(block, l, sections[s], far_side))
                  continue;
                if (cut.section[l] != numbers::invalid_unsigned_int)
                  {
                    std::ostringstream message;
                    message << "the element of cell "
                            << elements[block.element[l]].cell_id << " at ("
                            << elements[block.element[l]].centre
                            << ") is cut by two pretension sections";
                    throw std::invalid_argument(message.str());
                  }
                cut.section[l] = s;
                any            = true;
                ++n_cut[s];
                for (unsigned int a = 0; a < n_nodes; ++a)
                  if (far_side[a])
                    for (unsigned int d = 0; d < 3; ++d)
                      cut.direction[a][d][l] = sections[s].normal[d];
              }
          if (any)
            {
              cut_of_block[b] = cuts.size();
              cuts.push_back(cut);
            }
        }
      shortenings.assign(sections.size(), 0.);
      return n_cut;
    }



    void
    SolidHexElements::set_section_shortenings(
      const std::vector<double> &new_shortenings)
    {
      AssertThrow(new_shortenings.size() == shortenings.size(),
                  ExcDimensionMismatch(new_shortenings.size(),
                                       shortenings.size()));
      shortenings = new_shortenings;
    }



    bool
    SolidHexElements::block_offsets(
      const unsigned int block,
      double offsets[internal::n_nodes][3][internal::lanes]) const
    {
      if (cut_of_block.empty() ||
          cut_of_block[block] == numbers::invalid_unsigned_int)
        return false;
      const SectionCut &cut = cuts[cut_of_block[block]];
      for (unsigned int l = 0; l < lanes; ++l)
        {
          const double delta = cut.section[l] == numbers::invalid_unsigned_int ?
                                 0. :
                                 shortenings[cut.section[l]];
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              offsets[a][d][l] = delta * cut.direction[a][d][l];
        }
      return true;
    }



    unsigned int
    SolidHexElements::n_groups() const
    {
      return groups.size();
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
      for (unsigned int e = 0; e < elements.size(); ++e)
        {
          const internal::HexBlock &block = blocks[elements[e].block];
          const unsigned int        l     = elements[e].lane;
          const double rho = groups[block.group].density * density_scaling[e];
          for (unsigned int a = 0; a < n_nodes; ++a)
            {
              double integral = 0.;
              for (unsigned int q = 0; q < n_q; ++q)
                integral += reference.values[q][a] * block.JxW[q][l];
              for (unsigned int d = 0; d < 3; ++d)
                mass.local_element(block.dofs[a][d][l]) += rho * integral;
            }
        }
    }



    SolidHexElements::NodalMasses
    SolidHexElements::nodal_masses(const unsigned int e) const
    {
      const internal::HexBlock &block = blocks[elements[e].block];
      const unsigned int        l     = elements[e].lane;
      const double              rho   = groups[block.group].density;
      NodalMasses               result;
      result.group = block.group;
      for (unsigned int a = 0; a < n_nodes; ++a)
        {
          double integral = 0.;
          for (unsigned int q = 0; q < n_q; ++q)
            integral += reference.values[q][a] * block.JxW[q][l];
          result.mass[a] = rho * integral;
          for (unsigned int d = 0; d < 3; ++d)
            {
              result.dofs[a][d]     = block.dofs[a][d][l];
              result.position[a][d] = block.X[a][d][l];
            }
        }
      return result;
    }



    void
    SolidHexElements::set_time_step_factors(std::vector<double> factors)
    {
      Assert(factors.empty() || factors.size() == elements.size(),
             ExcDimensionMismatch(factors.size(), elements.size()));
      time_step_factors = std::move(factors);
    }



    std::vector<double>
    SolidHexElements::mass_by_group(
      const std::vector<double> &density_scaling) const
    {
      std::vector<double> masses(groups.size(), 0.);
      for (unsigned int e = 0; e < elements.size(); ++e)
        {
          const internal::HexBlock &block  = blocks[elements[e].block];
          double                    volume = 0.;
          for (unsigned int q = 0; q < n_q; ++q)
            volume += block.JxW[q][elements[e].lane];
          masses[block.group] +=
            groups[block.group].density * density_scaling[e] * volume;
        }
      return masses;
    }



    std::vector<double>
    SolidHexElements::reference_time_steps() const
    {
      std::vector<double> steps(elements.size());
      for (const internal::HexBlock &block : blocks)
        {
          // g0_a = grad_X N_a at the centre = (dxi/dX)^T dN_a/dxi.
          lanes_of::Lanes g0[n_nodes][3];
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              g0[a][d] =
                lanes_of::load(block.inverse_jacobian_centre[0][d]) *
                  reference.centre[a][0] +
                lanes_of::load(block.inverse_jacobian_centre[1][d]) *
                  reference.centre[a][1] +
                lanes_of::load(block.inverse_jacobian_centre[2][d]) *
                  reference.centre[a][2];
          const lanes_of::Lanes length =
            lanes_of::characteristic_length(g0, block.inverse_mass_fraction);
          // The F-bar stabilisation adds kappa / r_c to the longitudinal
          // modulus rho_0 c^2, as in the force kernel (doc/theory.md
          // section 8.3; r = 1 without a collapse check).
          const GroupData &group = groups[block.group];
          const double     r_c   = settings.fbar_collapse_ratio > 0. ?
                                     settings.fbar_collapse_ratio :
                                     1.;
          const double c = std::sqrt(
            std::pow(group.law->reference_wave_speed(), 2) +
            group.stabilization_modulus / (group.density * r_c));
          for (unsigned int l = 0; l < block.n_active; ++l)
            steps[block.element[l]] = length[l] / c;
        }
      // Selective mass scaling's factors (set_time_step_factors()).
      for (unsigned int e = 0; e < time_step_factors.size(); ++e)
        steps[e] *= time_step_factors[e];
      return steps;
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
      CellAverages averages(n_active_cells);
      constexpr unsigned int row[6] = {0, 1, 2, 0, 0, 1};
      constexpr unsigned int col[6] = {0, 1, 2, 1, 2, 2};
      std::vector<double>            scratch;
      materials::MaterialResponse<3> response;
      for (const internal::HexBlock &block : blocks)
        {
          const materials::MaterialModel<3> &law = *groups[block.group].law;
          const bool         fbar =
            (groups[block.group].formulation == Formulation::fbar);
          const unsigned int n_state = law.n_state_variables();
          scratch.resize(n_state);
          lanes_of::Lanes ue[n_nodes][3], F0[3][3], G[3][3], J0;
          lanes_of::gather(block, 0, u.begin(), ue);
          double offsets[n_nodes][3][lanes];
          if (block_offsets(&block - blocks.data(), offsets))
            for (unsigned int a = 0; a < n_nodes; ++a)
              for (unsigned int d = 0; d < 3; ++d)
                ue[a][d] += lanes_of::load(offsets[a][d]);
          lanes_of::Lanes H[n_q][3][3], H0[3][3];
          lanes_of::reference_gradients(ue, H, H0);
          lanes_of::deformation_gradient(H0,
                                         block.inverse_jacobian_centre,
                                         F0);
          lanes_of::determinant_and_inverse_transpose(F0, J0, G);
          double mises[lanes] = {}, p[lanes] = {}, J_mean[lanes] = {},
                 alpha[lanes] = {};
          double cauchy[6][lanes] = {};
          for (unsigned int q = 0; q < n_q; ++q)
            {
              lanes_of::Lanes F[3][3], J;
              lanes_of::deformation_gradient(H[q],
                                             block.inverse_jacobian[q],
                                             F);
              lanes_of::determinant_and_inverse_transpose(F, J, G);
              for (unsigned int l = 0; l < block.n_active; ++l)
                {
                  if (!(J[l] > 0.) || !(J0[l] > 0.))
                    continue;
                  const double scale = fbar ? std::cbrt(J0[l] / J[l]) : 1.;
                  Tensor<2, 3> F_bar;
                  for (unsigned int r = 0; r < 3; ++r)
                    for (unsigned int c = 0; c < 3; ++c)
                      F_bar[r][c] = scale * F[r][c][l];
                  try
                    {
                      law.evaluate(
                        F_bar,
                        ArrayView<const double>(history_old.data() +
                                                  block.history_offset +
                                                  (q * lanes + l) * n_state,
                                                n_state),
                        make_array_view(scratch),
                        false,
                        response);
                    }
                  catch (const InvertedMaterialError &)
                    {
                      continue;
                    }
                  const SymmetricTensor<2, 3> sigma =
                    response.kirchhoff_stress / determinant(F_bar);
                  for (unsigned int k = 0; k < 6; ++k)
                    cauchy[k][l] += sigma[row[k]][col[k]] / n_q;
                  mises[l] += std::sqrt(1.5) * deviator(sigma).norm() / n_q;
                  p[l] -= trace(sigma) / 3. / n_q;
                  J_mean[l] += J[l] / n_q;
                  // The history of the state at u (the accepted one when
                  // u is the accepted displacement).
                  alpha[l] +=
                    law.equivalent_plastic_strain(make_array_view(scratch)) /
                    n_q;
                }
            }
          for (unsigned int l = 0; l < block.n_active; ++l)
            {
              const unsigned int cell =
                elements[block.element[l]].active_cell_index;
              for (unsigned int k = 0; k < 6; ++k)
                averages.cauchy_stress[k][cell] = cauchy[k][l];
              averages.von_mises[cell] = mises[l];
              averages.pressure[cell]  = p[l];
              averages.jacobian[cell]  = J_mean[l];
              averages.equivalent_plastic_strain[cell] = alpha[l];
            }
        }
      return averages;
    }
  } // namespace elements
} // namespace rubberdyn
