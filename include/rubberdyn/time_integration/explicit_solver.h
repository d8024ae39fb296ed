#ifndef rubberdyn_time_integration_explicit_solver_h
#define rubberdyn_time_integration_explicit_solver_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <rubberdyn/base/vector.h>

#include <rubberdyn/contact/rigid_plane_contact.h>
#include <rubberdyn/elements/solid_hex_elements.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  /**
   * Time integrators. They move the model state in time and know nothing
   * of materials, elements or contact beyond the forces these return.
   */
  namespace time_integration
  {
    using namespace dealii;

    /**
     * A rigid body that carries one rigid plane of the contact layer, free
     * to translate along the directions its mask allows.
     */
    struct RigidBody
    {
      /** Mass (kg); ignored for a fixed body. */
      double mass = 0.;
      /** Translation allowed per direction (false: held). */
      bool free[3] = {false, false, false};
      /** Displacement (mm) and velocity at the last half step (mm/ms). */
      Tensor<1, 3> displacement, velocity;
      /** Force of the solid on the body at the last evaluation (kN). */
      Tensor<1, 3> contact_force;
    };

    /** Energies of the whole model (J = kN mm), summed over all ranks. */
    struct EnergyBalance
    {
      double kinetic              = 0.;
      double internal             = 0.;
      double external_work        = 0.;
      double contact              = 0.;
      double bulk_viscosity_work  = 0.;
      double initial              = 0.;
      /**
       * |E_kin + E_int + E_contact + W_bulk viscosity - E_0 - W_ext| /
       * max(E_kin + E_int + E_contact + W_bv, E_0 + |W_ext|).
       */
      double
      relative_error() const;
    };

    /** Settings of the central-difference integrator. */
    struct ExplicitSettings
    {
      /** Factor on the smallest element and contact stable step. */
      double time_step_scale = 0.9;
      /** The run stops with an error below this step (ms). */
      double minimum_time_step = 1e-8;
      /** Gravitational acceleration (mm/ms^2), on solid and bodies. */
      Tensor<1, 3> gravity;
    };

    /** Raised when the run cannot go on (inverted element, tiny step). */
    class SolverFailure : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /**
     * Explicit central-difference integration (reference study eqs.
     * 2.7-2.10) with lumped mass: velocities at half steps, displacements
     * at full steps,
     * @f[
     *   v^{n+1/2} = v^{n-1/2} + \Delta t^n M^{-1} (f^n_{ext} - f^n_{int}
     *     + f^n_{contact}),\qquad u^{n+1} = u^n + \Delta t^{n+1/2} v^{n+1/2},
     * @f]
     * $\Delta t^n = (\Delta t^{n-1/2} + \Delta t^{n+1/2})/2$, and the first
     * half step starts from the initial velocity ($\Delta t^0 =
     * \Delta t^{1/2}/2$). The step is re-evaluated every step from the
     * elements (current wave speed and size, bulk viscosity) and the penalty
     * springs, times the scale factor. Per step there are exactly two MPI
     * collectives: the minimum (stable step and failure flag) and one sum
     * (contact forces on rigid bodies and energy terms).
     */
    class ExplicitSolver
    {
    public:
      /**
       * Set up on a distributed DoFHandler (FESystem(FE_Q(1), 3)).
       */
      ExplicitSolver(const DoFHandler<3, 3> &                  dof_handler,
                     elements::SolidHexElements &              elements,
                     contact::RigidPlaneContact &              contact,
                     std::vector<RigidBody> &                  bodies,
                     const std::shared_ptr<const Utilities::MPI::Partitioner>
                       &                                       partitioner,
                     const std::vector<double> &               density_scaling,
                     const ExplicitSettings &                  settings,
                     const MPI_Comm                            comm);

      /** Set a uniform initial velocity of the solid (mm/ms). */
      void
      set_initial_velocity(const Tensor<1, 3> &velocity);

      /**
       * Advance until @p end_time. After every step @p monitor is called
       * (it decides itself whether to write output).
       *
       * @throws SolverFailure naming the element, position, time and step.
       */
      void
      run(const double                        end_time,
          const std::function<void()> &       monitor);

      /**
       * Time (ms), last step size (ms) and step count. Inside the monitor:
       * the time t_n of the state it sees, the step about to be taken.
       */
      double       time() const { return current_time; }
      double       time_step() const { return last_time_step; }
      unsigned int step() const { return step_number; }

      /** Displacement at the current time (ghosted). */
      const VectorType &displacement() const { return u; }
      /** Velocity at the last half step (ghosted). */
      const VectorType &velocity() const { return v; }
      /** Energies at the current time. */
      const EnergyBalance &energies() const { return energy; }
      /** Total added mass of mass scaling (kg). */
      double added_mass() const { return total_added_mass; }
      /** Physical mass of the solid (kg). */
      double physical_mass() const { return total_physical_mass; }

    private:
      elements::SolidHexElements &                       elements;
      contact::RigidPlaneContact &                       contact;
      std::vector<RigidBody> &                           bodies;
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      std::vector<double>                                density_scaling;
      ExplicitSettings                                   settings;
      MPI_Comm                                           comm;

      VectorType u, v, f, mass, inverse_mass, gravity_force;
      /** Direction (0, 1, 2) of each locally owned dof. */
      std::vector<unsigned char> dof_component;
      double       current_time = 0., last_time_step = 0.;
      unsigned int step_number  = 0;
      EnergyBalance energy;
      double        total_added_mass = 0., total_physical_mass = 0.;
      bool          started = false;
    };
  } // namespace time_integration
} // namespace rubberdyn

#endif
