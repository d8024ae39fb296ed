#ifndef rubberdyn_studies_drop_test_h
#define rubberdyn_studies_drop_test_h

#include <rubberdyn/studies/study.h>

#include <memory>
#include <string>

namespace rubberdyn
{
  namespace model
  {
    class Model;
  }

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
     * `impactor_force`, compression positive, then
     * `rubber_top_displacement` and `rubber_bottom_displacement`: minus the
     * area-weighted mean z displacement of the rubber's top and bottom
     * faces, i.e. downwards positive, so that the rubber's own height is
     * H - top + bottom without the penetration of the penalty contacts), a
     * ParaView series `solution.pvd` and `run_summary.json` (run statistics,
     * face areas of the faceted mesh, largest compressions, separation time
     * and rebound velocity, smallest Jacobian at the field outputs) in the
     * output directory. `Drop test/Stop after rebound` ends the run shortly
     * after the impactor has left the rubber.
     */
    class DropTest : public Study
    {
    public:
      /** Read and check the parameters. */
      explicit DropTest(dealii::ParameterHandler &prm);

      /** Declare `Drop test/...`, `Time integration/Element formulation`
       * and `Materials/Rubber/...` (the shared groups are declared by the
       * registry). */
      static void
      declare_parameters(dealii::ParameterHandler &   prm,
                         const registry::ListedNames &names);

      ~DropTest() override;

      void
      run(std::ostream &log) override;

      /** Build the model and report it and its stable step, without running. */
      void
      check(std::ostream &log) override;

    private:
      /** The drop test as a Model: mesh, the rubber part, the two plates. */
      void
      build_model(model::Model &model);

      struct Parameters;
      std::unique_ptr<Parameters> parameters;
    };
  } // namespace studies
} // namespace rubberdyn

#endif
