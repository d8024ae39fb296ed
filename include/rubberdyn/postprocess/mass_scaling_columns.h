#ifndef rubberdyn_postprocess_mass_scaling_columns_h
#define rubberdyn_postprocess_mass_scaling_columns_h

#include <rubberdyn/postprocess/postprocessor.h>
#include <rubberdyn/time_integration/selective_mass_scaling.h>

#include <string>
#include <vector>

namespace rubberdyn
{
  namespace postprocess
  {
    /**
     * Selective mass scaling's figures: the history column
     * `mass_scaling_iterations` (the accelerations' solve at the row's
     * step), in run_summary.json `selective_mass_scaling` (per part its
     * target step, scaled elements and added mass; the solves'
     * iterations: mean and largest) and a line at the end of the log.
     */
    class MassScalingColumns : public Postprocessor
    {
    public:
      /**
       * @param scaling The solver's selective mass scaling (kept by
       *   reference).
       * @param part_names The parts' names, in the model's order.
       * @param parts What the scaling did to each part.
       */
      MassScalingColumns(const time_integration::SelectiveMassScaling &scaling,
                         std::vector<std::string>                      part_names,
                         std::vector<time_integration::PartMassScaling> parts);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      void
      history_values(const SimulationView &view,
                     std::vector<double>  &values) override;

      void
      summary(const SimulationView      &view,
              std::vector<SummaryEntry> &entries) override;

      void
      final_log(std::ostream &log) const override;

    private:
      const time_integration::SelectiveMassScaling  &scaling;
      std::vector<std::string>                       part_names;
      std::vector<time_integration::PartMassScaling> parts;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
