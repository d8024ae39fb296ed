#ifndef rubberdyn_simulation_simulation_setup_h
#define rubberdyn_simulation_simulation_setup_h

#include <deal.II/base/point.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/parameters/time_integration_parameters.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace time_integration
  {
    class KinematicConstraints;
  }
  namespace contact
  {
    class RigidSurfaceContact;
    class RigidSurfaceForces;
    class MortarContactPair;
  } // namespace contact

  namespace postprocess
  {
    class Postprocessor;
  } // namespace postprocess

  namespace model
  {
    class Model;
    class SurfaceLoads;
    class ForceContribution;
  } // namespace model

  namespace simulation
  {
    using namespace dealii;
    /* The model layer's names, used here unqualified. */
    using model::Model;
    using model::SurfaceLoads;

    /**
     * The set-up every solver of a Model shares (simulation::ExplicitSimulation,
     * simulation::QuasiStaticSimulation): its element groups, the element
     * settings and the kinematic constraints of its boundary conditions,
     * built the same way whatever integrates them.
     */
    namespace setup
    {
      /**
       * One element group per part, in the parts' order: its material ids
       * (none for a rigid part: no element forces), law and formulation,
       * and the part's final F-bar beta: its own `Parts/<name>/F-bar
       * stabilization` if it sets one, else the model-wide `Time
       * integration/F-bar stabilization` of @p time_integration (0 for
       * parts that are not F-bar). This is the one place the two are
       * merged. The advice a group's F-bar hull collapse ends with names
       * the part's own entry if it sets one; else, in a model of several
       * deformable F-bar parts, that one and the model-wide one, so that
       * the message tells the part; else the model-wide one.
       */
      std::vector<elements::ElementGroup>
      element_groups(const Model                       &model,
                     const parameters::TimeIntegration &time_integration);

      /** Bulk viscosity settings from `Time integration`. */
      elements::ElementSettings
      element_settings(const parameters::TimeIntegration &time_integration);

      /**
       * One constraint group per constrained component of every fixed,
       * displacement, velocity and symmetry condition (pressures and
       * tractions are loads, not constraints), named
       * `Boundary conditions/<name>`. Appends to @p condition_of_group and
       * @p direction_of_group the condition and the direction of each
       * group.
       *
       * @throws InputError as KinematicConstraints::prescribe() does.
       */
      void
      add_kinematic_constraints(
        const Model                            &model,
        time_integration::KinematicConstraints &constraints,
        std::vector<unsigned int>              &condition_of_group,
        std::vector<unsigned int>              &direction_of_group);

      /**
       * Let the model's pretension sections cut @p hexes (one element
       * group per part, in the parts' order: element_groups()). Returns the
       * number of elements each cuts (all ranks). Collective.
       *
       * @throws InputError naming `Pretension sections/<name>/Point` for a
       *   section that cuts no element, or `Pretension sections/Names` for
       *   an element cut by two.
       */
      std::vector<unsigned int>
      cut_pretension_sections(const Model                &model,
                              elements::SolidHexElements &hexes);

      /**
       * Check that each of the model's cross sections cuts an element of
       * its part in @p hexes. Collective.
       *
       * @throws InputError naming `Cross sections/<name>/Point` for one that
       *   cuts none.
       */
      void
      check_cross_sections(const Model                      &model,
                           const elements::SolidHexElements &hexes);

      /**
       * One SurfaceLoads contribution for all the pressure and traction
       * conditions of the model, or nullptr if there is none. Appends to
       * @p condition_of_load the condition of each of its loads.
       *
       * @throws InputError as the SurfaceLoads constructor does.
       */
      std::unique_ptr<SurfaceLoads>
      surface_loads(const Model               &model,
                    std::vector<unsigned int> &condition_of_load);

      /**
       * One contact per rigid surface of the model (its boundary ids,
       * penalty scale and the bulk moduli of the parts that touch it),
       * appended to @p contacts, and its force contribution carried by the
       * body @p body_of_surface[s] (which body that is, is the scheme's
       * choice), appended to @p forces and, in the surfaces' order, to
       * @p contributions.
       */
      void
      add_rigid_surfaces(
        const Model                                             &model,
        const std::vector<unsigned int>                         &body_of_surface,
        std::vector<std::unique_ptr<contact::RigidSurfaceContact>> &contacts,
        std::vector<std::unique_ptr<contact::RigidSurfaceForces>>  &forces,
        std::vector<model::ForceContribution *> &contributions);

      /**
       * Mortar contact between the mesh's surfaces: one
       * contact::MortarContactPair per `Contact pairs` entry of the model,
       * in its order, appended to @p pairs and to @p contributions.
       */
      void
      add_contact_pairs(
        const Model                                             &model,
        std::vector<std::unique_ptr<contact::MortarContactPair>> &pairs,
        std::vector<model::ForceContribution *> &contributions);

      /**
       * The history columns and run_summary.json entries of the mortar
       * @p pairs (postprocess::ContactPairColumns), each named as the
       * model's `Contact pairs` entry it came from; nullptr without pairs.
       * Both schemes write them through it.
       */
      std::unique_ptr<postprocess::Postprocessor>
      contact_pair_columns(
        const Model                                                    &model,
        const std::vector<std::unique_ptr<contact::MortarContactPair>> &pairs);

      /**
       * The model's initial penetrations (Model::initial_penetrations,
       * contact::resolve_initial_penetrations()) into @p log, one line per
       * contact pair or rigid surface that has any, once per model (the
       * hand-off's preload logs them, its explicit run not again); a
       * `report` as a WARNING. Rank 0 writes.
       */
      void
      log_initial_penetrations(Model &model, std::ostream &log);

      /**
       * The model's initial penetrations as a JSON array for
       * run_summary.json: per interaction that has any its name
       * ("Contact pairs/<name>", "Rigid surfaces/<name>"), the number of
       * penetrating nodes, the largest penetration (mm) and where (mm),
       * the action and the nodes moved and the largest move (mm). "[]"
       * without any.
       */
      std::string
      initial_penetrations_json(const Model &model);

      /**
       * The row-summed (lumped) mass rho N_a of each part's cells, one
       * vector per part (kg, compressed: owned entries valid). Their sum is
       * the explicit engine's nodal mass without mass scaling.
       */
      std::vector<VectorType>
      part_masses(const Model &model);

      /**
       * The centre of mass of the rigid part @p p as the explicit engine
       * moves it: the centre of the nodal mass its nodes carry (the sum of
       * @p masses, part_masses(): its cells' own and what deformable
       * neighbours add to shared nodes), so that gravity has no moment
       * about it and its rotations are about it in both schemes (mm).
       * Collective.
       */
      Point<3>
      rigid_part_centre_of_mass(const Model                   &model,
                                const unsigned int             p,
                                const std::vector<VectorType> &masses);
    } // namespace setup
  }   // namespace simulation
} // namespace rubberdyn

#endif
