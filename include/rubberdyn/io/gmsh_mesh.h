#ifndef rubberdyn_io_gmsh_mesh_h
#define rubberdyn_io_gmsh_mesh_h

#include <string>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace rubberdyn
{
  namespace io
  {
    /**
     * Read the hexahedral mesh in the Gmsh file @p file_name into the empty
     * @p triangulation, after checking the whole file, so that a bad file
     * gives one readable InputError instead of a deal.II assertion, a crash
     * or a silently wrong mesh.
     *
     * <h4>What the file may contain</h4>
     * Gmsh's ASCII format 2.2 (`gmsh -format msh22`, or
     * `Mesh.MshFileVersion = 2.2;` in the .geo) or 4.1 (Gmsh's default);
     * binary files are refused. Elements: hexahedra (the cells; at least
     * one), quadrangles (boundary faces that carry a physical surface tag),
     * and points and lines, which are ignored. Any other element
     * (triangles, tetrahedra, prisms, pyramids, second-order elements)
     * is refused with its element number.
     *
     * <h4>Tag convention</h4>
     * - The physical volume tag of a hexahedron becomes its material id.
     *   Every hexahedron must have one (tag >= 1).
     * - The physical surface tag of a quadrangle becomes the boundary id of
     *   the boundary face it covers. Boundary faces that no tagged
     *   quadrangle covers get deal.II's default boundary id 0, so a
     *   physical surface may not use the tag 0 (it would be
     *   indistinguishable from them): number physical surfaces from 1. A
     *   tagged quadrangle must be a boundary face of exactly one
     *   hexahedron, and each face may be tagged once (in Gmsh: a surface in
     *   at most one physical group).
     * - Tags range from 1 to 2147483647 (Gmsh's tags are `int`; deal.II
     *   9.4's material and boundary ids are `unsigned int`, with the
     *   largest value reserved).
     * No manifold is attached: every face is flat (bilinear), as meshed.
     *
     * <h4>What is checked</h4>
     * Sections ($MeshFormat first; $Nodes and $Elements present once;
     * every $Section closed by its $EndSection), the counts they announce,
     * numbers (integers where Gmsh writes integers, finite reals),
     * unique node tags, that every node an element uses is defined, element
     * types and node counts, physical tags as above, duplicate hexahedra or
     * quadrangles (a volume or surface in two physical groups), and the
     * orientation of each hexahedron: its Jacobian must be positive at all
     * eight corners, as Gmsh writes them. Only then is the file handed to
     * deal.II's GridIn::read_msh(std::istream &), stripped of points and
     * lines; any exception deal.II still throws becomes an InputError.
     *
     * Bodies whose nodes coincide but are distinct (e.g. two blocks that
     * touch at a corner or an edge) stay apart: the stream reader does not
     * merge nodes, unlike GridIn::read_msh(const std::string &), which goes
     * through the Gmsh API (which in deal.II 9.4 also drops the physical
     * tags).
     *
     * @param triangulation Serial or parallel::distributed; must be empty.
     *   With MPI every rank reads the whole file.
     * @param file_name The Gmsh file; named in every error message.
     * @param entry_path The parameter that named the file (e.g.
     *   `Mesh/Mesh file`), the entry of the InputError.
     *
     * @throws InputError with the message "<file_name>: line N: what is
     *   wrong" (or "<file_name>: what is wrong" where no line applies).
     */
    void
    read_gmsh_mesh(dealii::Triangulation<3, 3> &triangulation,
                   const std::string           &file_name,
                   const std::string           &entry_path);
  } // namespace io
} // namespace rubberdyn

#endif
