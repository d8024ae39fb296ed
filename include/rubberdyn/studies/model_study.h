#ifndef rubberdyn_studies_model_study_h
#define rubberdyn_studies_model_study_h

#include <rubberdyn/studies/study.h>

#include <memory>

namespace rubberdyn
{
  namespace model
  {
    class Model;
  } // namespace model

  namespace simulation
  {
    class ExplicitSimulation;
    class QuasiStaticSimulation;
    class PreloadedSimulation;
  } // namespace simulation

  namespace studies
  {
    /**
     * The "Model" study: any multi-part solid model from a Gmsh mesh,
     * described in the parameter file. The mesh's physical volume tags are
     * material ids, its physical surface tags boundary ids; `Parts` give
     * each set of material ids a law, an element formulation and an initial
     * velocity; `Boundary conditions` prescribe motion on boundary ids (with
     * functions of x, y, z, t); `Rigid surfaces` are planes and cylinders
     * carried by rigid bodies; `Model/Gravity` acts on everything. The
     * model is built (and every input checked) in the constructor, before
     * anything is written; run() hands it to simulation::ExplicitSimulation, or
     * with `Time integration/Scheme = quasi-static` to
     * simulation::QuasiStaticSimulation.
     *
     * Outputs: time_history.csv with time, time_step, the energies, per
     * boundary condition its reaction force and moment, per part its
     * kinetic and internal energy and momentum, per rigid surface its
     * position, velocity and force; the ParaView series; run_summary.json.
     * doc/model.md documents every entry.
     */
    class ModelStudy : public Study
    {
    public:
      /**
       * Read the parameters, read the mesh (relative to the folder of
       * @p parameter_file) and build the model.
       */
      ModelStudy(dealii::ParameterHandler &prm,
                 const std::string &       parameter_file);

      /**
       * Declare `Model/...`, `Mesh/...` and a subsection of `Parts`,
       * `Boundary conditions` and `Rigid surfaces` per listed name (and one
       * named `<name>` that documents them).
       */
      static void
      declare_parameters(dealii::ParameterHandler &   prm,
                         const registry::ListedNames &names);

      ~ModelStudy() override;

      void
      run(std::ostream &log) override;

      void
      check(std::ostream &log) override;

    private:
      std::unique_ptr<model::Model>              model;
      /** The engine: one of the three, by `Time integration/Scheme`. */
      std::unique_ptr<simulation::ExplicitSimulation>    simulation;
      std::unique_ptr<simulation::QuasiStaticSimulation> quasi_static;
      std::unique_ptr<simulation::PreloadedSimulation>   preloaded;
    };
  } // namespace studies
} // namespace rubberdyn

#endif
