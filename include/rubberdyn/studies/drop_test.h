#ifndef rubberdyn_studies_drop_test_h
#define rubberdyn_studies_drop_test_h

#include <rubberdyn/studies/study.h>

#include <memory>
#include <string>

namespace rubberdyn
{
  namespace studies
  {
    /**
     * The "Drop test" study: chapter 4 of the reference study. A rubber
     * cylinder stands on a fixed rigid plate; a rigid impactor of mass M,
     * free only vertically, hits its top face at V0; gravity acts on the
     * impactor and the rubber. Explicit dynamics with F-bar hexahedra,
     * frictionless penalty contact with both plates.
     *
     * Writes `time_history.csv` (energies, `impactor_displacement` and
     * `impactor_force`, compression positive), a ParaView series
     * `solution.pvd` and `run_summary.json` in the output directory.
     */
    class DropTest : public Study
    {
    public:
      /** Read and check the parameters. */
      explicit DropTest(dealii::ParameterHandler &prm);

      /** Declare `Drop test/...`, `Time integration/...`, `Contact/...`,
       * the output intervals and `Materials/Rubber/...`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      ~DropTest() override;

      void
      run(std::ostream &log) override;

    private:
      struct Parameters;
      std::unique_ptr<Parameters> parameters;
    };
  } // namespace studies
} // namespace rubberdyn

#endif
