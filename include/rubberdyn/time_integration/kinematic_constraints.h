#ifndef rubberdyn_time_integration_kinematic_constraints_h
#define rubberdyn_time_integration_kinematic_constraints_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/types.h>

#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  namespace time_integration
  {
    using namespace dealii;

    /**
     * Prescribed velocities of the nodes on boundaries, by boundary id: a
     * fixed boundary, a velocity given as a function of time in one
     * direction, or a symmetry plane normal to a coordinate axis (zero normal
     * velocity, free tangential motion). Each call adds one named group; the
     * explicit solver overwrites the groups' velocities every step and
     * reports the reaction force of each group (the force the constraint
     * exerts on the solid) and its work in the energy balance.
     *
     * A node on two groups gets the velocity of the later one in the
     * direction both prescribe.
     */
    class KinematicConstraints
    {
    public:
      /**
       * @param dof_handler Distributed FESystem(FE_Q(1), 3) handler.
       * @param partitioner Its vector partitioner (owned + ghost dofs).
       */
      KinematicConstraints(
        const DoFHandler<3, 3> &                                   dof_handler,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner);

      /**
       * Velocity @p velocity(t) (mm/ms) in direction @p direction (0, 1, 2)
       * for the nodes on boundary @p boundary_id.
       *
       * @throws InputError naming @p name if no cell of the mesh (on any
       *   rank) has a face with this boundary id.
       */
      void
      prescribe_velocity(const std::string &                  name,
                         const types::boundary_id             boundary_id,
                         const unsigned int                   direction,
                         const std::function<double(double)> &velocity);

      /**
       * All three velocity components zero on @p boundary_id: three
       * groups, named @p name + "/x", "/y", "/z".
       */
      void
      fix(const std::string &name, const types::boundary_id boundary_id);

      /**
       * A symmetry plane: zero velocity in @p normal_direction on
       * @p boundary_id, whose faces must lie in one plane normal to that
       * axis (checked: otherwise an InputError naming @p name).
       */
      void
      symmetry_plane(const std::string &      name,
                     const types::boundary_id boundary_id,
                     const unsigned int       normal_direction);

      /** Names of the groups, in the order they were added. */
      std::vector<std::string>
      group_names() const;

      /** One constrained, locally owned degree of freedom. */
      struct Entry
      {
        /** Local index in the distributed vectors. */
        unsigned int dof;
        /** Its group. */
        unsigned int group;
      };

      /** The constrained locally owned dofs. */
      const std::vector<Entry> &
      entries() const
      {
        return constrained;
      }

      /** Prescribed velocity of @p group at time @p t (mm/ms). */
      double
      velocity(const unsigned int group, const double t) const
      {
        return velocities[group](t);
      }

      /** Number of groups. */
      unsigned int
      n_groups() const
      {
        return velocities.size();
      }

    private:
      /**
       * The locally owned dofs of direction @p direction on
       * @p boundary_id; appends the coordinate @p direction of the vertices
       * of this rank's faces on it to @p coordinates.
       */
      std::vector<unsigned int>
      boundary_dofs(const types::boundary_id boundary_id,
                    const unsigned int       direction,
                    std::vector<double> *    coordinates) const;

      void
      add_group(const std::string &                  name,
                const std::vector<unsigned int> &    dofs,
                const std::function<double(double)> &velocity);

      const DoFHandler<3, 3> &                           dof_handler;
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      std::vector<std::string>                           names;
      std::vector<std::function<double(double)>>         velocities;
      std::vector<Entry>                                 constrained;
      /** Index in `constrained` of each constrained dof. */
      std::unordered_map<unsigned int, unsigned int>     entry_of_dof;
    };
  } // namespace time_integration
} // namespace rubberdyn

#endif
