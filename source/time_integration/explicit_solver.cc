#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>

#include <rubberdyn/time_integration/explicit_solver.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <istream>
#include <ostream>
#include <iomanip>
#include <sstream>

namespace rubberdyn
{
  namespace time_integration
  {
    double
    EnergyBalance::relative_error() const
    {
      const double present =
        kinetic + internal + contact + bulk_viscosity_work + friction_work;
      const double supplied = initial + external_work;
      const double scale    = std::max(largest_energy, current_scale());
      return scale > 0. ? std::abs(present - supplied) / scale : 0.;
    }



    double
    EnergyBalance::current_scale() const
    {
      return std::max(std::abs(kinetic) + std::abs(internal) +
                        std::abs(contact) + std::abs(bulk_viscosity_work) +
                        std::abs(friction_work),
                      std::abs(initial) + std::abs(external_work));
    }



    ExplicitSolver::ExplicitSolver(
      const DoFHandler<3, 3> &                                   dof_handler,
      elements::SolidHexElements &                               elements,
      contact::RigidSurfaceContact &                               contact,
      std::vector<RigidBody> &                                   bodies,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const std::vector<double> &                                density_scaling,
      const ExplicitSettings &                                   settings,
      const MPI_Comm                                             comm)
      : elements(elements)
      , contact(contact)
      , bodies(bodies)
      , partitioner(partitioner)
      , density_scaling(density_scaling)
      , settings(settings)
      , comm(comm)
    {
      for (VectorType *vector :
           {&u, &v, &f, &mass, &inverse_mass, &gravity_force})
        vector->reinit(partitioner);

      // Direction of every locally owned dof.
      dof_component.resize(partitioner->locally_owned_size());
      const FiniteElement<3> &   fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < dof_indices.size(); ++i)
              if (partitioner->in_local_range(dof_indices[i]))
                dof_component[partitioner->global_to_local(dof_indices[i])] =
                  fe.system_to_component_index(i).first;
          }

      // Lumped mass with and without mass scaling; gravity acts on the
      // physical mass only (added mass is a numerical device, not weight).
      VectorType physical_mass(partitioner);
      elements.add_lumped_mass(mass, density_scaling);
      elements.add_lumped_mass(physical_mass,
                               std::vector<double>(density_scaling.size(), 1.));
      mass.compress(VectorOperation::add);
      physical_mass.compress(VectorOperation::add);
      double masses[2] = {0., 0.};
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        {
          inverse_mass.local_element(i) = 1. / mass.local_element(i);
          gravity_force.local_element(i) =
            physical_mass.local_element(i) * settings.gravity[dof_component[i]];
          // A node's mass appears once per direction.
          masses[0] += physical_mass.local_element(i) / 3.;
          masses[1] += mass.local_element(i) / 3.;
        }
      Utilities::MPI::sum(ArrayView<const double>(masses, 2),
                          comm,
                          ArrayView<double>(masses, 2));
      total_physical_mass = masses[0];
      total_added_mass    = masses[1] - masses[0];
    }



    void
    ExplicitSolver::set_initial_velocity(const Tensor<1, 3> &velocity)
    {
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        v.local_element(i) = velocity[dof_component[i]];
      v.update_ghost_values();
    }



    void
    ExplicitSolver::set_constraints(const KinematicConstraints &constraints_in)
    {
      constraints = &constraints_in;
      reaction.assign(constraints->n_groups(), 0.);
      for (const KinematicConstraints::Entry &entry : constraints->entries())
        v.local_element(entry.dof) =
          constraints->velocity(entry.group, current_time);
      v.update_ghost_values();
    }



    namespace
    {
      constexpr char         checkpoint_magic[8] = "RDYNCK1";
      constexpr unsigned int checkpoint_version  = 1;

      void
      write_doubles(std::ostream &out, const double *data, const std::size_t n)
      {
        const std::uint64_t size = n;
        out.write(reinterpret_cast<const char *>(&size), sizeof(size));
        out.write(reinterpret_cast<const char *>(data), n * sizeof(double));
      }

      // Read n doubles written by write_doubles(); @p what names them in
      // the error message if the stored size differs.
      void
      read_doubles(std::istream &     in,
                   double *           data,
                   const std::size_t  n,
                   const std::string &what)
      {
        std::uint64_t size = 0;
        in.read(reinterpret_cast<char *>(&size), sizeof(size));
        if (!in || size != n)
          throw SolverFailure("the checkpoint does not fit this model: it has " +
                              std::to_string(size) + " values of " + what +
                              ", the model " + std::to_string(n));
        in.read(reinterpret_cast<char *>(data), n * sizeof(double));
        if (!in)
          throw SolverFailure("the checkpoint ends early (in " + what + ")");
      }
    } // namespace



    void
    ExplicitSolver::save(std::ostream &out) const
    {
      out.write(checkpoint_magic, sizeof(checkpoint_magic));
      const unsigned int header[2] = {checkpoint_version,
                                      Utilities::MPI::n_mpi_processes(comm)};
      out.write(reinterpret_cast<const char *>(header), sizeof(header));
      const double scalars[15] = {current_time,
                                  last_time_step,
                                  double(step_number),
                                  started ? 1. : 0.,
                                  gravity_work_increment,
                                  energy.kinetic,
                                  energy.internal,
                                  energy.external_work,
                                  energy.contact,
                                  energy.bulk_viscosity_work,
                                  energy.friction_work,
                                  energy.initial,
                                  energy.largest_energy,
                                  double(bodies.size()),
                                  constraint_work_ahead};
      write_doubles(out, scalars, 15);
      const unsigned int n_owned = partitioner->locally_owned_size();
      write_doubles(out, u.begin(), n_owned);
      write_doubles(out, v.begin(), n_owned);
      for (const RigidBody &body : bodies)
        {
          double values[9];
          for (unsigned int d = 0; d < 3; ++d)
            {
              values[d]     = body.displacement[d];
              values[3 + d] = body.velocity[d];
              values[6 + d] = body.contact_force[d];
            }
          write_doubles(out, values, 9);
        }
      write_doubles(out, reaction.data(), reaction.size());
      const std::vector<double> &history = elements.history();
      write_doubles(out, history.data(), history.size());
      const std::vector<double> &friction = contact.state();
      write_doubles(out, friction.data(), friction.size());
      if (!out)
        throw SolverFailure("writing the checkpoint failed");
    }



    void
    ExplicitSolver::load(std::istream &in)
    {
      char magic[sizeof(checkpoint_magic)] = {};
      in.read(magic, sizeof(magic));
      if (!in || std::string(magic) != checkpoint_magic)
        throw SolverFailure("not a rubberdyn checkpoint");
      unsigned int header[2] = {0, 0};
      in.read(reinterpret_cast<char *>(header), sizeof(header));
      if (header[0] != checkpoint_version)
        throw SolverFailure("checkpoint version " + std::to_string(header[0]) +
                            " is not " + std::to_string(checkpoint_version));
      if (header[1] != Utilities::MPI::n_mpi_processes(comm))
        throw SolverFailure("the checkpoint was written by " +
                            std::to_string(header[1]) +
                            " ranks; restart with as many");
      double scalars[15];
      read_doubles(in, scalars, 15, "scalars");
      if (static_cast<unsigned int>(scalars[13]) != bodies.size())
        throw SolverFailure("the checkpoint has " +
                            std::to_string(int(scalars[13])) +
                            " rigid bodies, the model " +
                            std::to_string(bodies.size()));
      current_time               = scalars[0];
      last_time_step             = scalars[1];
      step_number                = static_cast<unsigned int>(scalars[2]);
      started                    = scalars[3] != 0.;
      gravity_work_increment     = scalars[4];
      energy.kinetic             = scalars[5];
      energy.internal            = scalars[6];
      energy.external_work       = scalars[7];
      energy.contact             = scalars[8];
      energy.bulk_viscosity_work = scalars[9];
      energy.friction_work       = scalars[10];
      energy.initial             = scalars[11];
      energy.largest_energy      = scalars[12];
      constraint_work_ahead      = scalars[14];
      const unsigned int n_owned = partitioner->locally_owned_size();
      read_doubles(in, u.begin(), n_owned, "displacements");
      read_doubles(in, v.begin(), n_owned, "velocities");
      u.update_ghost_values();
      v.update_ghost_values();
      for (RigidBody &body : bodies)
        {
          double values[9];
          read_doubles(in, values, 9, "rigid-body values");
          for (unsigned int d = 0; d < 3; ++d)
            {
              body.displacement[d]  = values[d];
              body.velocity[d]      = values[3 + d];
              body.contact_force[d] = values[6 + d];
            }
        }
      read_doubles(in, reaction.data(), reaction.size(), "reactions");
      std::vector<double> &history = elements.history();
      read_doubles(in, history.data(), history.size(), "material history");
      std::vector<double> &friction = contact.state();
      read_doubles(in, friction.data(), friction.size(), "contact state");
    }



    namespace
    {
      // Seconds since @p start, and restart the clock.
      double
      lap(std::chrono::steady_clock::time_point &start)
      {
        const auto   now     = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - start).count();
        start                = now;
        return seconds;
      }

      std::string
      number(const double value)
      {
        std::ostringstream text;
        text << std::setprecision(6) << value;
        return text.str();
      }
    } // namespace



    void
    ExplicitSolver::run(const double end_time, const std::function<void()> &monitor)
    {
      const unsigned int n_owned  = partitioner->locally_owned_size();
      const unsigned int n_bodies = bodies.size();
      const unsigned int n_groups = constraints ? constraints->n_groups() : 0;
      if (!started)
        {
          // Initial energy: kinetic energy of the initial velocities.
          double local = 0.;
          for (unsigned int i = 0; i < n_owned; ++i)
            local += 0.5 * mass.local_element(i) * v.local_element(i) *
                     v.local_element(i);
          energy.initial = Utilities::MPI::sum(local, comm);
          for (const RigidBody &body : bodies)
            energy.initial += 0.5 * body.mass * body.velocity.norm_square();
        }

      std::vector<Tensor<1, 3>> plane_displacement(n_bodies);
      // Collective 2: kinetic, internal, contact, bulk viscosity, gravity
      // work, the constraints' work up to t_n and their work at t_n that
      // belongs to t_{n+1}, friction work, then the body forces and the
      // reactions.
      constexpr unsigned int n_energy_sums = 8;
      std::vector<double> sums(n_energy_sums + 3 * n_bodies + n_groups);
      std::vector<double> local_reaction(n_groups);
      auto                clock = std::chrono::steady_clock::now();
      while (current_time < end_time * (1. - 1e-12))
        {
          // Forces at u^n: -f_int + f_contact + f_gravity.
          f = 0.;
          elements::ElementStepResult element_result;
          elements.compute_forces(u, v, density_scaling, f, element_result);
          timing.element_forces += lap(clock);
          f.compress(VectorOperation::add);
          timing.communication += lap(clock);
          f *= -1.;
          f += gravity_force;
          for (unsigned int b = 0; b < n_bodies; ++b)
            plane_displacement[b] = bodies[b].displacement;
          contact::ContactResult contact_result;
          contact.add_forces(u, plane_displacement, f, contact_result);
          const double contact_step = contact.stable_time_step(mass);
          timing.contact += lap(clock);

          // Collective 1: the stable step (negative: an element failed).
          // Elements and penalty springs act in parallel on contact nodes.
          double local_step =
            1. / std::sqrt(1. / (element_result.min_time_step *
                                 element_result.min_time_step) +
                           1. / (contact_step * contact_step));
          if (element_result.failure.failed)
            local_step = -1.;
          const double stable_step = Utilities::MPI::min(local_step, comm);
          timing.communication += lap(clock);
          if (stable_step < 0.)
            {
              std::ostringstream message;
              if (element_result.failure.failed)
                message << "element " << element_result.failure.cell_id
                        << " at (" << element_result.failure.position
                        << ") mm failed: " << element_result.failure.message;
              const std::vector<std::string> messages =
                Utilities::MPI::all_gather(comm, message.str());
              std::string text;
              for (const std::string &m : messages)
                if (!m.empty() && text.empty())
                  text = m;
              throw SolverFailure(text + ", at time " + number(current_time) +
                                  " ms, step " + std::to_string(step_number));
            }
          const double new_step = settings.time_step_scale * stable_step;
          if (new_step < settings.minimum_time_step)
            throw SolverFailure("the stable time step " + number(new_step) +
                                " ms fell below the minimum time step " +
                                number(settings.minimum_time_step) +
                                " ms at time " + number(current_time) +
                                " ms, step " + std::to_string(step_number));
          const double average_step =
            started ? 0.5 * (last_time_step + new_step) : 0.5 * new_step;

          // Velocities of the solid to the next half step; kinetic energy
          // at t_n from the mean of the half-step velocities.
          double kinetic = 0.;
          for (unsigned int i = 0; i < n_owned; ++i)
            {
              const double v_old = v.local_element(i);
              const double v_new =
                v_old + average_step * inverse_mass.local_element(i) *
                          f.local_element(i);
              kinetic += 0.125 * mass.local_element(i) * (v_old + v_new) *
                         (v_old + v_new);
              v.local_element(i) = v_new;
            }
          // Prescribed velocities at t_{n+1/2}, their reactions and work
          // (the kinetic energy of the free update is corrected). Their
          // work follows the trapezoidal rule per step, as the energies are
          // at t_n: (r^{n-1} + r^n) / 2 times the displacement increment on
          // [t_{n-1}, t_n]. The half with r^n counts now, the one on
          // [t_n, t_{n+1}] with the energies at t_{n+1}. The first step
          // starts from the velocity at t_0 itself: its work goes to t_1,
          // with the mean velocity, which also counts a jump from the
          // initial to the prescribed velocity exactly.
          double constraint_work = 0., constraint_work_next = 0.;
          std::fill(local_reaction.begin(), local_reaction.end(), 0.);
          if (constraints != nullptr)
            {
              const double half_step_time = current_time + 0.5 * new_step;
              for (const KinematicConstraints::Entry &entry :
                   constraints->entries())
                {
                  const unsigned int i = entry.dof;
                  const double       m = mass.local_element(i);
                  const double v_free  = v.local_element(i);
                  const double v_old =
                    v_free - average_step * inverse_mass.local_element(i) *
                               f.local_element(i);
                  const double v_new =
                    constraints->velocity(entry.group, half_step_time);
                  const double r =
                    m * (v_new - v_old) / average_step - f.local_element(i);
                  local_reaction[entry.group] += r;
                  if (started)
                    {
                      constraint_work += 0.5 * r * v_old * last_time_step;
                      constraint_work_next += 0.5 * r * v_new * new_step;
                    }
                  else
                    constraint_work_next +=
                      r * 0.5 * (v_old + v_new) * average_step;
                  kinetic += 0.125 * m *
                             ((v_old + v_new) * (v_old + v_new) -
                              (v_old + v_free) * (v_old + v_free));
                  v.local_element(i) = v_new;
                }
            }
          timing.vector_updates += lap(clock);

          // Collective 2: energies, contact forces on the bodies,
          // reactions.
          sums[0] = kinetic;
          sums[1] = element_result.internal_energy;
          sums[2] = contact_result.penalty_energy;
          sums[3] = element_result.bulk_viscosity_power;
          sums[4] = gravity_work_increment;
          sums[5] = constraint_work;
          sums[6] = constraint_work_next;
          sums[7] = contact_result.friction_dissipation;
          for (unsigned int b = 0; b < n_bodies; ++b)
            for (unsigned int d = 0; d < 3; ++d)
              sums[n_energy_sums + 3 * b + d] =
                contact_result.force_on_plane[b][d];
          for (unsigned int g = 0; g < n_groups; ++g)
            sums[n_energy_sums + 3 * n_bodies + g] = local_reaction[g];
          Utilities::MPI::sum(ArrayView<const double>(sums),
                              comm,
                              ArrayView<double>(sums));
          timing.communication += lap(clock);

          energy.kinetic  = sums[0];
          energy.internal = sums[1];
          energy.contact  = sums[2];
          energy.bulk_viscosity_work += sums[3] * average_step;
          energy.external_work += sums[4] + constraint_work_ahead + sums[5];
          constraint_work_ahead = sums[6];
          energy.friction_work += sums[7];
          for (unsigned int g = 0; g < n_groups; ++g)
            reaction[g] = sums[n_energy_sums + 3 * n_bodies + g];
          for (unsigned int b = 0; b < n_bodies; ++b)
            {
              RigidBody &body = bodies[b];
              for (unsigned int d = 0; d < 3; ++d)
                body.contact_force[d] = sums[n_energy_sums + 3 * b + d];
              if (body.mass > 0.)
                {
                  Tensor<1, 3> v_new = body.velocity;
                  for (unsigned int d = 0; d < 3; ++d)
                    if (body.free[d])
                      v_new[d] += average_step *
                                  (body.contact_force[d] / body.mass +
                                   settings.gravity[d]);
                  energy.kinetic +=
                    0.125 * body.mass * (body.velocity + v_new).norm_square();
                  body.velocity = v_new;
                }
            }

          energy.largest_energy =
            std::max(energy.largest_energy, energy.current_scale());

          // Output sees the state at t_n and the step about to be taken.
          last_time_step = new_step;
          lap(clock);
          monitor();
          timing.output += lap(clock);

          // Displacements to t_{n+1}.
          for (RigidBody &body : bodies)
            {
              const Tensor<1, 3> increment = new_step * body.velocity;
              body.displacement += increment;
              energy.external_work += body.mass * settings.gravity * increment;
            }
          gravity_work_increment = 0.;
          for (unsigned int i = 0; i < n_owned; ++i)
            {
              const double increment = new_step * v.local_element(i);
              u.local_element(i) += increment;
              gravity_work_increment += gravity_force.local_element(i) * increment;
            }
          elements.accept_history();
          timing.vector_updates += lap(clock);
          u.update_ghost_values();
          v.update_ghost_values();
          timing.communication += lap(clock);

          current_time += new_step;
          ++step_number;
          started = true;
        }
    }
  } // namespace time_integration
} // namespace rubberdyn
