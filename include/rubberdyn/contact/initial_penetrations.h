#ifndef rubberdyn_contact_initial_penetrations_h
#define rubberdyn_contact_initial_penetrations_h

namespace rubberdyn
{
  namespace model
  {
    class Model;
  }

  namespace contact
  {
    /**
     * Check the contact pairs and rigid surfaces of @p model for slave
     * nodes that start inside their master surface, and act as each
     * interaction's `Initial penetration` asks (parameters::
     * InitialPenetration): report, move the nodes out, or refuse. Called
     * by every simulation before it builds anything from the mesh; only
     * the first call on a model does the work (the hand-off's explicit
     * run finds the mesh its load path started from), and it stores the
     * reports in Model::initial_penetrations. Collective.
     *
     * <h3>What counts</h3>
     * A penalty contact that starts penetrated by g pushes with eps A g at
     * its first evaluation and puts eps A g^2 / 2 into the model that no
     * load paid for (the newcomer's block of issue 43: 0.3 mm of overlap,
     * 11.9 kN at t = 0 and 130 times the impact energy). A node counts if
     * its penetration, minus its gap, exceeds 1e-9 of the model's size
     * (the diagonal of the mesh's bounding box): faces that coincide in
     * the mesh give gaps of the integrals' round-off. For a frictionless
     * or Coulomb pair the gap is the mortar pair's own, the mean normal
     * gap g_a of each slave node (MortarContactPair::slave_node_gaps();
     * of both sides for two-pass and self-contact pairs); for a rigid
     * surface the distance of each boundary node from the surface
     * (RigidSurfaceContact::gap_and_normal()). Tied pairs keep their
     * initial offset, penetration included, and are not checked.
     *
     * <h3>Moving the slave nodes out</h3>
     * A rigid surface's nodes move by -g along its normal, onto it. A
     * pair's node a moves by g_a n_a, back along its own normal, the
     * direction the pair measures its gap in (the master's normal where
     * the faces are parallel); the mean gaps couple neighbouring nodes
     * (a node's gap is a mean over its facets), so the pair is evaluated
     * again at the moved positions and the nodes still in (by more than
     * the tolerance) moved again, up to 100 times. The moves change the
     * mesh's vertices (the reference configuration: stress free, as
     * LS-DYNA moves its slave nodes at t = 0), once, after every
     * interaction is done; the interactions are treated in order (pairs,
     * then rigid surfaces), each at the positions the earlier ones left.
     *
     * @throws InputError naming `Contact pairs/<name>/Initial penetration`
     *   or `Contact/Initial penetration` (with the surface's name) for
     *   `refuse`, with the count, the largest penetration and where; and
     *   for `move slave nodes out`, if a node to move belongs to a rigid
     *   part, if a move exceeds half the shortest edge of a cell at the
     *   node (the element would fold), or if the pair's nodes are still in
     *   after 100 moves.
     */
    void
    resolve_initial_penetrations(model::Model &model);
  } // namespace contact
} // namespace rubberdyn

#endif
