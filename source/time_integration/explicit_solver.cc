#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/time_integration/explicit_solver.h>
#include <rubberdyn/time_integration/selective_mass_scaling.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <limits>
#include <istream>
#include <ostream>
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
    EnergyBalance::absolute_error() const
    {
      return std::abs(kinetic + internal + contact + bulk_viscosity_work +
                      friction_work - initial - external_work);
    }



    double
    EnergyBalance::current_scale() const
    {
      return std::max(std::abs(kinetic) + std::abs(internal) +
                        std::abs(contact) + std::abs(bulk_viscosity_work) +
                        std::abs(friction_work),
                      std::abs(initial) + std::abs(external_work));
    }



    double
    EnergyBalance::deformable_scale() const
    {
      return std::abs(kinetic - rigid_kinetic) + std::abs(internal) +
             std::abs(contact) + std::abs(bulk_viscosity_work) +
             std::abs(friction_work);
    }



    double
    EnergyBalance::deformable_relative_error() const
    {
      const double scale =
        std::max({largest_deformable,
                  deformable_scale(),
                  0.01 * std::max(largest_energy, current_scale())});
      return scale > 0. ? absolute_error() / scale : 0.;
    }



    void
    DeformableErrorRecord::add(const double error, const double deformable)
    {
      if (!records.empty() && records.back().first == deformable &&
          error >= records.back().second)
        records.pop_back();
      if (records.empty() || error > 1.001 * records.back().second)
        records.emplace_back(deformable, error);
    }



    double
    DeformableErrorRecord::value(const double floor) const
    {
      double largest = 0.;
      for (const auto &record : records)
        {
          const double scale = std::max(record.first, floor);
          if (scale > 0.)
            largest = std::max(largest, record.second / scale);
        }
      return largest;
    }



    std::vector<double>
    DeformableErrorRecord::state() const
    {
      std::vector<double> values;
      for (const auto &record : records)
        {
          values.push_back(record.first);
          values.push_back(record.second);
        }
      return values;
    }



    void
    DeformableErrorRecord::set_state(const std::vector<double> &state)
    {
      records.clear();
      for (unsigned int i = 0; i + 1 < state.size(); i += 2)
        records.emplace_back(state[i], state[i + 1]);
    }



    namespace
    {
      /**
       * A number in [-1/2, 1/2) from a node's position (rounded to single
       * precision, so that round-off of a vertex's coordinates cannot
       * change it) and a direction (splitmix64): the assembled step
       * estimate's first start vector, the same on any partition.
       */
      double
      pseudo_random(const Point<3> &x, const unsigned int component)
      {
        std::uint64_t h = 0x9e3779b97f4a7c15ull * (component + 1);
        for (unsigned int d = 0; d < 3; ++d)
          {
            const float   rounded = static_cast<float>(x[d]);
            std::uint32_t bits    = 0;
            std::memcpy(&bits, &rounded, sizeof(bits));
            h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
            h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
            h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
            h = h ^ (h >> 31);
          }
        return double(h >> 11) * 0x1.0p-53 - 0.5;
      }
    } // namespace



    ExplicitSolver::ExplicitSolver(
      const DoFHandler<3, 3> &                                   dof_handler,
      const std::vector<model::ForceContribution *> &            contributions,
      std::vector<RigidBody> &                                   bodies,
      const KinematicConstraints *                               constraints,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const ExplicitSettings &                                   settings,
      const MPI_Comm                                             comm)
      : contributions(contributions)
      , bodies(bodies)
      , constraints(constraints)
      , partitioner(partitioner)
      , settings(settings)
      , comm(comm)
      , group_internal_energy(settings.n_groups, 0.)
      , group_motion(settings.n_groups)
      , group_work(settings.n_groups)
      , group_viscous_work_ahead(settings.n_groups, 0.)
      , group_gravity_increment(settings.n_groups + 1, 0.)
      , body_energy(bodies.size())
    {
      for (VectorType *vector :
           {&u, &v, &f, &mass, &inverse_mass, &gravity_force})
        vector->reinit(partitioner);

      // Direction and reference coordinate of every locally owned dof.
      const unsigned int n_owned = partitioner->locally_owned_size();
      dof_component.resize(n_owned);
      dof_coordinate.resize(n_owned);
      if (settings.assembled_step_estimate)
        estimate_start.resize(n_owned);
      const FiniteElement<3> &   fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < dof_indices.size(); ++i)
              if (partitioner->in_local_range(dof_indices[i]))
                {
                  const unsigned int local =
                    partitioner->global_to_local(dof_indices[i]);
                  const auto component_and_vertex =
                    fe.system_to_component_index(i);
                  dof_component[local] = component_and_vertex.first;
                  dof_coordinate[local] =
                    cell->vertex(component_and_vertex.second)
                                [component_and_vertex.first];
                  if (settings.assembled_step_estimate)
                    estimate_start[local] = pseudo_random(
                      cell->vertex(component_and_vertex.second),
                      component_and_vertex.first);
                }
          }
      dof_group.assign(n_owned, 0);
      rigid_dof.assign(n_owned, false);

      // Lumped mass with and without mass scaling; gravity acts on the
      // physical mass only (added mass is a numerical device, not weight).
      VectorType physical_mass(partitioner);
      for (const model::ForceContribution *contribution : contributions)
        contribution->add_lumped_mass(mass, physical_mass);
      mass.compress(VectorOperation::add);
      physical_mass.compress(VectorOperation::add);
      double masses[2] = {0., 0.};
      for (unsigned int i = 0; i < n_owned; ++i)
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
      if (constraints != nullptr)
        {
          reaction.assign(constraints->n_groups(), 0.);
          reaction_work.assign(constraints->n_groups(), 0.);
          reaction_work_ahead.assign(constraints->n_groups(), 0.);
          reaction_moment.assign(constraints->n_groups(), Tensor<1, 3>());
        }
      // Every body's initial velocity in its prescribed directions.
      for (RigidBody &body : bodies)
        if (body.prescribed_velocity)
          {
            const Tensor<1, 3> prescribed = body.prescribed_velocity(0.);
            for (unsigned int d = 0; d < 3; ++d)
              if (!body.moves_freely(d))
                body.velocity[d] = prescribed[d];
          }
    }



    ExplicitSolver::~ExplicitSolver() = default;



    void
    ExplicitSolver::set_initial_velocity(const Tensor<1, 3> &velocity)
    {
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        v.local_element(i) = velocity[dof_component[i]];
      v.update_ghost_values();
    }



    void
    ExplicitSolver::set_initial_velocity(const VectorType &velocity)
    {
      AssertThrow(!started, ExcMessage("initial velocity after the start"));
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        v.local_element(i) = velocity.local_element(i);
      v.update_ghost_values();
    }



    void
    ExplicitSolver::set_initial_displacement(const VectorType &displacement)
    {
      AssertThrow(!started,
                  ExcMessage("initial displacement after the start"));
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        u.local_element(i) = displacement.local_element(i);
      u.update_ghost_values();
    }



    void
    ExplicitSolver::set_group_masses(const std::vector<VectorType> &group_mass)
    {
      AssertThrow(group_mass.size() == settings.n_groups,
                  ExcDimensionMismatch(group_mass.size(), settings.n_groups));
      const unsigned int n_owned = partitioner->locally_owned_size();
      shared_dofs.clear();
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          unsigned int n_present = 0, last = 0;
          for (unsigned int g = 0; g < settings.n_groups; ++g)
            if (group_mass[g].local_element(i) > 0.)
              {
                ++n_present;
                last = g;
              }
          if (n_present == 1)
            dof_group[i] = last;
          else
            {
              // Shared by several groups (or by none, e.g. a node of a
              // rigid part): split by the groups' masses.
              dof_group[i] = settings.n_groups;
              SharedDof shared{i, std::vector<double>(settings.n_groups)};
              double    total = 0.;
              for (unsigned int g = 0; g < settings.n_groups; ++g)
                total += group_mass[g].local_element(i);
              // In proportion to the groups' physical masses, of the
              // node's (possibly scaled) mass.
              for (unsigned int g = 0; g < settings.n_groups; ++g)
                shared.mass_by_group[g] =
                  total > 0. ? mass.local_element(i) *
                                 group_mass[g].local_element(i) / total :
                               0.;
              shared_dofs.push_back(shared);
            }
        }
    }



    void
    ExplicitSolver::set_rigid_parts(const std::vector<RigidPartNodes> &parts)
    {
      AssertThrow(!started, ExcMessage("rigid parts after the start"));
      rigid_parts = parts;
      std::vector<double> weights(3 * bodies.size(), 0.);
      for (const RigidPartNodes &part : rigid_parts)
        {
          AssertIndexRange(part.body, bodies.size());
          AssertThrow(bodies[part.body].mass > 0.,
                      ExcMessage("a rigid part's body needs a mass"));
          for (const std::array<unsigned int, 3> &node : part.dofs)
            for (unsigned int d = 0; d < 3; ++d)
              {
                rigid_dof[node[d]] = true;
                // Its weight is the part's alone, as its body's kinetic
                // energy is, also where a deformable part shares the node.
                dof_group[node[d]] = part.group;
                weights[3 * part.body + d] +=
                  gravity_force.local_element(node[d]);
              }
        }
      Utilities::MPI::sum(ArrayView<const double>(weights),
                          comm,
                          ArrayView<double>(weights));
      for (const RigidPartNodes &part : rigid_parts)
        {
          RigidBody &body    = bodies[part.body];
          body.carries_nodes = true;
          for (unsigned int d = 0; d < 3; ++d)
            {
              body.weight[d] = weights[3 * part.body + d];
              if (!body.moves_freely(d))
                body.velocity[d] = 0.;
            }
          for (unsigned int d = 0; d < 3; ++d)
            if (!body.rotates() || !body.free_rotation[d])
              body.angular_velocity[d] = 0.;
          body.angular_momentum = body.inertia * body.angular_velocity;
          for (unsigned int n = 0; n < part.dofs.size(); ++n)
            {
              const Tensor<1, 3> velocity =
                body.velocity +
                cross_product_3d(body.angular_velocity,
                                 part.X[n] - body.reference_position);
              for (unsigned int d = 0; d < 3; ++d)
                v.local_element(part.dofs[n][d]) = velocity[d];
            }
        }
      v.update_ghost_values();
    }



    void
    ExplicitSolver::set_rigid_node_velocities(const double step)
    {
      for (const RigidPartNodes &part : rigid_parts)
        {
          const RigidBody &body = bodies[part.body];
          // The pose at t_{n+1}: x = C + u + R (X - C).
          const Point<3> centre =
            body.current_reference_position() + step * body.velocity;
          const Tensor<2, 3> rotation = body.rotation_after(step);
          for (unsigned int n = 0; n < part.dofs.size(); ++n)
            {
              const Point<3> x_next =
                centre + rotation * (part.X[n] - body.reference_position);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  const unsigned int i = part.dofs[n][d];
                  v.local_element(i) =
                    (x_next[d] - part.X[n][d] - u.local_element(i)) / step;
                }
            }
        }
    }



    namespace
    {
      constexpr char         checkpoint_magic[8] = "RDYNCK4";
      constexpr unsigned int checkpoint_version  = 4;
      /** Values per rigid body in a checkpoint. */
      constexpr unsigned int n_body_values = 27;

      /** A body's state as n_body_values numbers. */
      void
      body_values(const RigidBody &body, double *values)
      {
        for (unsigned int d = 0; d < 3; ++d)
          {
            values[d]      = body.displacement[d];
            values[3 + d]  = body.velocity[d];
            values[6 + d]  = body.contact_force[d];
            values[9 + d]  = body.angular_velocity[d];
            values[12 + d] = body.contact_moment[d];
            values[24 + d] = body.angular_momentum[d];
            for (unsigned int e = 0; e < 3; ++e)
              values[15 + 3 * d + e] = body.rotation[d][e];
          }
      }

      /** The inverse of body_values(). */
      void
      set_body_values(const double *values, RigidBody &body)
      {
        for (unsigned int d = 0; d < 3; ++d)
          {
            body.displacement[d]     = values[d];
            body.velocity[d]         = values[3 + d];
            body.contact_force[d]    = values[6 + d];
            body.angular_velocity[d] = values[9 + d];
            body.contact_moment[d]   = values[12 + d];
            body.angular_momentum[d] = values[24 + d];
            for (unsigned int e = 0; e < 3; ++e)
              body.rotation[d][e] = values[15 + 3 * d + e];
          }
      }
      constexpr unsigned int n_scalars           = 18;
    } // namespace



    void
    ExplicitSolver::save(std::ostream &out) const
    {
      using binary_io::write_doubles;
      out.write(checkpoint_magic, sizeof(checkpoint_magic));
      const unsigned int header[2] = {checkpoint_version,
                                      Utilities::MPI::n_mpi_processes(comm)};
      out.write(reinterpret_cast<const char *>(header), sizeof(header));
      const double scalars[n_scalars] = {current_time,
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
                                         constraint_work_ahead,
                                         energy.rigid_kinetic,
                                         energy.largest_deformable,
                                         viscous_work_ahead};
      write_doubles(out, scalars, n_scalars);
      const unsigned int n_owned = partitioner->locally_owned_size();
      write_doubles(out, u.begin(), n_owned);
      write_doubles(out, v.begin(), n_owned);
      for (const RigidBody &body : bodies)
        {
          double values[n_body_values];
          body_values(body, values);
          write_doubles(out, values, n_body_values);
        }
      write_doubles(out, reaction.data(), reaction.size());
      std::vector<double> moments;
      for (const Tensor<1, 3> &m : reaction_moment)
        for (unsigned int d = 0; d < 3; ++d)
          moments.push_back(m[d]);
      write_doubles(out, moments.data(), moments.size());
      write_doubles(out, reaction_work.data(), reaction_work.size());
      write_doubles(out, reaction_work_ahead.data(), reaction_work_ahead.size());
      std::vector<double> by_group = group_internal_energy;
      for (const GroupMotion &motion : group_motion)
        {
          by_group.push_back(motion.kinetic_energy);
          for (unsigned int d = 0; d < 3; ++d)
            by_group.push_back(motion.momentum[d]);
        }
      for (unsigned int g = 0; g < settings.n_groups; ++g)
        {
          by_group.push_back(group_work[g].bulk_viscosity);
          by_group.push_back(group_work[g].gravity);
          by_group.push_back(group_viscous_work_ahead[g]);
        }
      // This rank's share of the last gravity increments (summed next step).
      by_group.insert(by_group.end(),
                      group_gravity_increment.begin(),
                      group_gravity_increment.begin() + settings.n_groups);
      for (const BodyEnergy &body : body_energy)
        for (const double value :
             {body.kinetic, body.gravity_work, body.drive_work})
          by_group.push_back(value);
      write_doubles(out, by_group.data(), by_group.size());
      for (const model::ForceContribution *contribution : contributions)
        contribution->save(out);
      // Selective mass scaling: the next solve's start, so that a restart
      // takes the same iterations to the same bits.
      if (mass_scaling)
        {
          write_doubles(out, acceleration.begin(), n_owned);
          mass_scaling->save(out);
        }
      // The assembled step estimate's state (its warm start), so that a
      // restart takes the same steps; a checkpoint before the first step
      // has none yet (zeros: a fresh estimate).
      if (settings.assembled_step_estimate)
        {
          if (step_estimate)
            step_estimate->save(out);
          else
            {
              const std::vector<double> none(6 + n_owned, 0.);
              write_doubles(out, none.data(), none.size());
            }
        }
      if (!out)
        throw SolverFailure("writing the checkpoint failed");
    }



    void
    ExplicitSolver::load(std::istream &in)
    {
      using binary_io::read_doubles;
      // Every rank reads its own piece; only if all succeeded do they
      // exchange ghost values: a rank that fails must not leave the others
      // waiting in a collective. (The assembled step estimate is made
      // first: that is collective.)
      make_step_estimate();
      std::string error;
      try
        {
          char magic[sizeof(checkpoint_magic)] = {};
          in.read(magic, sizeof(magic));
          if (!in || std::string(magic, sizeof(magic) - 1) !=
                       std::string(checkpoint_magic, sizeof(magic) - 1))
            throw SolverFailure("not a rubberdyn checkpoint of this version");
          unsigned int header[2] = {0, 0};
          in.read(reinterpret_cast<char *>(header), sizeof(header));
          if (header[0] != checkpoint_version)
            throw SolverFailure("checkpoint version " +
                                std::to_string(header[0]) + " is not " +
                                std::to_string(checkpoint_version));
          if (header[1] != Utilities::MPI::n_mpi_processes(comm))
            throw SolverFailure("the checkpoint was written by " +
                                std::to_string(header[1]) +
                                " ranks; restart with as many");
          double scalars[n_scalars];
          read_doubles(in, scalars, n_scalars, "scalars");
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
          energy.rigid_kinetic       = scalars[15];
          energy.largest_deformable  = scalars[16];
          viscous_work_ahead         = scalars[17];
          const unsigned int n_owned = partitioner->locally_owned_size();
          read_doubles(in, u.begin(), n_owned, "displacements");
          read_doubles(in, v.begin(), n_owned, "velocities");
          for (RigidBody &body : bodies)
            {
              double values[n_body_values];
              read_doubles(in, values, n_body_values, "rigid-body values");
              set_body_values(values, body);
            }
          read_doubles(in, reaction.data(), reaction.size(), "reactions");
          std::vector<double> moments(3 * reaction_moment.size());
          read_doubles(in, moments.data(), moments.size(), "reaction moments");
          for (unsigned int g = 0; g < reaction_moment.size(); ++g)
            for (unsigned int d = 0; d < 3; ++d)
              reaction_moment[g][d] = moments[3 * g + d];
          read_doubles(in, reaction_work.data(), reaction_work.size(),
                       "reaction work");
          read_doubles(in, reaction_work_ahead.data(),
                       reaction_work_ahead.size(), "reaction work");
          const unsigned int n_groups = settings.n_groups;
          std::vector<double> by_group(9 * n_groups + 3 * bodies.size());
          read_doubles(in, by_group.data(), by_group.size(), "part energies");
          for (unsigned int g = 0; g < n_groups; ++g)
            {
              group_internal_energy[g]       = by_group[g];
              group_motion[g].kinetic_energy = by_group[n_groups + 4 * g];
              for (unsigned int d = 0; d < 3; ++d)
                group_motion[g].momentum[d] =
                  by_group[n_groups + 4 * g + 1 + d];
              group_work[g].bulk_viscosity = by_group[5 * n_groups + 3 * g];
              group_work[g].gravity = by_group[5 * n_groups + 3 * g + 1];
              group_viscous_work_ahead[g] = by_group[5 * n_groups + 3 * g + 2];
              group_gravity_increment[g] = by_group[8 * n_groups + g];
            }
          for (unsigned int b = 0; b < bodies.size(); ++b)
            {
              const double *values = &by_group[9 * n_groups + 3 * b];
              body_energy[b]       = {values[0], values[1], values[2]};
            }
          for (model::ForceContribution *contribution : contributions)
            contribution->load(in);
          if (mass_scaling)
            {
              read_doubles(in, acceleration.begin(), n_owned,
                           "selective mass scaling accelerations");
              mass_scaling->load(in);
            }
          if (step_estimate)
            step_estimate->load(in);
        }
      catch (const std::exception &failure)
        {
          error = failure.what();
        }
      const std::vector<std::string> errors =
        Utilities::MPI::all_gather(comm, error);
      for (unsigned int rank = 0; rank < errors.size(); ++rank)
        if (!errors[rank].empty())
          throw SolverFailure("rank " + std::to_string(rank) + ": " +
                              errors[rank]);
      u.update_ghost_values();
      v.update_ghost_values();
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
    ExplicitSolver::evaluate_forces()
    {
      const unsigned int n_groups = settings.n_groups;
      results.reset(n_groups, bodies.size());
      const model::EvaluationPoint point{u, v, mass, bodies, current_time};
      f = 0.;
      // The penalty stiffness of contact follows the geometry of every step.
      for (model::ForceContribution *contribution : contributions)
        contribution->follow_geometry();
      auto clock = std::chrono::steady_clock::now();
      // Internal forces first (owned and ghost entries), then compress and
      // turn them into forces on the solid, then the external forces. The
      // external ones are computed while the internal ones' sums travel,
      // and their own messages while the elements compute (the split
      // evaluation of ForceContribution): the ranks then wait for each
      // other once, on the whole step's work, rather than at every
      // contribution's exchange.
      for (model::ForceContribution *contribution : contributions)
        if (contribution->accumulation() ==
            model::ForceContribution::Accumulation::external_owned)
          contribution->start_forces(point);
      timing.contact += lap(clock);
      for (model::ForceContribution *contribution : contributions)
        if (contribution->accumulation() ==
            model::ForceContribution::Accumulation::internal_ghosted)
          contribution->add_forces(point, f, results);
      timing.element_forces += lap(clock);
      f.compress_start(0, VectorOperation::add);
      timing.communication += lap(clock);
      for (model::ForceContribution *contribution : contributions)
        if (contribution->accumulation() ==
            model::ForceContribution::Accumulation::external_owned)
          contribution->compute_forces(point, results);
      timing.contact += lap(clock);
      f.compress_finish(VectorOperation::add);
      timing.communication += lap(clock);
      f *= -1.;
      f += gravity_force;
      for (model::ForceContribution *contribution : contributions)
        if (contribution->accumulation() ==
            model::ForceContribution::Accumulation::external_owned)
          contribution->add_forces(point, f, results);
      timing.contact += lap(clock);
    }



    void
    ExplicitSolver::StepSums::reinit(const unsigned int n_bodies,
                                     const unsigned int n_constraint_groups,
                                     const unsigned int n_groups,
                                     const unsigned int n_shared_dofs)
    {
      body_offset     = n_energy_sums;
      reaction_offset = body_offset + 6 * n_bodies;
      // Per constraint group: reaction, moment (3), work up to t_n and its
      // share on [t_n, t_{n+1}].
      group_offset = reaction_offset + 6 * n_constraint_groups;
      values.assign(group_offset + 7 * n_groups, 0.);
      local_reaction.assign(6 * n_constraint_groups, 0.);
      shared_velocity.assign(n_shared_dofs, 0.);
      group_kinetic.assign(n_groups + 1, 0.);
      group_momentum.assign(3 * (n_groups + 1), 0.);
    }



    void
    ExplicitSolver::start()
    {
      // The constrained dofs start with their prescribed velocity (a
      // loaded checkpoint has started and keeps its own).
      if (constraints != nullptr)
        {
          for (const KinematicConstraints::Entry &entry :
               constraints->entries())
            v.local_element(entry.dof) = constraints->initial_velocity(entry);
          v.update_ghost_values();
        }
      // Initial energy: kinetic energy of the initial velocities.
      double local = 0.;
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        if (!rigid_dof[i]) // a rigid part's energy is its body's
          local += 0.5 * mass.local_element(i) * v.local_element(i) *
                   v.local_element(i);
      // Selective mass scaling: the added mass's share, 1/2 v^T A v (an
      // initial velocity that differs within a scaled element, e.g. next
      // to a held node, has some).
      if (mass_scaling)
        {
          v.update_ghost_values();
          std::vector<double> by_group(settings.n_groups, 0.);
          local += mass_scaling->added_kinetic_energy(v, by_group);
        }
      energy.initial = Utilities::MPI::sum(local, comm);
      for (const RigidBody &body : bodies)
        energy.initial +=
          0.5 * body.mass * body.velocity.norm_square() +
          0.5 * body.angular_velocity * (body.inertia * body.angular_velocity);
    }



    double
    ExplicitSolver::next_time_step(std::chrono::steady_clock::time_point &clock)
    {
      // Collective 1: the smallest element and contact steps of the whole
      // model (a failed element: a negative element step), then combined:
      // elements and penalty springs act in parallel on contact nodes.
      // With the assembled estimate also the elements' step without bulk
      // viscosity and the viscosity's smallest factor on it.
      double minima[4];
      minima[0] = results.failure.failed ? -1. : results.element_time_step;
      minima[1] = results.contact_time_step;
      minima[2] = results.element_undamped_time_step;
      minima[3] = results.element_damping_factor;
      const unsigned int n_minima = step_estimate ? 4 : 2;
      Utilities::MPI::min(ArrayView<const double>(minima, n_minima),
                          comm,
                          ArrayView<double>(minima, n_minima));
      timing.communication += lap(clock);
      if (minima[0] < 0.)
        {
          const std::vector<std::string> messages =
            Utilities::MPI::all_gather(comm, results.failure.message);
          std::string text;
          for (const std::string &m : messages)
            if (!m.empty() && text.empty())
              text = m;
          throw SolverFailure(text + ", at time " + number(current_time) +
                              " ms, step " + std::to_string(step_number));
        }
      // The elements' step: their bound, or the assembled model's estimate
      // (never below the bound). The contact springs combine with it either
      // way: 1/dt^2 = 1/dt_e^2 + 1/dt_c^2 is Weyl's inequality,
      // lambda_max(A + C) <= lambda_max(A) + lambda_max(C), with the
      // springs' M^{-1} C diagonal (doc/theory.md section 8.3).
      const double element_step =
        step_estimate ?
          step_estimate->element_time_step(minima[0], minima[2], minima[3]) :
          minima[0];
      const double stable_step =
        1. / std::sqrt(1. / (element_step * element_step) +
                       1. / (minima[1] * minima[1]));
      const double new_step    = settings.time_step_scale * stable_step;
      if (new_step < settings.minimum_time_step)
        throw SolverFailure("the stable time step " + number(new_step) +
                            " ms fell below the minimum time step " +
                            number(settings.minimum_time_step) +
                            " ms at time " + number(current_time) +
                            " ms, step " + std::to_string(step_number));
      return new_step;
    }



    void
    ExplicitSolver::make_step_estimate()
    {
      if (!settings.assembled_step_estimate || step_estimate)
        return;
      if (mass_scaling)
        throw SolverFailure(
          "Time integration/Stable time step estimate = assembled needs a "
          "lumped mass matrix; selective mass scaling makes it a full one: "
          "use Stable time step estimate = element with it");
      // The free dofs: not prescribed, not a rigid part's.
      const unsigned int n_owned = partitioner->locally_owned_size();
      std::vector<bool>  free_dof(n_owned, true);
      for (unsigned int i = 0; i < n_owned; ++i)
        if (rigid_dof[i])
          free_dof[i] = false;
      if (constraints != nullptr)
        for (const KinematicConstraints::Entry &entry : constraints->entries())
          free_dof[entry.dof] = false;
      step_estimate = std::make_unique<AssembledStepEstimate>(
        settings.assembled_step, partitioner, inverse_mass, free_dof,
        estimate_start, comm);
      for (VectorType *vector :
           {&probe_displacement, &probe_force, &base_force})
        vector->reinit(partitioner);
      // The probe: 1e-8 of the model's extent, so that the strain it makes
      // is far below any nonlinearity of the laws and far above the
      // forces' round-off (1e-16 of them) in elements down to 1e-6 of the
      // model's size.
      double extent[6] = {0., 0., 0., 0., 0., 0.};
      for (unsigned int d = 0; d < 3; ++d)
        {
          extent[d]     = -std::numeric_limits<double>::max();
          extent[3 + d] = -std::numeric_limits<double>::max();
        }
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const unsigned int d = dof_component[i];
          extent[d]            = std::max(extent[d], dof_coordinate[i]);
          extent[3 + d]        = std::max(extent[3 + d], -dof_coordinate[i]);
        }
      Utilities::MPI::max(ArrayView<const double>(extent, 6),
                          comm,
                          ArrayView<double>(extent, 6));
      double size = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        size = std::max(size, extent[d] + extent[3 + d]);
      probe_size = 1e-8 * (size > 0. && std::isfinite(size) ? size : 1.);
    }



    void
    ExplicitSolver::refresh_step_estimate()
    {
      // The stiffness forces (the elements') at a displacement; false if
      // an element failed on some rank (collective).
      const auto forces_at = [this](const VectorType &displacement,
                                    VectorType       &force) {
        probe_results.reset(settings.n_groups, bodies.size());
        const model::EvaluationPoint point{
          displacement, v, mass, bodies, current_time};
        force = 0.;
        for (model::ForceContribution *contribution : contributions)
          if (contribution->in_assembled_step_estimate())
            contribution->add_forces(point, force, probe_results);
        force.compress(VectorOperation::add);
        return Utilities::MPI::max(probe_results.failure.failed ? 1 : 0,
                                   comm) == 0;
      };
      const unsigned int n_owned = partitioner->locally_owned_size();
      // K x = (f(u + eps x) - f(u)) / eps, with eps max|x| = probe_size.
      const auto product = [&](const VectorType &x, VectorType &y) {
        double largest = 0.;
        for (unsigned int i = 0; i < n_owned; ++i)
          largest = std::max(largest, std::abs(x.local_element(i)));
        largest = Utilities::MPI::max(largest, comm);
        if (!(largest > 0.))
          {
            y = 0.;
            return true;
          }
        const double eps = probe_size / largest;
        for (unsigned int i = 0; i < n_owned; ++i)
          probe_displacement.local_element(i) =
            u.local_element(i) + eps * x.local_element(i);
        probe_displacement.update_ghost_values();
        if (!forces_at(probe_displacement, probe_force))
          return false;
        for (unsigned int i = 0; i < n_owned; ++i)
          y.local_element(i) =
            (probe_force.local_element(i) - base_force.local_element(i)) / eps;
        return true;
      };
      if (forces_at(u, base_force))
        step_estimate->refresh(step_number, product);
    }



    void
    ExplicitSolver::advance_velocities(const StepWeights &w)
    {
      // Velocities of the solid to the next half step; kinetic energy at
      // t_n from the mean of the half-step velocities, per group (StepWeights).
      std::fill(sums.group_kinetic.begin(), sums.group_kinetic.end(), 0.);
      std::fill(sums.group_momentum.begin(), sums.group_momentum.end(), 0.);
      for (unsigned int k = 0; k < shared_dofs.size(); ++k)
        sums.shared_velocity[k] = v.local_element(shared_dofs[k].dof);
      // (Locals: the stores into v may alias anything behind a reference.)
      const unsigned int n_owned = partitioner->locally_owned_size();
      const double average_step = w.average_step, w_old = w.old, w_new = w.next;
      double *const group_kinetic  = sums.group_kinetic.data();
      double *const group_momentum = sums.group_momentum.data();
      double        kinetic        = 0.;
      if (mass_scaling)
        solve_scaled_accelerations(w);
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double v_old = v.local_element(i);
          // (The scaled elements' nodes: the solved accelerations.)
          const double v_new =
            mass_scaling && mass_scaling->scaled(i) ?
              v_old + average_step * acceleration.local_element(i) :
              v_old + average_step * inverse_mass.local_element(i) *
                        f.local_element(i);
          v.local_element(i) = v_new;
          if (rigid_dof[i]) // moves with its body, counted with it
            continue;
          const double       m         = mass.local_element(i);
          const unsigned int g         = dof_group[i];
          const double       v_mean    = w_old * v_old + w_new * v_new;
          const double       kinetic_i = 0.5 * m * v_mean * v_mean;
          kinetic += kinetic_i;
          group_kinetic[g] += kinetic_i;
          group_momentum[3 * g + dof_component[i]] += m * v_mean;
        }
      sums.kinetic = kinetic;
    }



    void
    ExplicitSolver::apply_constraints(const StepWeights &w)
    {
      // Prescribed velocities at t_{n+1/2}, their reactions and work (the
      // kinetic energy of the free update is corrected). Their work follows
      // the trapezoidal rule per step, as the energies are at t_n:
      // (r^{n-1} + r^n) / 2 times the displacement increment on
      // [t_{n-1}, t_n]. The half with r^n counts now, the one on
      // [t_n, t_{n+1}] with the energies at t_{n+1}. The first step starts
      // from the velocity at t_0 itself: its work goes to t_1, with the
      // mean velocity, which also counts a jump from the initial to the
      // prescribed velocity exactly.
      sums.constraint_work      = 0.;
      sums.constraint_work_next = 0.;
      std::fill(sums.local_reaction.begin(), sums.local_reaction.end(), 0.);
      if (constraints == nullptr)
        return;
      const unsigned int n_cgroups = constraints->n_groups();
      constraints->begin_step(current_time, w.new_step);
      for (const KinematicConstraints::Entry &entry : constraints->entries())
        {
          const unsigned int i      = entry.dof;
          const double       m      = mass.local_element(i);
          const double       v_free = v.local_element(i);
          const bool scaled = mass_scaling && mass_scaling->scaled(i);
          const double v_old =
            scaled ? velocity_before.local_element(i) :
                     v_free - w.average_step * inverse_mass.local_element(i) *
                                f.local_element(i);
          const double v_new =
            constraints->half_step_velocity(entry, u.local_element(i));
          // With selective mass scaling the neighbours' added mass pulls
          // too: the reaction is (M a - f)_i with M's whole row.
          const double r =
            m * (v_new - v_old) / w.average_step - f.local_element(i) +
            (scaled ? added_inertia.local_element(i) : 0.);
          sums.local_reaction[entry.group] += r;
          // Moment about the group's point, current position.
          {
            Tensor<1, 3> arm;
            for (unsigned int d = 0; d < 3; ++d)
              arm[d] = entry.X[d] + u.local_element(entry.node_dofs[d]) -
                       constraints->moment_point(entry.group)[d];
            Tensor<1, 3> force;
            force[dof_component[i]]   = r;
            const Tensor<1, 3> moment = cross_product_3d(arm, force);
            for (unsigned int d = 0; d < 3; ++d)
              sums.local_reaction[n_cgroups + 3 * entry.group + d] += moment[d];
          }
          double work = 0., work_next;
          if (started)
            {
              work      = 0.5 * r * v_old * last_time_step;
              work_next = 0.5 * r * v_new * w.new_step;
            }
          else
            work_next = r * 0.5 * (v_old + v_new) * w.average_step;
          sums.constraint_work += work;
          sums.constraint_work_next += work_next;
          sums.local_reaction[4 * n_cgroups + entry.group] += work;
          sums.local_reaction[5 * n_cgroups + entry.group] += work_next;
          const unsigned int g         = dof_group[i];
          const double       mean_new  = w.old * v_old + w.next * v_new;
          const double       mean_free = w.old * v_old + w.next * v_free;
          const double       correction =
            0.5 * m * (mean_new * mean_new - mean_free * mean_free);
          sums.kinetic += correction;
          sums.group_kinetic[g] += correction;
          sums.group_momentum[3 * g + dof_component[i]] +=
            m * (mean_new - mean_free);
          v.local_element(i) = v_new;
        }
    }



    void
    ExplicitSolver::set_selective_mass_scaling(
      std::unique_ptr<SelectiveMassScaling> scaling)
    {
      AssertThrow(!started,
                  ExcMessage("Selective mass scaling is set before the first "
                             "step"));
      mass_scaling = std::move(scaling);
      const unsigned int n_owned = partitioner->locally_owned_size();
      std::vector<bool> prescribed(n_owned, false);
      if (constraints != nullptr)
        for (const KinematicConstraints::Entry &entry : constraints->entries())
          prescribed[entry.dof] = true;
      std::vector<unsigned int> component(dof_component.begin(),
                                          dof_component.end());
      mass_scaling->initialize(mass, component, prescribed);
      bool scaled_prescribed = false;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          AssertThrow(!(rigid_dof[i] && mass_scaling->scaled(i)),
                      ExcMessage("A rigid part's node is in an element with "
                                 "selective mass scaling"));
          scaled_prescribed |= prescribed[i] && mass_scaling->scaled(i);
        }
      // The reactions need A a only where a scaled element holds a
      // prescribed dof, on some rank: decided once, for all of them.
      reactions_need_added_mass =
        Utilities::MPI::logical_or(scaled_prescribed, comm);
      for (VectorType *vector :
           {&acceleration, &added_inertia, &velocity_before, &mean_velocity})
        vector->reinit(partitioner);
      // The first solve starts from the lumped accelerations.
      acceleration = 0.;
    }



    void
    ExplicitSolver::solve_scaled_accelerations(const StepWeights &w)
    {
      const auto         start   = std::chrono::steady_clock::now();
      const unsigned int n_owned = partitioner->locally_owned_size();
      for (unsigned int i = 0; i < n_owned; ++i)
        velocity_before.local_element(i) = v.local_element(i);
      // The first solve starts from the lumped mass's accelerations; later
      // ones from the last step's.
      if (!started)
        for (unsigned int i = 0; i < n_owned; ++i)
          acceleration.local_element(i) =
            inverse_mass.local_element(i) * f.local_element(i);
      // The prescribed dofs' accelerations are known: they take the
      // constraint's half-step velocity.
      if (constraints != nullptr)
        {
          constraints->begin_step(current_time, w.new_step);
          for (const KinematicConstraints::Entry &entry :
               constraints->entries())
            if (mass_scaling->scaled(entry.dof))
              acceleration.local_element(entry.dof) =
                (constraints->half_step_velocity(entry,
                                                 u.local_element(entry.dof)) -
                 v.local_element(entry.dof)) /
                w.average_step;
        }
      try
        {
          mass_scaling->solve(f, acceleration);
        }
      catch (const std::runtime_error &error)
        {
          throw SolverFailure(std::string(error.what()) + " at time " +
                              number(current_time) + " ms, step " +
                              std::to_string(step_number));
        }
      // (Collective: on every rank, whether or not it owns such a dof.)
      if (reactions_need_added_mass)
        mass_scaling->multiply_added_mass(acceleration, added_inertia);
      timing.mass_scaling +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }



    void
    ExplicitSolver::add_scaled_kinetic_energy(const StepWeights &w)
    {
      // 1/2 v^T A v at t_n, with the same mean of the half-step velocities
      // as the lumped part's (advance_velocities()). The added mass moves
      // no momentum (A 1 = 0).
      const unsigned int n_owned = partitioner->locally_owned_size();
      for (unsigned int i = 0; i < n_owned; ++i)
        mean_velocity.local_element(i) =
          w.old * velocity_before.local_element(i) +
          w.next * v.local_element(i);
      mean_velocity.update_ghost_values();
      std::vector<double> by_group(settings.n_groups, 0.);
      sums.kinetic +=
        mass_scaling->added_kinetic_energy(mean_velocity, by_group);
      for (unsigned int g = 0; g < settings.n_groups; ++g)
        sums.group_kinetic[g] += by_group[g];
    }



    void
    ExplicitSolver::add_shared_dofs_motion(const StepWeights &w)
    {
      // Dofs shared by several groups: split by their masses.
      for (unsigned int k = 0; k < shared_dofs.size(); ++k)
        {
          const unsigned int i = shared_dofs[k].dof;
          if (rigid_dof[i])
            continue;
          const double v_mid =
            w.old * sums.shared_velocity[k] + w.next * v.local_element(i);
          for (unsigned int g = 0; g < settings.n_groups; ++g)
            {
              const double m = shared_dofs[k].mass_by_group[g];
              sums.group_kinetic[g] += 0.5 * m * v_mid * v_mid;
              sums.group_momentum[3 * g + dof_component[i]] += m * v_mid;
            }
        }
    }



    void
    ExplicitSolver::sum_over_ranks()
    {
      // Collective 2: kinetic, internal, contact, bulk viscosity, gravity
      // work, the constraints' work up to t_n and their work at t_n that
      // belongs to t_{n+1}, friction work, the contributions' external
      // work, the prescribed bodies' work, then the body forces, the
      // reactions and their moments, and per group the internal energy,
      // kinetic energy and momentum, bulk-viscosity power and gravity work.
      const unsigned int   n_groups = settings.n_groups;
      std::vector<double> &values   = sums.values;
      values[0]                     = sums.kinetic;
      values[1]                     = results.internal_energy;
      values[2]                     = results.contact_energy;
      values[3]                     = results.bulk_viscosity_power;
      values[4]                     = gravity_work_increment;
      values[5]                     = sums.constraint_work;
      values[6]                     = sums.constraint_work_next;
      values[7]                     = results.friction_dissipation;
      values[8]                     = results.external_work;
      values[9]                     = 0.;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        for (unsigned int d = 0; d < 3; ++d)
          {
            values[sums.body_offset + 6 * b + d] = results.force_on_body[b][d];
            values[sums.body_offset + 6 * b + 3 + d] =
              results.moment_on_body[b][d];
          }
      // The forces on the rigid parts' nodes (with their weight) and their
      // moments about the bodies' current centres.
      for (const RigidPartNodes &part : rigid_parts)
        {
          const RigidBody &body   = bodies[part.body];
          const Point<3>   centre = body.current_reference_position();
          double *const    sum    = &values[sums.body_offset + 6 * part.body];
          for (unsigned int n = 0; n < part.dofs.size(); ++n)
            {
              Tensor<1, 3> force, arm;
              for (unsigned int d = 0; d < 3; ++d)
                {
                  const unsigned int i = part.dofs[n][d];
                  force[d]             = f.local_element(i);
                  arm[d] = part.X[n][d] + u.local_element(i) - centre[d];
                }
              const Tensor<1, 3> moment = cross_product_3d(arm, force);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  sum[d] += force[d];
                  sum[3 + d] += moment[d];
                }
            }
        }
      for (unsigned int g = 0; g < sums.local_reaction.size(); ++g)
        values[sums.reaction_offset + g] = sums.local_reaction[g];
      for (unsigned int g = 0; g < n_groups; ++g)
        {
          values[sums.group_offset + g] = results.internal_energy_by_group[g];
          values[sums.group_offset + n_groups + 4 * g] = sums.group_kinetic[g];
          for (unsigned int d = 0; d < 3; ++d)
            values[sums.group_offset + n_groups + 4 * g + 1 + d] =
              sums.group_momentum[3 * g + d];
          values[sums.group_offset + 5 * n_groups + g] =
            results.bulk_viscosity_power_by_group[g];
          values[sums.group_offset + 6 * n_groups + g] =
            group_gravity_increment[g];
        }
      Utilities::MPI::sum(ArrayView<const double>(values),
                          comm,
                          ArrayView<double>(values));
    }



    void
    ExplicitSolver::book_sums(const double new_step)
    {
      const std::vector<double> &values = sums.values;
      const unsigned int n_cgroups = constraints ? constraints->n_groups() : 0;
      const unsigned int n_groups  = settings.n_groups;
      energy.kinetic               = values[0];
      energy.internal              = values[1];
      energy.contact               = values[2];
      // A run that starts deformed (a preloaded state handed over from the
      // quasi-static solver) starts with its stored energy: in the elements
      // and in the penalty springs of contacts that are closed at the
      // start.
      if (!started)
        energy.initial += energy.internal + energy.contact;
      // The viscous forces at t_n act on [t_{n-1/2}, t_{n+1/2}]: the half
      // on [t_n, t_{n+1/2}] belongs to the energies at t_{n+1}, as the
      // constraints' work does (the same time level as the kinetic energy
      // at t_n and the trapezoidal external work up to t_n).
      energy.bulk_viscosity_work +=
        viscous_work_ahead + (started ? 0.5 * values[3] * last_time_step : 0.);
      viscous_work_ahead = 0.5 * values[3] * new_step;
      energy.external_work +=
        values[4] + constraint_work_ahead + values[5] + values[8];
      constraint_work_ahead = values[6];
      energy.friction_work += values[7];
      for (unsigned int g = 0; g < n_cgroups; ++g)
        {
          reaction[g] = values[sums.reaction_offset + g];
          for (unsigned int d = 0; d < 3; ++d)
            reaction_moment[g][d] =
              values[sums.reaction_offset + n_cgroups + 3 * g + d];
          // The same trapezoidal work as the external work's, per group.
          reaction_work[g] += reaction_work_ahead[g] +
                              values[sums.reaction_offset + 4 * n_cgroups + g];
          reaction_work_ahead[g] =
            values[sums.reaction_offset + 5 * n_cgroups + g];
        }
      for (unsigned int g = 0; g < n_groups; ++g)
        {
          group_internal_energy[g] = values[sums.group_offset + g];
          group_motion[g].kinetic_energy =
            values[sums.group_offset + n_groups + 4 * g];
          for (unsigned int d = 0; d < 3; ++d)
            group_motion[g].momentum[d] =
              values[sums.group_offset + n_groups + 4 * g + 1 + d];
          // Booked like the model's bulk-viscosity and gravity work.
          const double group_power =
            values[sums.group_offset + 5 * n_groups + g];
          group_work[g].bulk_viscosity +=
            group_viscous_work_ahead[g] +
            (started ? 0.5 * group_power * last_time_step : 0.);
          group_viscous_work_ahead[g] = 0.5 * group_power * new_step;
          group_work[g].gravity += values[sums.group_offset + 6 * n_groups + g];
        }
    }



    void
    ExplicitSolver::advance_bodies(const StepWeights &w)
    {
      const std::vector<double> &values = sums.values;
      const double half_step_time       = current_time + 0.5 * w.new_step;
      energy.rigid_kinetic              = 0.;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          RigidBody &body = bodies[b];
          for (unsigned int d = 0; d < 3; ++d)
            {
              body.contact_force[d]  = values[sums.body_offset + 6 * b + d];
              body.contact_moment[d] = values[sums.body_offset + 6 * b + 3 + d];
            }
          // A rigid part's sum holds its weight: the force of the rest of
          // the model on it is the remainder.
          if (body.carries_nodes)
            body.contact_force -= body.weight;
          // Where the body's motion is prescribed, the drive does the work
          // minus the solid's force on it times the displacement, by the
          // trapezoidal rule: the half with the force at t_n on the last
          // step's increment now (body.velocity is still the one of that
          // step; see advance_displacements()).
          for (unsigned int d = 0; d < 3; ++d)
            if (!body.moves_freely(d))
              {
                const double work = -0.5 * body.contact_force[d] *
                                    (last_time_step * body.velocity[d]);
                energy.external_work += work;
                body_energy[b].drive_work += work;
              }
          Tensor<1, 3>       v_new = body.velocity;
          const Tensor<1, 3> prescribed =
            body.prescribed_velocity ?
              body.prescribed_velocity(half_step_time) :
              Tensor<1, 3>();
          for (unsigned int d = 0; d < 3; ++d)
            if (!body.moves_freely(d))
              v_new[d] = prescribed[d];
            else if (body.carries_nodes)
              v_new[d] += w.average_step *
                          (body.contact_force[d] + body.weight[d]) / body.mass;
            else
              v_new[d] += w.average_step * (body.contact_force[d] / body.mass +
                                            settings.gravity[d]);
          const Tensor<1, 3> v_mean = w.old * body.velocity + w.next * v_new;
          double body_kinetic       = 0.5 * body.mass * v_mean.norm_square();
          body.velocity             = v_new;
          if (body.rotates())
            {
              // Angular momentum about the centre, spatial frame:
              // L^{n+1/2} = L^{n-1/2} + Dt^n M^n (kept, not recomputed from
              // the turning inertia, so a torque-free body keeps it
              // exactly), then w^{n+1/2} from L with the inertia at t_n,
              // I = R I_0 R^T, in the free directions (held ones stay 0;
              // their L is what the constraint leaves).
              const Tensor<2, 3> inertia =
                body.rotation * body.inertia * transpose(body.rotation);
              const Tensor<1, 3> w_previous = body.angular_velocity;
              body.angular_momentum += w.average_step * body.contact_moment;
              std::vector<unsigned int> free;
              for (unsigned int d = 0; d < 3; ++d)
                if (body.free_rotation[d])
                  free.push_back(d);
              FullMatrix<double> block(free.size(), free.size());
              Vector<double>     right(free.size()), w_free(free.size());
              for (unsigned int r = 0; r < free.size(); ++r)
                {
                  right(r) = body.angular_momentum[free[r]];
                  for (unsigned int c = 0; c < free.size(); ++c)
                    block(r, c) = inertia[free[r]][free[c]];
                }
              block.gauss_jordan();
              block.vmult(w_free, right);
              Tensor<1, 3> w_next;
              for (unsigned int r = 0; r < free.size(); ++r)
                w_next[free[r]] = w_free(r);
              // The held directions' momentum follows the motion.
              const Tensor<1, 3> L = inertia * w_next;
              for (unsigned int d = 0; d < 3; ++d)
                if (!body.free_rotation[d])
                  body.angular_momentum[d] = L[d];
              const Tensor<1, 3> w_mean = w.old * w_previous + w.next * w_next;
              body_kinetic += 0.5 * w_mean * (inertia * w_mean);
              body.angular_velocity = w_next;
            }
          energy.kinetic += body_kinetic;
          energy.rigid_kinetic += body_kinetic;
          body_energy[b].kinetic = body_kinetic;
          if (body.carries_nodes)
            for (const RigidPartNodes &part : rigid_parts)
              if (part.body == b)
                {
                  group_motion[part.group].kinetic_energy += body_kinetic;
                  group_motion[part.group].momentum += body.mass * v_mean;
                  break;
                }
        }
      set_rigid_node_velocities(w.new_step);
    }



    void
    ExplicitSolver::advance_displacements(const double new_step)
    {
      // A body that is held or driven in a direction does work on the
      // solid there: minus the solid's force on it times its displacement.
      // (A rigid part's gravity work is its nodes', booked below.)
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          RigidBody         &body      = bodies[b];
          const Tensor<1, 3> increment = new_step * body.velocity;
          body.displacement += increment;
          body.rotation = body.rotation_after(new_step);
          for (unsigned int d = 0; d < 3; ++d)
            if (!body.moves_freely(d))
              {
                // The half with the force at t_n; the other half, with the
                // force at t_{n+1}, when that is known.
                const double work = -0.5 * body.contact_force[d] * increment[d];
                energy.external_work += work;
                body_energy[b].drive_work += work;
              }
            else if (!body.carries_nodes)
              {
                const double work =
                  body.mass * settings.gravity[d] * increment[d];
                energy.external_work += work;
                body_energy[b].gravity_work += work;
              }
        }
      std::fill(group_gravity_increment.begin(),
                group_gravity_increment.end(),
                0.);
      const unsigned int n_owned      = partitioner->locally_owned_size();
      double             gravity_work = 0.;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double increment = new_step * v.local_element(i);
          u.local_element(i) += increment;
          const double work = gravity_force.local_element(i) * increment;
          gravity_work += work;
          group_gravity_increment[dof_group[i]] += work;
        }
      gravity_work_increment = gravity_work;
      // The dofs shared by several parts (the last entry): split by mass,
      // like their kinetic energy. A rigid part's are its own.
      for (const SharedDof &shared : shared_dofs)
        if (!rigid_dof[shared.dof])
          {
            const unsigned int i             = shared.dof;
            const double       work_per_mass = gravity_force.local_element(i) *
                                         new_step * v.local_element(i) *
                                         inverse_mass.local_element(i);
            for (unsigned int g = 0; g < settings.n_groups; ++g)
              group_gravity_increment[g] +=
                work_per_mass * shared.mass_by_group[g];
          }
    }



    void
    ExplicitSolver::run(const double                 end_time,
                        const std::function<void()> &monitor)
    {
      AssertThrow(!end_state_monitored,
                  ExcMessage("ExplicitSolver::run() after monitor_end_state(): "
                             "the velocities are past the end time"));
      if (!started)
        start();
      make_step_estimate();
      size_step_sums();
      auto clock = std::chrono::steady_clock::now();
      while (current_time < end_time * (1. - 1e-12))
        {
          // The assembled step estimate's probes before the step's own
          // evaluation, which overwrites what they leave in the elements.
          if (step_estimate && step_estimate->due(step_number))
            {
              lap(clock);
              refresh_step_estimate();
              timing.element_forces += lap(clock);
            }
          const StepWeights w = state_at_current_time(clock, monitor);
          advance_displacements(w.new_step);
          for (model::ForceContribution *contribution : contributions)
            contribution->accept_step();
          timing.vector_updates += lap(clock);
          u.update_ghost_values();
          v.update_ghost_values();
          timing.communication += lap(clock);

          current_time += w.new_step;
          ++step_number;
          started = true;
        }
    }



    void
    ExplicitSolver::size_step_sums()
    {
      sums.reinit(bodies.size(),
                  constraints ? constraints->n_groups() : 0,
                  settings.n_groups,
                  shared_dofs.size());
    }



    void
    ExplicitSolver::monitor_end_state(const std::function<void()> &monitor)
    {
      AssertThrow(started && !end_state_monitored,
                  ExcMessage("monitor_end_state() once, after run()"));
      size_step_sums();
      auto clock = std::chrono::steady_clock::now();
      state_at_current_time(clock, monitor);
      end_state_monitored = true;
    }



    ExplicitSolver::StepWeights
    ExplicitSolver::state_at_current_time(
      std::chrono::steady_clock::time_point &clock,
      const std::function<void()>           &monitor)
    {
      // Forces at u^n: -f_int + f_contact + f_gravity + loads.
      lap(clock);
      evaluate_forces();
      clock = std::chrono::steady_clock::now();
      StepWeights w;
      w.new_step = next_time_step(clock);
      w.average_step =
        started ? 0.5 * (last_time_step + w.new_step) : 0.5 * w.new_step;
      w.old  = started ? 0.5 : 1.;
      w.next = started ? 0.5 : 0.;

      // The solid's velocities to t_{n+1/2}, the constraints' reactions.
      advance_velocities(w);
      apply_constraints(w);
      if (mass_scaling)
        add_scaled_kinetic_energy(w);
      add_shared_dofs_motion(w);
      timing.vector_updates += lap(clock);
      sum_over_ranks();
      timing.communication += lap(clock);

      // The energies at t_n, the bodies to t_{n+1/2}.
      book_sums(w.new_step);
      advance_bodies(w);
      energy.largest_energy =
        std::max(energy.largest_energy, energy.current_scale());
      energy.largest_deformable =
        std::max(energy.largest_deformable, energy.deformable_scale());

      // Output sees the state at t_n and the step about to be taken.
      last_time_step = w.new_step;
      lap(clock);
      monitor();
      timing.output += lap(clock);
      return w;
    }
  } // namespace time_integration
} // namespace rubberdyn
