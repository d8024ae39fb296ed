#ifndef rubberdyn_postprocess_load_path_body_columns_h
#define rubberdyn_postprocess_load_path_body_columns_h

#include <rubberdyn/postprocess/postprocessor.h>

#include <string>
#include <vector>

namespace rubberdyn
{
  namespace contact
  {
    class RigidSurfaceForces;
  }

  namespace postprocess
  {
    /**
     * The rigid surfaces and rigid parts of a quasi-static load path, where
     * bodies have no velocity or energy of their own (their columns of
     * RigidBodyColumns that a load path can fill, with the same names and
     * meanings):
     * per rigid surface `<surface>_position_x/_y/_z` (mm, its point where
     * its body is) and `<surface>_force_x/_y/_z` (kN, the force of the
     * solid on it); per rigid part `<part>_force_x/_y/_z` (kN, the force of
     * the solid on it through its nodes, minus the reaction of its held
     * nodes, and through the surfaces it carries); per rigid part in
     * equilibrium `<part>_position_x/_y/_z` (mm, its centre of mass) and
     * `<part>_rotation_x/_y/_z` (its rotation vector, rad). One sum over
     * the ranks per row.
     */
    class LoadPathBodyColumns : public Postprocessor
    {
    public:
      /** A constraint group that holds a rigid part in one direction. */
      struct HeldPartGroup
      {
        unsigned int part, direction, group;
      };

      /**
       * @param model The model (names of its surfaces and parts).
       * @param surface_body The body (of SimulationView::bodies()) of each
       *   rigid surface.
       * @param surfaces The rigid surfaces' contacts, in the model's order.
       * @param held_groups The constraint groups of the held rigid parts.
       * @param equilibrium_parts The rigid parts in equilibrium, in the
       *   order of @p poses.
       * @param poses Their poses at the last converged state (the solver's
       *   time_integration::QuasiStaticSolver::rigid_part_poses(): must
       *   outlive this plugin).
       */
      LoadPathBodyColumns(
        const model::Model                                     &model,
        const std::vector<unsigned int>                        &surface_body,
        const std::vector<const contact::RigidSurfaceForces *> &surfaces,
        const std::vector<HeldPartGroup>                       &held_groups,
        const std::vector<unsigned int>     &equilibrium_parts,
        const std::vector<model::RigidBody> &poses);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      /** Collective: the surfaces' forces are summed over the ranks. */
      void
      history_values(const SimulationView &view,
                     std::vector<double>  &values) override;

    private:
      std::vector<std::string>                         columns;
      std::vector<unsigned int>                        surface_body;
      std::vector<const contact::RigidSurfaceForces *> surfaces;
      std::vector<HeldPartGroup>                       held_groups;
      const std::vector<model::RigidBody>             &poses;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
