#include <deal.II/lac/lapack_templates.h>

#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/time_integration/assembled_step_estimate.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rubberdyn
{
  namespace time_integration
  {
    AssembledStepEstimate::AssembledStepEstimate(
      const AssembledStepSettings                              &settings,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const VectorType                                         &inverse_mass,
      const std::vector<bool>                                  &free_dof,
      const std::vector<double>                                &start,
      const MPI_Comm                                            comm)
      : settings(settings)
      , partitioner(partitioner)
      , comm(comm)
      , start_vector(start)
    {
      const unsigned int n_owned = partitioner->locally_owned_size();
      scale.assign(n_owned, 0.);
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double inverse = inverse_mass.local_element(i);
          if (free_dof[i] && inverse > 0. && std::isfinite(inverse))
            scale[i] = std::sqrt(inverse);
        }
      // Everything an estimate needs, once: no allocation in refresh().
      const unsigned int k = settings.max_iterations;
      basis.resize(k + 1);
      for (VectorType &q : basis)
        q.reinit(partitioner);
      direction.reinit(partitioner);
      product_vector.reinit(partitioner);
      warm.reinit(partitioner);
      alpha.assign(k, 0.);
      beta.assign(k, 0.);
      d.assign(k, 0.);
      e.assign(k, 0.);
      z.assign(k * k, 0.);
      work.assign(std::max(1u, 2 * k), 0.);
    }



    bool
    AssembledStepEstimate::due(const unsigned int step) const
    {
      return !refreshed || step >= last_refresh + settings.refresh_interval;
    }



    double
    AssembledStepEstimate::dot(const VectorType &a, const VectorType &b) const
    {
      const unsigned int n_owned = partitioner->locally_owned_size();
      double             local   = 0.;
      for (unsigned int i = 0; i < n_owned; ++i)
        local += a.local_element(i) * b.local_element(i);
      return Utilities::MPI::sum(local, comm);
    }



    void
    AssembledStepEstimate::refresh(const unsigned int      step,
                                   const StiffnessProduct &product)
    {
      const auto         start   = std::chrono::steady_clock::now();
      const unsigned int n_owned = partitioner->locally_owned_size();
      const unsigned int k_max   = settings.max_iterations;
      last_refresh               = step;
      refreshed                  = true;
      ++stats.refreshes;
      estimate                = 0.;
      reference_undamped_step = 0.;

      // q_0: the last Ritz vector (warm start), else the start vector; on
      // the free dofs only, normalised.
      VectorType &q0 = basis[0];
      if (has_warm)
        q0 = warm;
      else
        for (unsigned int i = 0; i < n_owned; ++i)
          q0.local_element(i) = start_vector[i];
      for (unsigned int i = 0; i < n_owned; ++i)
        if (scale[i] == 0.)
          q0.local_element(i) = 0.;
      const double norm0 = std::sqrt(dot(q0, q0));
      if (!(norm0 > 0.))
        return; // nothing moves freely
      q0 /= norm0;

      double              theta = 0., residual = 0.;
      unsigned int        n         = 0; // size of the tridiagonal matrix
      bool                converged = false, failed = false;
      std::vector<double> dots_local(k_max + 1), dots(k_max + 1);
      for (unsigned int j = 0; j < k_max; ++j)
        {
          // w = B q_j = M^{-1/2} K M^{-1/2} q_j.
          for (unsigned int i = 0; i < n_owned; ++i)
            direction.local_element(i) = scale[i] * basis[j].local_element(i);
          ++stats.products;
          if (!product(direction, product_vector))
            {
              failed = true;
              break;
            }
          VectorType &w = basis[j + 1];
          for (unsigned int i = 0; i < n_owned; ++i)
            w.local_element(i) = scale[i] * product_vector.local_element(i);
          // Full reorthogonalisation, twice (classical Gram-Schmidt; one
          // collective each): alpha_j is the first pass's coefficient of
          // q_j.
          for (unsigned int pass = 0; pass < 2; ++pass)
            {
              for (unsigned int m = 0; m <= j; ++m)
                {
                  double local = 0.;
                  for (unsigned int i = 0; i < n_owned; ++i)
                    local += w.local_element(i) * basis[m].local_element(i);
                  dots_local[m] = local;
                }
              Utilities::MPI::sum(ArrayView<const double>(dots_local.data(),
                                                          j + 1),
                                  comm,
                                  ArrayView<double>(dots.data(), j + 1));
              if (pass == 0)
                alpha[j] = dots[j];
              else
                alpha[j] += dots[j];
              for (unsigned int m = 0; m <= j; ++m)
                w.add(-dots[m], basis[m]);
            }
          beta[j] = std::sqrt(dot(w, w));
          n       = j + 1;

          // The largest eigenpair of the tridiagonal T_n (LAPACK dstev):
          // eigenvalues ascending, eigenvectors in the columns of z.
          std::copy(alpha.begin(), alpha.begin() + n, d.begin());
          std::copy(beta.begin(), beta.begin() + n, e.begin());
          const char            jobz   = 'V';
          const types::blas_int n_blas = n, ldz = n;
          types::blas_int       info = 0;
          stev(&jobz,
               &n_blas,
               d.data(),
               e.data(),
               z.data(),
               &ldz,
               work.data(),
               &info);
          if (info != 0)
            {
              failed = true;
              break;
            }
          theta    = d[n - 1];
          residual = beta[j] * std::abs(z[(n - 1) * n + (n - 1)]);
          if (n >= 2 && residual <= settings.tolerance * theta)
            {
              converged = true;
              break;
            }
          // An invariant subspace: theta is an eigenvalue (of the part of
          // the space the start vector reaches).
          if (!(beta[j] > 1e-12 * std::abs(theta)))
            {
              converged = n >= 2;
              break;
            }
          w /= beta[j];
        }

      if (!failed && n > 0)
        {
          // The Ritz vector of theta: the next estimate's start.
          warm = 0.;
          for (unsigned int m = 0; m < n; ++m)
            warm.add(z[(n - 1) * n + m], basis[m]);
          has_warm = true;
        }
      if (converged && theta > 0.)
        {
          // theta + r, rounded up to 2^-11 relative: the same step on any
          // partition unless round-off crosses a rounding boundary.
          int          exponent = 0;
          const double mantissa = std::frexp(theta + residual, &exponent);
          estimate = std::ldexp(std::ceil(mantissa * 2048.) / 2048., exponent);
        }
      else
        ++stats.unconverged;
      stats.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }



    double
    AssembledStepEstimate::element_time_step(const double element_step,
                                             const double undamped_step,
                                             const double damping_factor)
    {
      if (!(estimate > 0.) || !(undamped_step > 0.) ||
          undamped_step == std::numeric_limits<double>::max())
        return element_step;
      if (reference_undamped_step == 0.)
        reference_undamped_step = undamped_step;
      // The element bound's omega now is an upper bound (section 8.3);
      // the estimate follows its growth since the estimate was made.
      const double element_omega = 2. / undamped_step;
      const double omega =
        std::min(element_omega,
                 std::sqrt(estimate) *
                   std::max(1., reference_undamped_step / undamped_step));
      const double step  = std::max(element_step, damping_factor * 2. / omega);
      const double gain  = step / element_step;
      stats.last_gain    = gain;
      stats.largest_gain = std::max(stats.largest_gain, gain);
      stats.smallest_gain =
        stats.smallest_gain == 0. ? gain : std::min(stats.smallest_gain, gain);
      return step;
    }



    void
    AssembledStepEstimate::save(std::ostream &out) const
    {
      const double scalars[6] = {estimate,
                                 reference_undamped_step,
                                 double(last_refresh),
                                 refreshed ? 1. : 0.,
                                 has_warm ? 1. : 0.,
                                 0.};
      binary_io::write_doubles(out, scalars, 6);
      binary_io::write_doubles(out,
                               warm.begin(),
                               partitioner->locally_owned_size());
    }



    void
    AssembledStepEstimate::load(std::istream &in)
    {
      double scalars[6];
      binary_io::read_doubles(in, scalars, 6, "stable step estimate");
      estimate                = scalars[0];
      reference_undamped_step = scalars[1];
      last_refresh            = static_cast<unsigned int>(scalars[2]);
      refreshed               = scalars[3] != 0.;
      has_warm                = scalars[4] != 0.;
      binary_io::read_doubles(in,
                              warm.begin(),
                              partitioner->locally_owned_size(),
                              "stable step estimate vector");
    }
  } // namespace time_integration
} // namespace rubberdyn
