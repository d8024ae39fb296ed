#ifndef rubberdyn_model_model_h
#define rubberdyn_model_model_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>

#include <rubberdyn/materials/material_model.h>
#include <rubberdyn/model/element_formulation.h>
#include <rubberdyn/model/rigid_body.h>
#include <rubberdyn/model/rigid_surface.h>
#include <rubberdyn/parameters/contact_parameters.h>

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rubberdyn
{
  /**
   * The model: what a study builds and every solver uses. A mesh with
   * material and boundary ids, the parts (a law and an element formulation
   * per set of material ids), the boundary conditions, the rigid surfaces
   * with their bodies and the gravity. Studies only build a Model (from a
   * Gmsh file and a .prm, or from a generator such as the drop test's);
   * simulation::ExplicitSimulation runs any Model.
   */
  namespace model
  {
    using namespace dealii;

    /** A part: the cells of some material ids, one law, one formulation. */
    struct Part
    {
      /** Name (the columns `<name>_kinetic_energy` etc.). */
      std::string name;
      /** The material ids (Gmsh physical volume tags) of its cells. */
      std::set<types::material_id> material_ids;
      /** The constitutive law. */
      std::unique_ptr<materials::MaterialModel<3>> law;
      /** Element formulation. */
      Formulation formulation = Formulation::fbar;
      /**
       * F-bar only: the part's own beta of the volumetric stabilisation
       * (-, `Parts/<name>/F-bar stabilization`); empty: the model's
       * (`Time integration/F-bar stabilization`).
       */
      std::optional<double> fbar_stabilization;
      /**
       * The part's own target step of selective mass scaling (ms, `Parts/
       * <name>/Selective mass scaling time step`; 0: none); empty: the
       * model's (`Time integration/Selective mass scaling time step`).
       */
      std::optional<double> selective_mass_scaling_time_step;
      /** Initial velocity of its nodes (mm/ms). */
      Tensor<1, 3> initial_velocity;
      /**
       * A rigid part's initial angular velocity about its centre of mass
       * (rad/ms), in its free rotations.
       */
      Tensor<1, 3> initial_angular_velocity;
      /**
       * A rigid part (LS-DYNA's MAT_RIGID): its nodes move with one rigid
       * body whose mass, centre and inertia come from its elements and the
       * law's density (plus the mass its nodes get from deformable
       * neighbours); the law then only gives the density and the contact
       * stiffness, and its cells have no element forces and no stable
       * step.
       */
      bool rigid = false;
      /** A rigid part's free translations x, y, z. */
      bool rigid_free_translation[3] = {true, true, true};
      /** A rigid part's free rotations about x, y, z. */
      bool rigid_free_rotation[3] = {true, true, true};
      /**
       * Whether a rigid part's free directions are unknowns of the static
       * equilibrium on a quasi-static load path (`Quasi-static motion =
       * equilibrium`); else it stands still there (`held`).
       */
      bool quasi_static_equilibrium = false;
    };

    /** A boundary condition on some boundary ids. */
    struct BoundaryCondition
    {
      /** What the condition prescribes. */
      enum class Type
      {
        /** All listed components held at zero displacement. */
        fixed,
        /** Displacement u(X, t) (mm) in the listed components. */
        displacement,
        /** Velocity v(X, t) (mm/ms) in the listed components. */
        velocity,
        /** Zero normal displacement of a plane face normal to an axis. */
        symmetry,
        /**
         * Follower pressure p(X, t) (GPa) on the current surface, positive
         * when it pushes on it; one function, `components` unused
         * (model::SurfaceLoads).
         */
        pressure,
        /**
         * Traction t(X, t) per reference area (GPa) in the listed
         * components (model::SurfaceLoads).
         */
        traction
      };
      /** Name (the columns `<name>_force_x` etc.). */
      std::string name;
      /** Its faces' boundary ids (Gmsh physical surface tags). */
      std::set<types::boundary_id> boundary_ids;
      Type type = Type::fixed;
      /** The components it acts on. */
      std::vector<unsigned int> components = {0, 1, 2};
      /**
       * The prescribed value of each component in `components` as a
       * function of the reference position (mm) and time (ms); for a
       * pressure the one scalar p.
       */
      std::vector<std::function<double(const Point<3> &, double)>> functions;
      /** Whether the functions use the position. */
      bool depends_on_position = false;
      /** The reaction moment is taken about this point (mm). */
      Point<3> moment_point;
    };

    /** A rigid surface carried by a rigid body. */
    struct RigidSurfaceDefinition
    {
      /** Name (the columns `<name>_position_x` etc.). */
      std::string name;
      /** Shape, position, friction coefficient. */
      RigidSurface surface;
      /**
       * The body that carries it (mass, free directions, velocity); unused
       * if the surface is carried by a rigid part.
       */
      RigidBody body;
      /**
       * Name of the rigid part that carries it (its geometry is given at
       * t = 0 and moves and turns with the part), or empty: its own body.
       */
      std::string rigid_part;
      /** Boundary ids of the solid faces that may touch it. */
      std::set<types::boundary_id> boundary_ids;
      /** Penalty scale factor of its springs (-). */
      double penalty_scale = 0.1;
      /**
       * What the run does with boundary nodes that start inside the surface
       * (`Contact/Initial penetration`).
       */
      parameters::InitialPenetration initial_penetration =
        parameters::InitialPenetration::report;
    };

    /**
     * A contact pair between two surfaces of the mesh (`Contact
     * pairs/<name>`): segment-to-segment mortar contact
     * (contact::MortarContactPair).
     */
    struct ContactPairDefinition
    {
      /** What the pair enforces. */
      enum class Type
      {
        /** Normal contact only. */
        frictionless,
        /** Normal contact and Coulomb friction. */
        coulomb,
        /** The surfaces are bonded with their initial offset. */
        tied
      };
      /** Name (the columns `<name>_normal_force` etc.). */
      std::string name;
      /** Boundary ids of the slave and of the master faces. */
      std::set<types::boundary_id> slave_boundary_ids, master_boundary_ids;
      Type type = Type::frictionless;
      /**
       * LS-DYNA's FS, FD, DC: mu = FD + (FS - FD) exp(-DC * slip rate)
       * (-, -, ms/mm).
       */
      double static_friction  = 0.;
      double dynamic_friction = 0.;
      double decay            = 0.;
      /** Penalty scale factor s (-). */
      double penalty_scale = 1.;
      /**
       * The smallest stable step of the penalty springs (ms; 0: no
       * bound): the penalty is lowered where it would be smaller.
       */
      double penalty_time_step = 0.;
      /** Whether the pass with slave and master swapped is added. */
      bool two_pass = false;
      /** Tied: the largest initial gap that is tied (mm). */
      double tie_tolerance = 0.;
      /**
       * Explicit runs: how far the surfaces may move along a slave facet,
       * relative to the facet, before its mortar segments are integrated
       * anew (mm); 0: every evaluation (contact::MortarContactPair).
       */
      double segment_reuse_slip = 0.;
      /**
       * What the run does with slave nodes that start inside the master
       * surface (`Contact pairs/<name>/Initial penetration`; tied pairs
       * keep their initial offset and are not checked).
       */
      parameters::InitialPenetration initial_penetration =
        parameters::InitialPenetration::report;
    };

    /**
     * What the check of the initial penetrations found for one contact
     * pair or rigid surface that has any (contact::
     * resolve_initial_penetrations()), and what it did.
     */
    struct InitialPenetrationReport
    {
      /** "Contact pairs/<name>" or "Rigid surfaces/<name>". */
      std::string interaction;
      /** The entry that chose the action. */
      std::string entry;
      /** The action taken. */
      parameters::InitialPenetration action =
        parameters::InitialPenetration::report;
      /** Number of slave nodes that penetrate (all ranks). */
      unsigned int n_nodes = 0;
      /** The largest penetration, minus the gap (mm). */
      double max_penetration = 0.;
      /**
       * Where: the node with the largest penetration (of equal ones to
       * the tolerance, the lowest in x, then y, then z), mesh coordinates
       * (mm).
       */
      Point<3> where;
      /**
       * The finding as a sentence: "25 slave nodes start inside the
       * master surface, by up to 0.3 mm (at (0, 0, 5))".
       */
      std::string found;
      /** Moved out: the number of nodes moved and the largest move (mm). */
      unsigned int n_moved  = 0;
      double       max_move = 0.;
    };

    /**
     * A bolt pretension section (`Pretension sections/<name>`): a plane
     * across a part, usually a bolt's shank. The elements of the part that
     * the plane cuts carry the section's shortening, driven to a target
     * force (or a prescribed shortening) on the quasi-static load path and
     * held from the lock time on (doc/theory.md, section 12).
     */
    struct PretensionSection
    {
      /** Name (the columns `<name>_force`, `<name>_shortening`). */
      std::string name;
      /** Index of the part it cuts. */
      unsigned int part = 0;
      /** A point of the plane (mm). */
      Point<3> point;
      /** Unit normal of the plane (the bolt's axis; either sense). */
      Tensor<1, 3> normal;
      /** Force control (else a prescribed shortening). */
      bool force_control = true;
      /** Target force (kN, > 0) at the lock time, force control. */
      double target_force = 0.;
      /** Shortening (mm) at the lock time, shortening control. */
      double shortening = 0.;
      /** Pseudo-time at which the target is reached and the section locked. */
      double lock_time = 1.;
    };

    /**
     * A cross section for output (`Cross sections/<name>`, LS-DYNA's
     * *DATABASE_CROSS_SECTION): a plane across a deformable part through
     * which the resultant force and moment are reported
     * (postprocess::CrossSectionColumns).
     */
    struct CrossSection
    {
      /** Name (the columns `<name>_force_x`, ..., `<name>_bending_moment`). */
      std::string name;
      /** Index of the part it cuts. */
      unsigned int part = 0;
      /** A point of the plane (mm). */
      Point<3> point;
      /** Unit normal of the plane: the side the resultant acts from. */
      Tensor<1, 3> normal;
    };

    /**
     * The complete model, distributed over the ranks of its communicator.
     */
    class Model
    {
    public:
      explicit Model(const MPI_Comm comm);

      /**
       * After the mesh, parts, conditions and surfaces are set: distribute
       * the dofs and check that every cell belongs to exactly one part.
       * The dofs are those of `fe` (Q1), or of `fe_quadratic` (Q2) when the
       * deformable parts use the mixed u-p element (uses_mixed_up()).
       *
       * @throws InputError naming the part or material id otherwise, or
       *   naming two deformable parts of which one uses the mixed u-p
       *   element and the other not.
       */
      void
      setup();

      /**
       * Whether the deformable parts use the mixed u-p element (then all
       * of them do, and the dofs are Q2). Valid after setup().
       */
      bool
      uses_mixed_up() const
      {
        return mixed_up;
      }

      /** Index of the part named @p name. @throws if there is none. */
      unsigned int
      part_index(const std::string &name) const;

      /** Index of the part that holds @p material_id. */
      unsigned int
      part_of_material_id(const types::material_id material_id) const;

      /** The boundary ids present in the mesh (on any rank). */
      std::set<types::boundary_id>
      boundary_ids_in_mesh() const;

      MPI_Comm                                  comm;
      parallel::distributed::Triangulation<3>   triangulation;
      /** FE_Q(1)^3: the dofs of the explicit and F-bar/displacement runs. */
      FESystem<3>                               fe;
      /** FE_Q(2)^3: the dofs of the mixed u-p element (quasi-static). */
      FESystem<3>                               fe_quadratic;
      DoFHandler<3>                             dof_handler;
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;

      std::vector<Part>                   parts;
      std::vector<BoundaryCondition>      boundary_conditions;
      std::vector<RigidSurfaceDefinition> rigid_surfaces;
      std::vector<PretensionSection>      pretension_sections;
      std::vector<CrossSection>           cross_sections;
      std::vector<ContactPairDefinition>  contact_pairs;

      /**
       * The initial penetrations of the contact pairs and rigid surfaces,
       * one report per interaction that has any, once the first
       * simulation built on the model has checked them (contact::
       * resolve_initial_penetrations(), which moves nodes out at most
       * once); empty before.
       */
      std::optional<std::vector<InitialPenetrationReport>> initial_penetrations;
      /** Whether a log has shown them (the hand-off's two runs log once). */
      bool initial_penetrations_logged = false;

    private:
      /** Set by setup(): the dofs are fe_quadratic's. */
      bool mixed_up = false;

    public:
      /** Gravitational acceleration (mm/ms^2). */
      Tensor<1, 3> gravity;
    };
  } // namespace model
} // namespace rubberdyn

#endif
