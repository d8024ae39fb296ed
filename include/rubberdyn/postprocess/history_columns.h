#ifndef rubberdyn_postprocess_history_columns_h
#define rubberdyn_postprocess_history_columns_h

#include <rubberdyn/postprocess/postprocessor.h>

#include <string>
#include <vector>

namespace rubberdyn
{
  namespace postprocess
  {
    /**
     * The energy columns of time_history.csv (J): kinetic_energy,
     * internal_energy, external_work, contact_work, bulk_viscosity_work,
     * then added_mass (kg) and energy_error (-, relative to the largest
     * energy so far), optionally friction_work (J), and
     * energy_error_deformable (-, relative to the largest energy that has
     * flowed through the deformable parts so far; see
     * time_integration::EnergyBalance::deformable_relative_error()).
     */
    class EnergyColumns : public Postprocessor
    {
    public:
      explicit EnergyColumns(const bool with_friction_work);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      void
      history_values(const SimulationView &view,
                     std::vector<double> &  values) override;

    private:
      bool with_friction_work;
    };


    /**
     * The stored energy of the elements, for a scheme without the explicit
     * run's energy balance (a quasi-static load path): `internal_energy`
     * (J, summed over the ranks) and per part `<part>_internal_energy` (J):
     * the columns of the same names of EnergyColumns and PartColumns.
     */
    class InternalEnergyColumns : public Postprocessor
    {
    public:
      /** The model's part names, in its order (one element group each). */
      explicit InternalEnergyColumns(
        const std::vector<std::string> &part_names);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      /**
       * A part without an element group of its own (a rigid part: only
       * mass) has 0.
       */
      void
      history_values(const SimulationView &view,
                     std::vector<double>  &values) override;

    private:
      std::vector<std::string> part_names;
    };


    /**
     * The reaction of every boundary condition on the body (LS-DYNA's
     * BNDOUT): `<bc>_force_x/_y/_z` (kN) and `<bc>_moment_x/_y/_z` (kN mm
     * about the condition's moment point, with the nodes' current
     * positions).
     */
    class BoundaryReactionColumns : public Postprocessor
    {
    public:
      /**
       * @param names Name of each boundary condition.
       * @param condition_of_group For each constraint group of the solver,
       *   the index of its condition.
       * @param direction_of_group For each group, its direction (0, 1, 2).
       */
      BoundaryReactionColumns(
        const std::vector<std::string> & names,
        const std::vector<unsigned int> &condition_of_group,
        const std::vector<unsigned int> &direction_of_group);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      void
      history_values(const SimulationView &view,
                     std::vector<double> &  values) override;

    private:
      std::vector<std::string>  names;
      std::vector<unsigned int> condition_of_group, direction_of_group;
    };


    /**
     * Per part (LS-DYNA's MATSUM): `<part>_kinetic_energy`,
     * `<part>_internal_energy`, `<part>_bulk_viscosity_work` (dissipated by
     * its bulk viscosity), `<part>_gravity_work` (done by gravity on its
     * nodes) (J) and `<part>_momentum_x/_y/_z` (kg mm/ms). With
     * RigidBodyColumns' energies and the interactions' works they add up to
     * the model's energy columns (doc/model.md, "Energy balance").
     */
    class PartColumns : public Postprocessor
    {
    public:
      std::string
      name() const override;

      /** Needs the model's part names: set by the constructor. */
      explicit PartColumns(const std::vector<std::string> &part_names);

      std::vector<std::string>
      history_columns() const override;

      void
      history_values(const SimulationView &view,
                     std::vector<double> &  values) override;

    private:
      std::vector<std::string> part_names;
    };


    /**
     * Per pretension section (model::PretensionSection; in the explicit run
     * of `quasi-static then explicit`, locked at its preload):
     * `<name>_force` (kN, the axial force through it, tension positive:
     * elements::SolidHexElements::section_forces() at the current
     * displacement, without bulk viscosity) and `<name>_shortening` (mm,
     * held), the columns of the quasi-static run.
     */
    class PretensionSectionColumns : public Postprocessor
    {
    public:
      std::string
      name() const override;

      /** The sections' names, in the elements' order of sections. */
      explicit PretensionSectionColumns(
        const std::vector<std::string> &section_names);

      std::vector<std::string>
      history_columns() const override;

      /** Collective: the forces are summed over the ranks. */
      void
      history_values(const SimulationView &view,
                     std::vector<double> &  values) override;

    private:
      std::vector<std::string> section_names;
    };


    /**
     * Per cross section (model::CrossSection, `Cross sections/<name>`;
     * LS-DYNA's *DATABASE_CROSS_SECTION): the resultant of the part's
     * stresses on the plane, from the internal forces of the part's
     * elements that the plane cuts at their nodes on the normal's side
     * (elements::SolidHexElements::section_resultants(); without bulk
     * viscosity):
     * `<name>_force_x/_y/_z` (kN, the traction sigma n integrated over the
     * plane), `<name>_moment_x/_y/_z` (kN mm, about the current centre c
     * of the cut elements: @f$\sum_a (x_a - c) \times f_a@f$),
     * `<name>_centre_x/_y/_z` (mm, that centre c, the mean of the cut
     * elements' current centres),
     * `<name>_axial_force` (kN, along the normal n of the reference
     * configuration, tension positive), `<name>_shear_force` (kN, the
     * magnitude across n), `<name>_torque` (kN mm, about n) and
     * `<name>_bending_moment` (kN mm, the magnitude across n). In static
     * equilibrium these are exactly the resultant and moment of the
     * external forces on the normal's side (the internal forces of the
     * uncut elements cancel), the check of tests/model/cross_section.
     */
    class CrossSectionColumns : public Postprocessor
    {
    public:
      /** The sections' names, in the order of model::Model::cross_sections. */
      explicit CrossSectionColumns(
        const std::vector<std::string> &section_names);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      /** Collective: the sums are taken over the ranks. */
      void
      history_values(const SimulationView &view,
                     std::vector<double> &  values) override;

    private:
      std::vector<std::string> section_names;
    };


    /**
     * Per rigid body (of a rigid surface, or a rigid part):
     * `<name>_position_x/_y/_z` (mm, of its reference point: a rigid part's
     * centre of mass), `<name>_velocity_x/_y/_z` (mm/ms) and
     * `<name>_force_x/_y/_z` (kN, the force of the rest of the model on it:
     * contact and, for a rigid part, its bonded deformable neighbours;
     * not its weight). A rotating body (rigid part) also gets
     * `<name>_rotation_x/_y/_z` (its rotation vector, rad),
     * `<name>_angular_velocity_x/_y/_z` (rad/ms) and
     * `<name>_moment_x/_y/_z` (kN mm, of that force about its centre).
     * A rigid surface's body (not a part) also gets `<name>_kinetic_energy`
     * and `<name>_gravity_work` (J; a rigid part's are in its
     * PartColumns), and a body held or driven in some direction
     * `<name>_drive_work` (J, the work done on the solid through it:
     * time_integration::BodyEnergy).
     */
    class RigidBodyColumns : public Postprocessor
    {
    public:
      std::string
      name() const override;

      /**
       * @param bodies The solver's bodies, set up (a rigid part's body
       *   carries nodes: it gets the rotation columns and no energy
       *   columns of its own).
       */
      explicit RigidBodyColumns(const std::vector<model::RigidBody> &bodies);

      std::vector<std::string>
      history_columns() const override;

      void
      history_values(const SimulationView &view,
                     std::vector<double> &  values) override;

    private:
      /** What each body gets. */
      struct BodyColumns
      {
        std::string name;
        bool        rotating;
        bool        driven;
      };
      std::vector<BodyColumns> bodies;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
