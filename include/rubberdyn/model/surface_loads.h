#ifndef rubberdyn_model_surface_loads_h
#define rubberdyn_model_surface_loads_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/model/force_contribution.h>
#include <rubberdyn/model/model.h>

#include <array>
#include <functional>
#include <iosfwd>
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
  namespace model
  {
    /**
     * Distributed loads on boundary faces as a force contribution: any
     * number of boundary conditions of type `traction` or `pressure`, each
     * on a set of boundary ids. The faces are the bilinear boundary faces of
     * the trilinear hexahedra, integrated with the 2 x 2 Gauss rule on the
     * unit square, $(\xi_q, \eta_q)$ with weights $w_q = 1/4$, and the face
     * shape functions $N_a$ (bilinear, a = 0..3).
     *
     * <b>Traction</b> (dead load per reference area, GPa = kN/mm^2): the
     * vector $\mathbf t(\mathbf X, t)$ in the listed components (the others
     * are zero) gives the nodal forces
     * @f[
     *   \mathbf f_a = \int_{\Gamma_0} N_a\, \mathbf t\, dA
     *     \approx \sum_q N_a(\xi_q, \eta_q)\, \mathbf t(\mathbf X_q, t)\,
     *       \bigl|\mathbf X_{,\xi} \times \mathbf X_{,\eta}\bigr|_q\, w_q .
     * @f]
     * The weights $N_a w_q |\mathbf X_{,\xi} \times \mathbf X_{,\eta}|_q$ are
     * computed once. A traction that does not depend on x, y, z is evaluated
     * once per step and scaled by each node's $\int N_a\, dA$; otherwise at
     * the four quadrature points of every face.
     *
     * <b>Pressure</b> (follower load, GPa; positive when it pushes on the
     * surface): the scalar $p(\mathbf X, t)$ acts on the current surface,
     * $\mathbf x = \mathbf X + \mathbf u$, against its outward normal,
     * @f[
     *   \mathbf f_a = -\int_{\Gamma} p\, N_a\, \mathbf n\, da
     *     = -\int_0^1\!\!\int_0^1 p\, N_a\,
     *       (\mathbf x_{,\xi} \times \mathbf x_{,\eta})\, d\xi\, d\eta
     *     \approx -\sum_q p(\mathbf X_q, t)\, N_a(\xi_q, \eta_q)\,
     *       (\mathbf x_{,\xi} \times \mathbf x_{,\eta})_q\, w_q ,
     * @f]
     * with $\mathbf x_{,\xi} = \sum_a N_{a,\xi}\, \mathbf x_a$ from the
     * current nodal positions (the discretised virtual work of a follower
     * pressure, e.g. Bonet & Wood, Nonlinear Continuum Mechanics for Finite
     * Element Analysis, 2nd ed., 2008, ch. 8). For a uniform pressure the
     * integrand is a polynomial of degree 2 in each of $\xi$, $\eta$, so the
     * 2 x 2 rule is exact: the resultant is $-p$ times the vector area of
     * the deformed bilinear face. The face's vertices are taken in
     * GeometryInfo<3>::face_to_cell_vertices order, whose $\xi \times \eta$
     * normal points out of the cell on some faces and into it on others; at
     * set-up every face is checked against the direction from the cell's
     * centre to the face's centre in the reference configuration, and its
     * vertices 1 and 2 are swapped (which swaps $\xi$ and $\eta$ and turns
     * the normal) where needed. The per-step cost is proportional to the
     * number of loaded faces.
     *
     * <b>Work.</b> The contribution books the loads' work on the solid in
     * ContributionResults::external_work, by the trapezoidal rule over each
     * step, like the energies at $t_n$:
     * @f[
     *   W^n = \tfrac12 (\mathbf f^{n-1} + \mathbf f^n) \cdot
     *     (\mathbf u^n - \mathbf u^{n-1})
     * @f]
     * over the loaded nodes; it keeps $\mathbf f^{n-1}$ and
     * $\mathbf u^{n-1}$ of the loaded nodes (written by save(), so that a
     * restart continues identically). The first evaluation books nothing.
     *
     * The loads are taken on the boundary faces of the locally owned cells,
     * which touch ghost nodes: they are written as resisting forces
     * (Accumulation::internal_ghosted), i.e. minus the load, and the
     * integrator compresses and negates. Each rank's nodal sums over its own
     * faces are partial at nodes shared with other ranks; every sum over
     * nodes (work, resultant, moment) is therefore a sum over faces, and
     * its sum over ranks counts every face once.
     */
    class SurfaceLoads : public ForceContribution
    {
    public:
      /** The resultant of one load on the body. */
      struct Resultant
      {
        /** Sum of the nodal forces (kN). */
        Tensor<1, 3> force;
        /**
         * Sum of $(\mathbf x_a - \mathbf p) \times \mathbf f_a$ about the
         * condition's moment point $\mathbf p$ (kN mm), with the nodes'
         * current positions $\mathbf x_a = \mathbf X_a + \mathbf u_a$.
         */
        Tensor<1, 3> moment;
      };

      /**
       * Find the faces of every load on the locally owned cells and
       * precompute their weights.
       *
       * @param dof_handler The solid's DoFHandler (FESystem(FE_Q(1), 3)).
       * @param partitioner The layout of the solver's vectors.
       * @param conditions Boundary conditions of type pressure or traction
       *   (copied; their functions are kept): for traction one function per
       *   entry of `components`, for pressure one function (`components` is
       *   not used).
       *
       * @throws InputError naming the condition if no face on any rank has
       *   one of its boundary ids, or if the functions do not fit the type.
       */
      SurfaceLoads(
        const DoFHandler<3, 3>                                   &dof_handler,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
        const std::vector<BoundaryCondition>                     &conditions);

      std::string
      name() const override;

      /** Accumulation::internal_ghosted (see the class documentation). */
      Accumulation
      accumulation() const override;

      /**
       * Add minus the loads' nodal forces at the current displacement and
       * time to @p f (owned and ghost entries) and their work over the last
       * step to `results.external_work`.
       */
      void
      add_forces(const EvaluationPoint &point,
                 VectorType            &f,
                 ContributionResults   &results) override;

      /** Yes: the loads are static, and their tangent is add_tangents(). */
      bool
      supports_implicit() const override;

      /** Whether no pressure is among the loads (tractions add no tangent). */
      bool
      symmetric_tangent() const override;

      /**
       * The load stiffness of the pressures (a traction is a dead load and
       * adds nothing): per face, with $\mathbf a_q = \mathbf x_{,\xi} \times
       * \mathbf x_{,\eta}$ and the resisting force $\mathbf r_a = \sum_q
       * p\, N_a w_q\, \mathbf a_q$,
       * @f[
       *   \frac{\partial \mathbf r_a}{\partial \mathbf x_b} = \sum_q p\, N_a
       *   w_q \bigl( N_{b,\eta} [\mathbf x_{,\xi}]_\times - N_{b,\xi}
       *   [\mathbf x_{,\eta}]_\times \bigr),
       * @f]
       * $[\mathbf v]_\times \mathbf w = \mathbf v \times \mathbf w$: one
       * 12 x 12 block per face, not symmetric on its own (it is symmetric
       * summed over a closed surface under a uniform pressure: Bonet & Wood
       * (2008), section 8.4).
       */
      void
      add_tangents(const EvaluationPoint &point,
                   const TangentBlock    &add) const override;

      /** Keep the last evaluation's forces and displacements for the work. */
      void
      accept_step() override;

      /** Write the forces and displacements kept for the work. */
      void
      save(std::ostream &out) const override;

      /** Read what save() wrote. */
      void
      load(std::istream &in) override;

      /** Number of loads (conditions). */
      unsigned int
      n_loads() const
      {
        return loads.size();
      }

      /** Number of this rank's faces of load @p l. */
      unsigned int
      n_local_faces(const unsigned int l) const;

      /**
       * The resultant force and moment of every load at the last evaluation
       * (or the one a checkpoint was written after), summed over all ranks:
       * collective on the partitioner's communicator; meant for output times
       * only, it costs one reduction.
       */
      std::vector<Resultant>
      resultants() const;

      /**
       * The work (J) each load has done on the solid up to the last
       * evaluation (its share of the external work), summed over all ranks
       * (collective).
       */
      std::vector<double>
      works() const;

    private:
      /** One load and its faces on this rank. */
      struct Load
      {
        std::string                                                  name;
        BoundaryCondition::Type                                      type;
        std::vector<unsigned int>                                    components;
        std::vector<std::function<double(const Point<3> &, double)>> functions;
        bool     depends_on_position = false;
        Point<3> moment_point;
        /**
         * Work on this rank's faces up to the last accepted step, and that
         * of the last evaluation (J).
         */
        double work = 0., work_pending = 0.;

        /** Local vector indices of the x, y, z dofs of each node. */
        std::vector<std::array<unsigned int, 3>> node_dofs;
        /** Reference position of each node (mm). */
        std::vector<Point<3>> node_position;
        /**
         * The four nodes (indices into node_dofs) of each face, in an order
         * whose $\xi \times \eta$ normal points out of the body.
         */
        std::vector<std::array<unsigned int, 4>> face_nodes;
        /** Reference position of each face's quadrature points (mm). */
        std::vector<std::array<Point<3>, 4>> quadrature_points;
        /**
         * Traction: $N_a(\xi_q) w_q |\mathbf X_{,\xi} \times
         * \mathbf X_{,\eta}|_q$ of each face, index 4 q + a (mm^2).
         */
        std::vector<std::array<double, 16>> face_weights;
        /** Traction: $\int N_a\, dA$ of each node over its faces (mm^2). */
        std::vector<double> node_area;

        /** Nodal forces on the solid at the last evaluation, 3 per node. */
        std::vector<double> force;
        /** Nodal displacements at the last evaluation, 3 per node. */
        std::vector<double> displacement;
        /** The same at the accepted step before (for the work). */
        std::vector<double> previous_force, previous_displacement;
      };

      /** The nodal forces of @p load at @p point into load.force. */
      void
      evaluate(Load &load, const EvaluationPoint &point) const;

      // The steps of the constructor.

      /**
       * The load of boundary condition @p bc on the locally owned cells of
       * @p dof_handler, ready for evaluate().
       *
       * @throws InputError if @p bc is not a load, has the wrong number of
       *   functions or names no boundary face.
       */
      Load
      make_load(const DoFHandler<3, 3>  &dof_handler,
                const BoundaryCondition &bc) const;

      /**
       * The faces of @p load's boundary ids on the locally owned cells:
       * their nodes (every node once), reference positions, quadrature
       * points and weights.
       */
      void
      add_faces(const DoFHandler<3, 3>  &dof_handler,
                const BoundaryCondition &bc,
                Load                    &load) const;

      /**
       * The nodal areas of @p load, and the vectors of its evaluation;
       * drops what its evaluation does not need.
       */
      static void
      prepare_for_evaluation(Load &load);

      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      std::vector<Load>                                  loads;
      /** Whether previous_force and previous_displacement hold a step. */
      bool has_previous = false;
      /** $N_a(\xi_q) w_q$, index 4 q + a. */
      std::array<double, 16> shape_weight;
      /** $N_{a,\xi}$ and $N_{a,\eta}$ at the quadrature points, 4 q + a. */
      std::array<double, 16> shape_d_xi, shape_d_eta;
    };
  } // namespace model
} // namespace rubberdyn

#endif
