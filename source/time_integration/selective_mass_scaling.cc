#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/time_integration/selective_mass_scaling.h>

#include <rubberdyn/base/simd_math.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rubberdyn
{
  namespace time_integration
  {
    void
    ScaledElement::set_geometry(
      const std::array<std::array<double, 3>, 8> &X)
    {
      double centroid[3] = {0., 0., 0.};
      for (unsigned int a = 0; a < 8; ++a)
        for (unsigned int d = 0; d < 3; ++d)
          centroid[d] += 0.125 * X[a][d];
      // J = sum_a (|r_a|^2 I - r_a r_a^T): the Gram matrix of the three
      // rotation modes e_k x r_a, positive definite for any hexahedron.
      double J[3][3] = {};
      for (unsigned int a = 0; a < 8; ++a)
        {
          for (unsigned int d = 0; d < 3; ++d)
            r[a][d] = X[a][d] - centroid[d];
          const double rr =
            r[a][0] * r[a][0] + r[a][1] * r[a][1] + r[a][2] * r[a][2];
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              J[k][l] += (k == l ? rr : 0.) - r[a][k] * r[a][l];
        }
      const double det =
        J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
        J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
        J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          {
            // Cofactor of J[l][k] over det (J is symmetric anyway).
            const unsigned int k1 = (l + 1) % 3, k2 = (l + 2) % 3,
                               l1 = (k + 1) % 3, l2 = (k + 2) % 3;
            inverse_inertia[k][l] =
              (J[k1][l1] * J[k2][l2] - J[k1][l2] * J[k2][l1]) / det;
          }
    }



    namespace
    {
      constexpr unsigned int L = 4;
      /** One double per element of a block (GCC vector extension). */
      typedef double Lanes __attribute__((vector_size(L * sizeof(double))));

      inline __attribute__((always_inline)) Lanes
      lanes(const double (&values)[L])
      {
        Lanes v;
        std::memcpy(&v, values, sizeof(v));
        return v;
      }

      // y = P x for the four elements of a block: translation, the mean;
      // rotation, omega = J^-1 sum_a r_a x x_a, the least-squares rigid
      // rotation, whose nodal motion is omega x r_a (translations and
      // rotations about the centroid are orthogonal).
      template <typename Block>
      inline __attribute__((always_inline)) void
      deformation_part(const Block &block,
                       const Lanes  x[8][3],
                       Lanes        y[8][3])
      {
        Lanes mean[3] = {}, L_[3] = {};
        for (unsigned int a = 0; a < 8; ++a)
          {
            const Lanes r0 = lanes(block.r[a][0]),
                        r1 = lanes(block.r[a][1]),
                        r2 = lanes(block.r[a][2]);
            for (unsigned int d = 0; d < 3; ++d)
              mean[d] += x[a][d];
            L_[0] += r1 * x[a][2] - r2 * x[a][1];
            L_[1] += r2 * x[a][0] - r0 * x[a][2];
            L_[2] += r0 * x[a][1] - r1 * x[a][0];
          }
        const Lanes Jxx = lanes(block.inverse_inertia[0]),
                    Jyy = lanes(block.inverse_inertia[1]),
                    Jzz = lanes(block.inverse_inertia[2]),
                    Jxy = lanes(block.inverse_inertia[3]),
                    Jxz = lanes(block.inverse_inertia[4]),
                    Jyz = lanes(block.inverse_inertia[5]);
        const Lanes w0 = Jxx * L_[0] + Jxy * L_[1] + Jxz * L_[2];
        const Lanes w1 = Jxy * L_[0] + Jyy * L_[1] + Jyz * L_[2];
        const Lanes w2 = Jxz * L_[0] + Jyz * L_[1] + Jzz * L_[2];
        for (unsigned int d = 0; d < 3; ++d)
          mean[d] *= 0.125;
        for (unsigned int a = 0; a < 8; ++a)
          {
            const Lanes r0 = lanes(block.r[a][0]),
                        r1 = lanes(block.r[a][1]),
                        r2 = lanes(block.r[a][2]);
            y[a][0] = x[a][0] - mean[0] - (w1 * r2 - w2 * r1);
            y[a][1] = x[a][1] - mean[1] - (w2 * r0 - w0 * r2);
            y[a][2] = x[a][2] - mean[2] - (w0 * r1 - w1 * r0);
          }
      }

      template <typename Block>
      inline __attribute__((always_inline)) void
      gather(const Block &block, const double *in, Lanes x[8][3])
      {
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            for (unsigned int l = 0; l < L; ++l)
              x[a][d][l] = in[block.dofs[a][d][l]];
      }

      template <typename Block>
      inline __attribute__((always_inline)) void
      scatter_add(const Block &block, const Lanes y[8][3], double *out)
      {
        for (unsigned int l = 0; l < L; ++l)
          for (unsigned int a = 0; a < 8; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              out[block.dofs[a][d][l]] += y[a][d][l];
      }

      // out += A in (beta P per element).
      template <typename Block>
      RUBBERDYN_VECTOR_CLONES void
      add_added_mass(const std::vector<Block> &blocks,
                     const double             *in,
                     double                   *out)
      {
        Lanes x[8][3], y[8][3];
        for (const Block &block : blocks)
          {
            gather(block, in, x);
            deformation_part(block, x, y);
            const Lanes beta = lanes(block.beta);
            for (unsigned int a = 0; a < 8; ++a)
              for (unsigned int d = 0; d < 3; ++d)
                y[a][d] *= beta;
            scatter_add(block, y, out);
          }
      }

      // out += sum_e W_e (m I + beta P)^-1 W_e in (the preconditioner's
      // element part).
      template <typename Block>
      RUBBERDYN_VECTOR_CLONES void
      add_element_inverses(const std::vector<Block> &blocks,
                           const double             *in,
                           double                   *out)
      {
        Lanes x[8][3], y[8][3];
        for (const Block &block : blocks)
          {
            gather(block, in, x);
            for (unsigned int a = 0; a < 8; ++a)
              {
                const Lanes w = lanes(block.weight[a]);
                for (unsigned int d = 0; d < 3; ++d)
                  x[a][d] *= w;
              }
            deformation_part(block, x, y);
            const Lanes deformation = lanes(block.deformation_inverse),
                        rigid       = lanes(block.rigid_inverse);
            for (unsigned int a = 0; a < 8; ++a)
              {
                const Lanes w = lanes(block.weight[a]);
                for (unsigned int d = 0; d < 3; ++d)
                  y[a][d] = w * (deformation * y[a][d] +
                                 rigid * (x[a][d] - y[a][d]));
              }
            scatter_add(block, y, out);
          }
      }

      // 1/2 beta |P v|^2 per lane, into energy[block][lane].
      template <typename Block>
      RUBBERDYN_VECTOR_CLONES void
      added_energies(const std::vector<Block> &blocks,
                     const double             *v,
                     double                   *energy)
      {
        Lanes x[8][3], y[8][3];
        for (unsigned int b = 0; b < blocks.size(); ++b)
          {
            const Block &block = blocks[b];
            gather(block, v, x);
            deformation_part(block, x, y);
            Lanes sum = {};
            for (unsigned int a = 0; a < 8; ++a)
              for (unsigned int d = 0; d < 3; ++d)
                sum += y[a][d] * y[a][d];
            sum *= 0.5 * lanes(block.beta);
            std::memcpy(energy + L * b, &sum, sizeof(sum));
          }
      }
    } // namespace



    void
    SelectiveMassScaling::make_blocks()
    {
      blocks.clear();
      for (unsigned int first = 0; first < elements.size(); first += L)
        {
          ElementBlock block;
          block.n_active =
            std::min<unsigned int>(L, elements.size() - first);
          for (unsigned int l = 0; l < L; ++l)
            {
              const bool active = l < block.n_active;
              const ScaledElement &e = elements[active ? first + l : first];
              for (unsigned int a = 0; a < 8; ++a)
                {
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      block.dofs[a][d][l] = e.dofs[a][d];
                      block.r[a][d][l]    = e.r[a][d];
                    }
                  block.weight[a][l] = active ? e.weight[a] : 0.;
                }
              const auto &J = e.inverse_inertia;
              const double values[6] = {
                J[0][0], J[1][1], J[2][2], J[0][1], J[0][2], J[1][2]};
              for (unsigned int k = 0; k < 6; ++k)
                block.inverse_inertia[k][l] = values[k];
              block.beta[l] = active ? e.beta : 0.;
              block.deformation_inverse[l] = 1. / (e.mean_mass + e.beta);
              block.rigid_inverse[l]       = 1. / e.mean_mass;
              block.group[l]               = e.group;
            }
          blocks.push_back(block);
        }
    }



    SelectiveMassScaling::SelectiveMassScaling(
      std::vector<ScaledElement>                                elements,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const SelectiveMassScalingSettings                       &settings,
      const MPI_Comm                                            comm)
      : elements(std::move(elements))
      , partitioner(partitioner)
      , settings(settings)
      , comm(comm)
    {
      for (VectorType *vector :
           {&lumped, &inverse_diagonal, &residual, &search, &product,
            &preconditioned})
        vector->reinit(partitioner);
    }



    void
    SelectiveMassScaling::initialize(
      const VectorType                &lumped_mass,
      const std::vector<unsigned int> &dof_component,
      const std::vector<bool>         &prescribed)
    {
      const unsigned int n_owned = partitioner->locally_owned_size();
      // Which dofs the scaled elements touch (also other ranks' elements:
      // summed to the owner), and the added mass's diagonal, 7/8 beta_e
      // from each element.
      VectorType touched(partitioner), added_diagonal(partitioner);
      for (const ScaledElement &element : elements)
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            {
              // P's diagonal: 1 - 1/8 - L^T J^-1 L with L = r_a x e_d.
              const auto  &r = element.r[a];
              const double L[3] = {d == 0 ? 0. : (d == 1 ? -r[2] : r[1]),
                                   d == 1 ? 0. : (d == 2 ? -r[0] : r[2]),
                                   d == 2 ? 0. : (d == 0 ? -r[1] : r[0])};
              double rotation = 0.;
              for (unsigned int k = 0; k < 3; ++k)
                for (unsigned int l = 0; l < 3; ++l)
                  rotation += L[k] * element.inverse_inertia[k][l] * L[l];
              const unsigned int i = element.dofs[a][d];
              touched.local_element(i) += 1.;
              added_diagonal.local_element(i) +=
                element.beta * (0.875 - rotation);
            }
      touched.compress(VectorOperation::add);
      added_diagonal.compress(VectorOperation::add);

      // The preconditioner's weights: each element's share of its nodes'
      // lumped masses (ghost nodes' masses from their owners).
      VectorType ghosted_mass(partitioner), scaled_share(partitioner);
      ghosted_mass = lumped_mass;
      ghosted_mass.update_ghost_values();
      for (ScaledElement &element : elements)
        {
          element.mean_mass = 0.;
          for (unsigned int a = 0; a < 8; ++a)
            {
              element.weight[a] =
                element.node_mass[a] /
                ghosted_mass.local_element(element.dofs[a][0]);
              element.mean_mass += 0.125 * element.node_mass[a];
              for (unsigned int d = 0; d < 3; ++d)
                scaled_share.local_element(element.dofs[a][d]) +=
                  element.node_mass[a];
            }
        }
      scaled_share.compress(VectorOperation::add);
      make_blocks();

      rest_over_mass.assign(n_owned, 0.);
      in_scaled_element.assign(n_owned, false);
      unknown.assign(n_owned, false);
      unknown_dofs.clear();
      unknown_component.clear();
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          lumped.local_element(i) = lumped_mass.local_element(i);
          inverse_diagonal.local_element(i) =
            1. / (lumped_mass.local_element(i) +
                  added_diagonal.local_element(i));
          if (touched.local_element(i) > 0.)
            {
              const double m = lumped_mass.local_element(i);
              rest_over_mass[i] =
                std::max(0., m - scaled_share.local_element(i)) / (m * m);
              in_scaled_element[i] = true;
              if (!prescribed[i])
                {
                  unknown[i] = true;
                  unknown_dofs.push_back(i);
                  unknown_component.push_back(dof_component[i]);
                }
            }
        }

      // W_{d'd}: M applied to the unknowns' translation in d, summed over
      // the unknowns of direction d' (without prescribed dofs W is the
      // diagonal of the scaled nodes' masses: M_add 1_d = 0).
      double W[3][3];
      VectorType ones(partitioner);
      for (unsigned int d = 0; d < 3; ++d)
        {
          ones = 0.;
          for (unsigned int k = 0; k < unknown_dofs.size(); ++k)
            if (unknown_component[k] == d)
              ones.local_element(unknown_dofs[k]) = 1.;
          ones.update_ghost_values();
          multiply_unknowns(ones, product);
          double sums[3] = {0., 0., 0.};
          for (unsigned int k = 0; k < unknown_dofs.size(); ++k)
            sums[unknown_component[k]] +=
              product.local_element(unknown_dofs[k]);
          Utilities::MPI::sum(ArrayView<const double>(sums, 3),
                              comm,
                              ArrayView<double>(sums, 3));
          for (unsigned int e = 0; e < 3; ++e)
            W[e][d] = sums[e];
        }
      // A direction without unknowns: identity there.
      for (unsigned int d = 0; d < 3; ++d)
        if (W[d][d] == 0.)
          W[d][d] = 1.;
      const double det =
        W[0][0] * (W[1][1] * W[2][2] - W[1][2] * W[2][1]) -
        W[0][1] * (W[1][0] * W[2][2] - W[1][2] * W[2][0]) +
        W[0][2] * (W[1][0] * W[2][1] - W[1][1] * W[2][0]);
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          {
            const unsigned int k1 = (l + 1) % 3, k2 = (l + 2) % 3,
                               l1 = (k + 1) % 3, l2 = (k + 2) % 3;
            inverse_translation_mass[k][l] =
              (W[k1][l1] * W[k2][l2] - W[k1][l2] * W[k2][l1]) / det;
          }
    }



    void
    SelectiveMassScaling::multiply_added_mass(const VectorType &x,
                                              VectorType       &y) const
    {
      // y = sum_e beta_e P_e x_e, into owned and ghost entries, then summed
      // to the owners.
      y = 0.;
      add_added_mass(blocks, x.begin(), y.begin());
      y.compress(VectorOperation::add);
    }



    void
    SelectiveMassScaling::multiply_unknowns(const VectorType &x,
                                            VectorType       &y) const
    {
      multiply_added_mass(x, y);
      const unsigned int n_owned = partitioner->locally_owned_size();
      for (unsigned int i = 0; i < n_owned; ++i)
        y.local_element(i) =
          unknown[i] ?
            y.local_element(i) + lumped.local_element(i) * x.local_element(i) :
            0.;
    }



    void
    SelectiveMassScaling::precondition(VectorType &r, VectorType &z) const
    {
      // Smooth residuals (r = D c with c a rigid motion of each element)
      // come back exact, z = c, as from D^-1; residuals of an element's
      // deformation modes see its added mass beta. Jacobi's diagonal
      // (D + beta) would give smooth modes, which M barely scales, beta's
      // weight too: a condition number about the scaling factor s.
      r.update_ghost_values();
      z = 0.;
      add_element_inverses(blocks, r.begin(), z.begin());
      z.compress(VectorOperation::add);
      const unsigned int n_owned = partitioner->locally_owned_size();
      for (unsigned int i = 0; i < n_owned; ++i)
        z.local_element(i) =
          unknown[i] ?
            z.local_element(i) + rest_over_mass[i] * r.local_element(i) :
            0.;
    }



    unsigned int
    SelectiveMassScaling::solve(const VectorType &f, VectorType &a)
    {
      // Residual r = f - M a on the unknowns (the prescribed dofs' known
      // accelerations enter through M a).
      a.update_ghost_values();
      multiply_added_mass(a, residual);
      // |r|^2, |f|^2 and |M a|^2 on the unknowns, in the D^-1 norm.
      double norms[3] = {0., 0., 0.};
      for (const unsigned int i : unknown_dofs)
        {
          const double m_a = residual.local_element(i) +
                             lumped.local_element(i) * a.local_element(i);
          const double r = f.local_element(i) - m_a;
          residual.local_element(i) = r;
          const double w = inverse_diagonal.local_element(i);
          norms[0] += r * r * w;
          norms[1] += f.local_element(i) * f.local_element(i) * w;
          norms[2] += m_a * m_a * w;
        }
      Utilities::MPI::sum(ArrayView<const double>(norms, 3),
                          comm,
                          ArrayView<double>(norms, 3));
      // The right-hand side's size: the forces on the unknowns, or, where
      // they vanish (prescribed neighbours drive the nodes), the inertia
      // of the start. Both zero: the unknowns' accelerations are zero and
      // so is the residual.
      const double target = settings.tolerance * settings.tolerance *
                            std::max(norms[1], norms[2]);

      // The residual off the unknowns is zero (the preconditioner reads
      // its ghosts).
      const unsigned int n_owned = partitioner->locally_owned_size();
      for (unsigned int i = 0; i < n_owned; ++i)
        if (!unknown[i])
          residual.local_element(i) = 0.;
      search = 0.;
      double       rho        = 0.;
      unsigned int iterations = 0;
      if (norms[0] > target && norms[0] > 0.)
        {
          precondition(residual, preconditioned);
          for (const unsigned int i : unknown_dofs)
            {
              const double z          = preconditioned.local_element(i);
              search.local_element(i) = z;
              rho += residual.local_element(i) * z;
            }
          rho = Utilities::MPI::sum(rho, comm);
          while (true)
            {
              if (iterations == settings.max_iterations)
                throw std::runtime_error(
                  "the selective mass scaling solve did not converge in " +
                  std::to_string(settings.max_iterations) +
                  " iterations (relative residual " +
                  std::to_string(std::sqrt(norms[0] / std::max(norms[1], norms[2]))) + ")");
              ++iterations;
              search.update_ghost_values();
              multiply_unknowns(search, product);
              double pq = 0.;
              for (const unsigned int i : unknown_dofs)
                pq += search.local_element(i) * product.local_element(i);
              pq                 = Utilities::MPI::sum(pq, comm);
              const double alpha = rho / pq;
              double rr = 0.;
              for (const unsigned int i : unknown_dofs)
                {
                  a.local_element(i) += alpha * search.local_element(i);
                  const double r = residual.local_element(i) -
                                   alpha * product.local_element(i);
                  residual.local_element(i) = r;
                  rr += r * r * inverse_diagonal.local_element(i);
                }
              // The stopping test's norm and r.z in one reduction.
              precondition(residual, preconditioned);
              double sums[2] = {rr, 0.};
              for (const unsigned int i : unknown_dofs)
                sums[1] +=
                  residual.local_element(i) * preconditioned.local_element(i);
              Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                                  comm,
                                  ArrayView<double>(sums, 2));
              norms[0] = sums[0];
              if (norms[0] <= target)
                break;
              const double rho_new = sums[1];
              const double beta    = rho_new / rho;
              rho                  = rho_new;
              for (const unsigned int i : unknown_dofs)
                search.local_element(i) = preconditioned.local_element(i) +
                                          beta * search.local_element(i);
            }
        }

      // Momentum: the residual's sum per direction is what the scaled
      // nodes' momentum would miss. A uniform correction c_d of the
      // unknowns' accelerations changes that sum by c_d 1^T M_uu 1.
      double missing[3] = {0., 0., 0.};
      for (unsigned int k = 0; k < unknown_dofs.size(); ++k)
        missing[unknown_component[k]] +=
          residual.local_element(unknown_dofs[k]);
      Utilities::MPI::sum(ArrayView<const double>(missing, 3),
                          comm,
                          ArrayView<double>(missing, 3));
      double correction[3];
      for (unsigned int d = 0; d < 3; ++d)
        correction[d] = inverse_translation_mass[d][0] * missing[0] +
                        inverse_translation_mass[d][1] * missing[1] +
                        inverse_translation_mass[d][2] * missing[2];
      for (unsigned int k = 0; k < unknown_dofs.size(); ++k)
        a.local_element(unknown_dofs[k]) += correction[unknown_component[k]];
      a.update_ghost_values();

      iterations_last = iterations;
      iterations_total += iterations;
      iterations_largest = std::max(iterations_largest, iterations);
      ++solves;
      return iterations;
    }



    double
    SelectiveMassScaling::added_kinetic_energy(
      const VectorType    &velocity,
      std::vector<double> &by_group) const
    {
      // 1/2 sum_e beta_e |P_e v_e|^2 (P_e a projector).
      std::vector<double> &energy = energy_scratch;
      energy.resize(L * blocks.size());
      added_energies(blocks, velocity.begin(), energy.data());
      double sum = 0.;
      for (unsigned int b = 0; b < blocks.size(); ++b)
        for (unsigned int l = 0; l < blocks[b].n_active; ++l)
          {
            by_group[blocks[b].group[l]] += energy[L * b + l];
            sum += energy[L * b + l];
          }
      return sum;
    }



    std::vector<double>
    SelectiveMassScaling::added_mass_by_group(const unsigned int n_groups) const
    {
      std::vector<double> mass(n_groups, 0.);
      // The trace of beta_e P_e over one direction: P_e has rank 18 of 24.
      for (const ScaledElement &element : elements)
        mass[element.group] += 6. * element.beta;
      return mass;
    }



    void
    SelectiveMassScaling::save(std::ostream &out) const
    {
      const double counters[3] = {double(iterations_total),
                                  double(iterations_largest),
                                  double(solves)};
      binary_io::write_doubles(out, counters, 3);
    }



    void
    SelectiveMassScaling::load(std::istream &in)
    {
      double counters[3];
      binary_io::read_doubles(in, counters, 3, "selective mass scaling counters");
      iterations_total   = static_cast<unsigned long long>(counters[0]);
      iterations_largest = static_cast<unsigned int>(counters[1]);
      solves             = static_cast<unsigned long long>(counters[2]);
    }
  } // namespace time_integration
} // namespace rubberdyn
