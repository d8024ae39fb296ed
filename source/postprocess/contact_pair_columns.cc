#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/postprocess/contact_pair_columns.h>

#include <iomanip>
#include <sstream>

namespace rubberdyn
{
  namespace postprocess
  {
    ContactPairColumns::ContactPairColumns(
      const std::vector<const contact::MortarContactPair *> &pairs,
      const std::vector<std::string>                        &names,
      const MPI_Comm                                         comm)
      : pairs(pairs)
      , names(names)
      , comm(comm)
    {}



    std::string
    ContactPairColumns::name() const
    {
      return "contact pairs";
    }



    std::vector<std::string>
    ContactPairColumns::history_columns() const
    {
      std::vector<std::string> columns;
      for (const std::string &pair : names)
        for (const char *column : {"_normal_force",
                                   "_tangential_force",
                                   "_force_x",
                                   "_force_y",
                                   "_force_z",
                                   "_max_pressure",
                                   "_min_pressure",
                                   "_contact_area",
                                   "_max_penetration",
                                   "_active_nodes",
                                   "_slipping_nodes",
                                   "_friction_work",
                                   "_contact_energy",
                                   "_energy_error"})
          columns.push_back(pair + column);
      return columns;
    }



    void
    ContactPairColumns::history_values(const SimulationView &view,
                                       std::vector<double>  &values)
    {
      (void)view;
      append_values(values);
    }



    void
    ContactPairColumns::append_values(std::vector<double> &values) const
    {
      using dealii::ArrayView;
      namespace MPI = dealii::Utilities::MPI;
      // Sums, maxima and minima of all pairs in one reduction each.
      std::vector<double> sums, maxima, minima;
      for (const contact::MortarContactPair *pair : pairs)
        {
          const contact::ContactPairStatistics &s = pair->last_statistics();
          sums.insert(sums.end(),
                      {s.normal_force,
                       s.tangential_force,
                       s.force[0],
                       s.force[1],
                       s.force[2],
                       s.contact_area,
                       double(s.active_nodes),
                       double(s.slipping_nodes),
                       pair->friction_work(),
                       pair->contact_energy(),
                       pair->energy_error()});
          maxima.insert(maxima.end(), {s.max_pressure, s.max_penetration});
          minima.push_back(s.min_pressure);
        }
      MPI::sum(ArrayView<const double>(sums), comm, ArrayView<double>(sums));
      MPI::max(ArrayView<const double>(maxima),
               comm,
               ArrayView<double>(maxima));
      MPI::min(ArrayView<const double>(minima),
               comm,
               ArrayView<double>(minima));
      for (unsigned int p = 0; p < pairs.size(); ++p)
        {
          const double *sum    = &sums[11 * p];
          const bool    active = sum[6] > 0.;
          values.insert(values.end(),
                        {sum[0],
                         sum[1],
                         sum[2],
                         sum[3],
                         sum[4],
                         active ? maxima[2 * p] : 0.,
                         active ? minima[p] : 0.,
                         sum[5],
                         maxima[2 * p + 1],
                         sum[6],
                         sum[7],
                         sum[8],
                         sum[9],
                         sum[10]});
        }
    }



    void
    ContactPairColumns::summary(const SimulationView      &view,
                                std::vector<SummaryEntry> &entries)
    {
      (void)view;
      namespace MPI     = dealii::Utilities::MPI;
      const auto number = [](const double value) {
        std::ostringstream text;
        text << std::setprecision(9) << value;
        return text.str();
      };
      for (unsigned int p = 0; p < pairs.size(); ++p)
        {
          const contact::ContactPairTimings &t = pairs[p]->timings();
          entries.emplace_back(names[p] + "_searches",
                               number(MPI::max(t.searches, comm)));
          entries.emplace_back(names[p] + "_candidates",
                               number(double(MPI::sum(t.candidates, comm))));
          entries.emplace_back(names[p] + "_search_seconds",
                               number(MPI::max(t.search_seconds, comm)));
          entries.emplace_back(names[p] + "_evaluation_seconds",
                               number(MPI::max(t.evaluation_seconds, comm)));
          // Each rank's (the balance of the pair's work), and of it the
          // time spent waiting for the other ranks (positions, force sums).
          const auto by_rank = [&](const double seconds) {
            std::string list = "[";
            for (const double value : MPI::all_gather(comm, seconds))
              list += (list.size() > 1 ? ", " : "") + number(value);
            return list + "]";
          };
          entries.emplace_back(names[p] + "_evaluation_seconds_by_rank",
                               by_rank(t.evaluation_seconds));
          entries.emplace_back(names[p] + "_waiting_seconds_by_rank",
                               by_rank(t.waiting_seconds));
        }
    }
  } // namespace postprocess
} // namespace rubberdyn
