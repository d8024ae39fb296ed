#ifndef rubberdyn_time_integration_kinematic_constraints_h
#define rubberdyn_time_integration_kinematic_constraints_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <functional>
#include <memory>
#include <set>
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
     * Prescribed motion of the nodes on boundaries, by boundary id: a
     * fixed boundary, a velocity or a displacement given as a function of
     * the reference position and time in one direction, or a symmetry
     * plane normal to a coordinate axis (zero normal velocity, free
     * tangential motion). Each call adds one named group (one direction);
     * the explicit solver overwrites the groups' half-step velocities every
     * step and reports the reaction force of each group (the force the
     * constraint exerts on the solid), its moment about the group's moment
     * point and its work in the energy balance.
     *
     * A dof may belong to one group only, unless two groups prescribe the
     * same motion there (e.g. two fixed faces sharing an edge): then the
     * first keeps it. Two groups that prescribe different motions of the
     * same dof are an InputError naming both.
     */
    class KinematicConstraints
    {
    public:
      /** What a group's function prescribes. */
      enum class Kind
      {
        /** The velocity (mm/ms) at the half step. */
        velocity,
        /** The displacement (mm) at the next full step. */
        displacement
      };

      /**
       * A prescribed value as a function of the reference position X (mm)
       * and time t (ms).
       */
      using Function = std::function<double(const Point<3> &X, double t)>;

      /**
       * @param dof_handler Distributed FESystem(FE_Q(1), 3) handler, or
       *   FESystem(FE_Q(2), 3) (the mixed u-p element): then every node of
       *   a face (vertices, edge midpoints, face centre) is constrained, at
       *   its support point.
       * @param partitioner Its vector partitioner (owned + ghost dofs).
       */
      KinematicConstraints(
        const DoFHandler<3, 3> &                                   dof_handler,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner);

      /**
       * Prescribe @p kind in direction @p direction (0, 1, 2) for the nodes
       * on the boundaries @p boundary_ids.
       *
       * @param depends_on_position Whether @p function uses X; if not, it is
       *   evaluated once per step for the whole group.
       * @param moment_point Point about which the reaction moment is
       *   reported (mm).
       * @throws InputError naming @p name if no face of the mesh (on any
       *   rank) has one of the boundary ids, or if a dof is already
       *   prescribed differently by another group.
       */
      void
      prescribe(const std::string &                 name,
                const std::set<types::boundary_id> &boundary_ids,
                const unsigned int                  direction,
                const Kind                          kind,
                const Function &                    function,
                const bool                          depends_on_position,
                const Point<3> &                    moment_point = Point<3>());

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
       * Hold every node of the cells with @p material_ids at zero
       * displacement in @p direction (a group of zero velocity, named
       * @p name): a rigid part that stands still on a quasi-static load
       * path.
       *
       * @throws InputError naming @p name if no cell has one of the ids,
       *   or if a node is already prescribed differently by another group.
       */
      void
      hold_cells(const std::string                  &name,
                 const std::set<types::material_id> &material_ids,
                 const unsigned int                  direction);

      /**
       * A symmetry plane: zero velocity in @p normal_direction on
       * @p boundary_id, whose faces must lie in one plane normal to that
       * axis (checked: otherwise an InputError naming @p name).
       */
      void
      symmetry_plane(const std::string &      name,
                     const types::boundary_id boundary_id,
                     const unsigned int       normal_direction);

      /**
       * The direction normal to the plane of the faces on @p boundary_ids,
       * which must be one plane normal to a coordinate axis.
       *
       * @throws InputError naming @p name otherwise.
       */
      unsigned int
      plane_normal_direction(
        const std::string &                 name,
        const std::set<types::boundary_id> &boundary_ids) const;

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
        /** Local indices of the x, y, z dofs of its node. */
        unsigned int node_dofs[3];
        /** Reference position of its node (mm). */
        Point<3> X;
      };

      /** The constrained locally owned dofs. */
      const std::vector<Entry> &
      entries() const
      {
        return constrained;
      }

      /**
       * Evaluate the groups that do not depend on position for the step
       * from @p time (t_n) with size @p time_step: call before
       * half_step_velocity() on every step.
       */
      void
      begin_step(const double time, const double time_step) const;

      /**
       * The velocity (mm/ms) of @p entry on the half step from t_n to
       * t_n + dt, for the step begun by begin_step(): a velocity group's
       * value at the half step, a displacement group's (g(X, t_n + dt) -
       * u_n) / dt with @p displacement the current u_n of the dof.
       */
      double
      half_step_velocity(const Entry &entry, const double displacement) const;

      /**
       * The velocity (mm/ms) of @p entry at t = 0: a velocity group's value,
       * a displacement group's time derivative (by a finite difference).
       */
      double
      initial_velocity(const Entry &entry) const;

      /** Prescribed velocity of @p group at time @p t (mm/ms), for
       * position-independent velocity groups. */
      double
      velocity(const unsigned int group, const double t) const;

      /** What group @p group prescribes. */
      Kind
      kind(const unsigned int group) const
      {
        return groups[group].kind;
      }

      /**
       * The displacement (mm) at time @p t that @p entry's group prescribes
       * at its node, for a displacement group (the quasi-static solver's
       * load path); for a velocity group, the value of its velocity
       * function instead (mm/ms).
       */
      double
      prescribed_function_value(const Entry &entry, const double t) const
      {
        return prescribed_value(groups[entry.group], entry.X, t);
      }

      /** Number of groups. */
      unsigned int
      n_groups() const
      {
        return groups.size();
      }

      /** The moment point of @p group (mm). */
      const Point<3> &
      moment_point(const unsigned int group) const
      {
        return groups[group].moment_point;
      }

    private:
      struct Group
      {
        std::string name;
        Kind        kind;
        Function    function;
        bool        depends_on_position;
        Point<3>    moment_point;
        /** This step's value (position-independent groups). */
        mutable double step_value = 0.;
      };

      /**
       * The entry of group @p group for the cell dof @p i (of the cell's
       * @p dof_indices, locally owned) whose node is at @p X.
       */
      Entry
      node_entry(const std::vector<types::global_dof_index> &dof_indices,
                 const unsigned int                          i,
                 const unsigned int                          group,
                 const Point<3>                             &X) const;

      /**
       * The locally owned dofs of direction @p direction on the faces with
       * @p boundary_ids, as entries of group @p group; appends the
       * vertices of this rank's faces on them to @p vertices.
       */
      std::vector<Entry>
      boundary_entries(const std::set<types::boundary_id> &boundary_ids,
                       const unsigned int                  direction,
                       const unsigned int                  group,
                       std::vector<Point<3>> *             vertices) const;

      /**
       * The locally owned dofs of direction @p direction of the cells with
       * @p material_ids (every node: vertices, and for FE_Q(2) edge, face
       * and cell nodes), as entries of group @p group; sets @p n_cells to
       * the number of such cells on this rank.
       */
      std::vector<Entry>
      cell_entries(const std::set<types::material_id> &material_ids,
                   const unsigned int                  direction,
                   const unsigned int                  group,
                   unsigned int                       &n_cells) const;

      /**
       * Add group @p group (already in `groups`) with its @p entries: a
       * dof claimed before keeps its first group if both prescribe the
       * same motion; otherwise an InputError naming the group.
       */
      void
      add_entries(const unsigned int group, const std::vector<Entry> &entries);

      /** The value group @p g prescribes at @p X, time t. */
      double
      prescribed_value(const Group &g, const Point<3> &X, const double t) const;

      const DoFHandler<3, 3> &                           dof_handler;
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      std::vector<Group>                                 groups;
      std::vector<Entry>                                 constrained;
      /** Index in `constrained` of each constrained dof. */
      std::unordered_map<unsigned int, unsigned int>     entry_of_dof;
      /** t_n and dt of the step begun by begin_step(). */
      mutable double step_time = 0., step_size = 0.;
    };
  } // namespace time_integration
} // namespace rubberdyn

#endif
