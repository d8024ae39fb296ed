#ifndef rubberdyn_simulation_preload_h
#define rubberdyn_simulation_preload_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/base/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace simulation
  {
    using namespace dealii;
    /**
     * Where the load path left a rigid part in equilibrium: x = c + d +
     * R (X - c) about its centre c.
     */
    struct RigidPartPose
    {
      /** Index of the part in the model. */
      unsigned int part = 0;
      /** Its centre at t = 0 (mm). */
      dealii::Point<3> centre;
      /** Displacement of the centre (mm) and rotation. */
      dealii::Tensor<1, 3> displacement;
      dealii::Tensor<2, 3> rotation;
    };

    /**
     * The converged state of a quasi-static preload from which the
     * explicit run of `Time integration/Scheme = quasi-static then
     * explicit` starts (with zero velocity): the displacement, the
     * elements' material history and the pretension sections' locked
     * shortenings. What the explicit element force needs to be in
     * equilibrium at t = 0 is exactly this: it is the quasi-static solver's
     * own residual function (doc/theory.md, section 10.1).
     */
    struct PreloadState
    {
      /** Displacement (mm; ghosted). */
      VectorType displacement;
      /**
       * History of every Gauss point, in the layout of
       * elements::SolidHexElements::history().
       */
      std::vector<double> history;
      /** Shortening of each pretension section (mm). */
      std::vector<double> shortenings;
      /** Force through each section (kN), for the log. */
      std::vector<double> section_forces;
      /**
       * The accepted friction state of each rigid surface's contact
       * (contact::RigidSurfaceContact::state(): tangential forces and
       * reference points of this rank's nodes), then of each mortar contact
       * pair (contact::MortarContactPair::friction_state(): empty for
       * frictionless and tied pairs).
       */
      std::vector<std::vector<double>> contact_states;
      /** The rigid parts in equilibrium (Quasi-static motion). */
      std::vector<RigidPartPose> rigid_part_poses;
      /** Pseudo-time of the converged state. */
      double time = 0.;
    };

    /**
     * The part of a model's parameter text (ExplicitSimulation::
     * model_parameters_text()) that determines the preload: every entry
     * except those only the explicit run reads (initial velocities,
     * densities if there is no gravity, rigid surfaces' masses and motion,
     * the explicit step and bulk-viscosity settings). A preload checkpoint serves every explicit
     * run whose preload text is the same: another end time, impact
     * velocity or mass.
     *
     * @param with_gravity Whether the model has gravity: then the
     *   densities weigh on the preload and are part of its text.
     */
    std::string
    preload_parameters_text(const std::string &model_parameters,
                            const bool         with_gravity);

    /**
     * Write @p state as the preload checkpoint @p directory (replaced as a
     * whole only once complete): one binary file per rank and preload.txt
     * with the number of ranks, the pseudo-time and @p parameters
     * (preload_parameters_text()). Collective.
     *
     * @throws InputError naming `Time integration/Scheme` if it cannot be
     *   written.
     */
    void
    write_preload(const PreloadState &state,
                  const std::string  &directory,
                  const std::string  &parameters,
                  const MPI_Comm      comm);

    /**
     * Read the preload checkpoint @p directory.
     *
     * @param parameters The present model's preload text: it must be the
     *   one stored.
     * @param history_size, n_sections What the present elements hold.
     * @param contact_state_sizes The size of each rigid surface contact's
     *   state on this rank.
     * @throws InputError naming `Output/Restart from checkpoint` if there is
     *   none, it is damaged, it was written by another number of ranks, its
     *   parameters differ (naming the first entry that does) or its sizes
     *   do not fit. Collective.
     */
    PreloadState
    read_preload(
      const std::string                                        &directory,
      const std::string                                        &parameters,
      const std::shared_ptr<const dealii::Utilities::MPI::Partitioner> &partitioner,
      const std::size_t                                         history_size,
      const unsigned int                                        n_sections,
      const std::vector<std::size_t>                           &contact_state_sizes,
      const MPI_Comm                                            comm);
  } // namespace simulation
} // namespace rubberdyn

#endif
