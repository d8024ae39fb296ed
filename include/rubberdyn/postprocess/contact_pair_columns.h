#ifndef rubberdyn_postprocess_contact_pair_columns_h
#define rubberdyn_postprocess_contact_pair_columns_h

#include <rubberdyn/postprocess/postprocessor.h>

#include <mpi.h>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace contact
  {
    class MortarContactPair;
  }

  namespace postprocess
  {
    /**
     * Per mortar contact pair (`Contact pairs/<pair>`), at the last
     * evaluation, on the slave side: `<pair>_normal_force` (kN, the sum of
     * the active slave nodes' p_a A_a), `<pair>_tangential_force` (kN, the
     * sum of their tangential tractions' magnitudes times A_a),
     * `<pair>_force_x/_y/_z` (kN, the force of the master side on the slave
     * side), `<pair>_max_pressure` and `<pair>_min_pressure` (GPa, over the
     * active slave nodes; 0 when none is active), `<pair>_contact_area`
     * (mm^2, their covered area), `<pair>_max_penetration` (mm),
     * `<pair>_active_nodes`, `<pair>_slipping_nodes`,
     * `<pair>_friction_work` (J), `<pair>_contact_energy` (J, the springs'
     * energy as the energy balance books it) and `<pair>_energy_error` (J,
     * the energy the pair created since the run's start:
     * MortarContactPair::energy_error()). Reduced over the ranks at output
     * times only.
     */
    class ContactPairColumns : public Postprocessor
    {
    public:
      /** @p pairs: the simulation's pairs (kept by pointer). */
      ContactPairColumns(
        const std::vector<const contact::MortarContactPair *> &pairs,
        const std::vector<std::string>                        &names,
        const MPI_Comm                                         comm);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      /** Collective: append_values(). */
      void
      history_values(const SimulationView &view,
                     std::vector<double>  &values) override;

      /**
       * Append the columns' values at the pairs' last evaluation to
       * @p values (for a run without a SimulationView: the quasi-static
       * one). Collective.
       */
      void
      append_values(std::vector<double> &values) const;

      /**
       * Per pair, for benchmarks: `<pair>_searches`, `<pair>_candidates`
       * (candidate facet pairs after the last search, all ranks) and the
       * largest over the ranks of `<pair>_search_seconds` and
       * `<pair>_evaluation_seconds` (wall time, all evaluations). Collective.
       */
      void
      summary(const SimulationView      &view,
              std::vector<SummaryEntry> &entries) override;

    private:
      std::vector<const contact::MortarContactPair *> pairs;
      std::vector<std::string>                        names;
      MPI_Comm                                        comm;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
