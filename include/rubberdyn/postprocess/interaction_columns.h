#ifndef rubberdyn_postprocess_interaction_columns_h
#define rubberdyn_postprocess_interaction_columns_h

#include <rubberdyn/postprocess/history_columns.h>
#include <rubberdyn/postprocess/postprocessor.h>

#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace model
  {
    class Model;
    class SurfaceLoads;
  } // namespace model
  namespace contact
  {
    class RigidSurfaceForces;
  } // namespace contact

  namespace postprocess
  {
    /**
     * The reaction columns of every boundary condition
     * (BoundaryReactionColumns: six per condition, force then moment) with,
     * in those of a pressure or traction condition, the load's resultant
     * force and moment on the body (model::SurfaceLoads::resultants(),
     * summed over the ranks at output times only).
     */
    class ReactionAndLoadColumns : public Postprocessor
    {
    public:
      /**
       * @param reactions The kinematic conditions' reaction columns.
       * @param loads The pressure and traction loads (nullptr: none).
       * @param condition_of_load The boundary condition of each load.
       */
      ReactionAndLoadColumns(
        std::unique_ptr<BoundaryReactionColumns> reactions,
        const model::SurfaceLoads               *loads,
        const std::vector<unsigned int>         &condition_of_load);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      void
      history_values(const SimulationView &view,
                     std::vector<double>  &values) override;

    private:
      std::unique_ptr<BoundaryReactionColumns> reactions;
      const model::SurfaceLoads               *loads;
      std::vector<unsigned int>                condition_of_load;
    };


    /**
     * The energy balance per interaction (LS-DYNA's SLEOUT and the
     * boundary work of GLSTAT): for every boundary condition `<bc>_work`
     * (J, the work it has done on the body: a kinematic condition's
     * reactions, a load's forces; the external work is their sum plus
     * gravity's and the driven rigid bodies'), and for every rigid surface
     * `<name>_contact_energy` (J, in its penalty springs) and
     * `<name>_friction_work` (J, dissipated by its friction). Summed over
     * the ranks at output times only.
     */
    class InteractionEnergyColumns : public Postprocessor
    {
    public:
      /**
       * @param condition_of_group The boundary condition of each
       *   constraint group of the solver's reactions.
       * @param loads The pressure and traction loads (nullptr: none).
       * @param condition_of_load The boundary condition of each load.
       * @param surfaces The rigid surfaces' contacts, in the model's order.
       */
      InteractionEnergyColumns(
        const model::Model                                     &model,
        const std::vector<unsigned int>                        &condition_of_group,
        const model::SurfaceLoads                              *loads,
        const std::vector<unsigned int>                        &condition_of_load,
        const std::vector<const contact::RigidSurfaceForces *> &surfaces);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      void
      history_values(const SimulationView &view,
                     std::vector<double>  &values) override;

    private:
      const model::Model                              &model;
      std::vector<unsigned int>                        condition_of_group;
      const model::SurfaceLoads                       *loads;
      std::vector<unsigned int>                        condition_of_load;
      std::vector<const contact::RigidSurfaceForces *> surfaces;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
