// What the mortar pair's unit tests (tests/contact/mortar_*.cc) do to a
// pair: evaluate its forces at a displacement and compare its tangent with
// central differences of them.
#ifndef rubberdyn_tests_contact_mortar_probe_h
#define rubberdyn_tests_contact_mortar_probe_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/model/force_contribution.h>
#include <rubberdyn/model/model.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace mortar_probe
{
  using namespace dealii;
  using namespace rubberdyn;

  /** A smooth pseudo-random vector field of amplitude 1 (mm). */
  inline Tensor<1, 3>
  wobble(const Point<3> &X, const double phase)
  {
    Tensor<1, 3> w;
    for (unsigned int d = 0; d < 3; ++d)
      w[d] = std::sin(1.7 * X[0] + 2.3 * X[1] + 3.1 * X[2] + phase + 1.9 * d) *
             std::cos(0.9 * X[0] - 1.3 * X[1] + 0.7 * d + 0.5 * phase);
    return w;
  }

  /** The owned entries of @p f on every rank, as one full vector. */
  inline Vector<double>
  gather(const VectorType &f, const MPI_Comm comm)
  {
    Vector<double> full(f.size());
    for (unsigned int i = 0; i < f.locally_owned_size(); ++i)
      full[f.get_partitioner()->local_to_global(i)] = f.local_element(i);
    Utilities::MPI::sum(full, comm, full);
    return full;
  }

  /** The tangent against the central difference of the forces. */
  struct TangentComparison
  {
    /** |K w - fd| / |fd| and |fd|, fd = -(f(u + h w) - f(u - h w)) / 2h. */
    double error = 0., norm = 0.;
    /** Whether every nonzero block entry lies within add_couplings(). */
    bool within_couplings = true;
  };

  /** What walk() saw along a path. */
  struct WorkAudit
  {
    /** The largest |energy_error()| and contact_energy() (J). */
    double largest_error = 0., largest_energy = 0.;
  };

  /**
   * Evaluates a pair on a model at rest (velocity zero, unit masses, no
   * rigid bodies, as an explicit run's pair sees them).
   */
  class Probe
  {
  public:
    explicit Probe(const model::Model &model)
      : comm(model.comm)
      , v(model.partitioner)
      , mass(model.partitioner)
      , f(model.partitioner)
    {
      mass = 1.;
      mass.update_ghost_values();
    }

    /** add_forces() at the displacement @p at and @p time, gathered. */
    Vector<double>
    forces(contact::MortarContactPair &pair,
           const VectorType           &at,
           const double                time)
    {
      const model::EvaluationPoint point{at, v, mass, bodies, time};
      model::ContributionResults   results;
      results.reset(2, 0);
      f = 0.;
      pair.add_forces(point, f, results);
      return gather(f, comm);
    }

    /**
     * add_tangents() at @p u times @p w against the central difference of
     * forces() with h = 1e-6 mm (truncation ~(h / 1e-2 mm)^2 = 1e-8,
     * round-off ~1e-12). Leaves the pair evaluated at @p u.
     */
    TangentComparison
    compare_tangent(contact::MortarContactPair &pair,
                    const VectorType           &u,
                    const VectorType           &w,
                    const double                time)
    {
      const double h = 1e-6;
      VectorType   plus(u), minus(u);
      plus.add(h, w);
      minus.add(-h, w);
      plus.update_ghost_values();
      minus.update_ghost_values();
      const Vector<double> f_plus  = forces(pair, plus, time);
      const Vector<double> f_minus = forces(pair, minus, time);
      forces(pair, u, time);

      // As the quasi-static solver does before each assembly.
      const model::EvaluationPoint point{u, v, mass, bodies, time};
      pair.update_couplings(point);
      std::set<std::pair<types::global_dof_index, types::global_dof_index>>
        announced;
      pair.add_couplings([&](const std::vector<types::global_dof_index> &dofs) {
        for (const auto i : dofs)
          for (const auto j : dofs)
            announced.emplace(i, j);
      });
      TangentComparison            result;
      Vector<double>               Kw(u.size());
      const Vector<double>         w_full = gather(w, comm);
      pair.add_tangents(point,
                        [&](const std::vector<types::global_dof_index> &dofs,
                            const std::vector<double>                  &K) {
                          const unsigned int n = dofs.size();
                          for (unsigned int i = 0; i < n; ++i)
                            for (unsigned int j = 0; j < n; ++j)
                              {
                                Kw[dofs[i]] += K[n * i + j] * w_full[dofs[j]];
                                if (K[n * i + j] != 0. &&
                                    announced.count({dofs[i], dofs[j]}) == 0)
                                  result.within_couplings = false;
                              }
                        });
      Utilities::MPI::sum(Kw, comm, Kw);
      result.within_couplings =
        !Utilities::MPI::logical_or(!result.within_couplings, comm);
      Vector<double> difference(u.size());
      for (unsigned int i = 0; i < u.size(); ++i)
        difference[i] = -(f_plus[i] - f_minus[i]) / (2. * h);
      result.norm = difference.l2_norm();
      difference -= Kw;
      result.error = difference.l2_norm() / result.norm;
      return result;
    }

    /**
     * Walk @p pair along a path of @p n_steps + 1 evaluations: at each
     * step @p place(step) sets the displacement @p u, the pair is
     * evaluated at time 1e-3 step ms and the evaluation accepted; the work
     * audit's largest error and the springs' largest energy, over the
     * ranks.
     */
    template <typename Place>
    WorkAudit
    walk(contact::MortarContactPair &pair,
         const VectorType           &u,
         const unsigned int          n_steps,
         const Place                &place)
    {
      WorkAudit audit;
      for (unsigned int step = 0; step <= n_steps; ++step)
        {
          place(step);
          forces(pair, u, 1e-3 * step);
          pair.accept_step();
          audit.largest_error =
            std::max(audit.largest_error,
                     std::abs(Utilities::MPI::sum(pair.energy_error(), comm)));
          audit.largest_energy =
            std::max(audit.largest_energy,
                     Utilities::MPI::sum(pair.contact_energy(), comm));
        }
      return audit;
    }

  private:
    MPI_Comm                      comm;
    VectorType                    v, mass, f;
    std::vector<model::RigidBody> bodies;
  };
} // namespace mortar_probe

#endif
