#ifndef rubberdyn_postprocess_history_nodes_h
#define rubberdyn_postprocess_history_nodes_h

#include <deal.II/base/partitioner.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/parameters/output_parameters.h>
#include <rubberdyn/postprocess/postprocessor.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace model
  {
    class Model;
  }

  namespace postprocess
  {
    /**
     * The displacement of named mesh nodes as history columns
     * (`Output/History nodes`; LS-DYNA's *DATABASE_HISTORY_NODE): for each,
     * `<name>_displacement_x`, `_y`, `_z` (mm). Each point must coincide
     * with a mesh vertex (within 1e-6 of the mesh's bounding-box diagonal):
     * a history of "the nearest node" would silently follow another point
     * than the user meant. Where touching parts have nodes of their own at
     * the same point (a sleeve's end on a brace), the node names its part;
     * without one such a point is refused, not given to whichever part
     * comes first. Used by every scheme: the explicit run through
     * HistoryNodeColumns, the quasi-static run directly.
     */
    class HistoryNodes
    {
    public:
      /**
       * Find the vertex of each node among the locally owned cells of the
       * model (of its part, if it names one), and the rank that owns its
       * dofs.
       *
       * @throws InputError naming `Output/History nodes` and the node if no
       *   vertex of the mesh (of the part) lies at its point (with the
       *   distance to the nearest one and where it is), if the point is a
       *   vertex of two nodes (parts with nodes of their own there; the
       *   message names the parts), or if its part is not one of the
       *   model's.
       */
      HistoryNodes(const model::Model                                 &model,
                   const std::vector<parameters::Output::HistoryNode> &nodes);

      /** The columns, three per node. */
      std::vector<std::string>
      columns() const;

      /**
       * Append the displacements of the nodes in @p u (mm) to @p values:
       * collective (a sum over the ranks, each node given by its owner).
       */
      void
      append_values(const VectorType &u, std::vector<double> &values) const;

    private:
      std::vector<std::string> names;
      /**
       * Local vector indices of the x, y, z dofs of each node on the rank
       * that owns them; numbers::invalid_unsigned_int elsewhere.
       */
      std::vector<std::array<unsigned int, 3>> owned_dofs;
    };



    /**
     * HistoryNodes as a postprocessor of the explicit run: the columns of
     * the solver's displacement at every history row.
     */
    class HistoryNodeColumns : public Postprocessor
    {
    public:
      explicit HistoryNodeColumns(std::unique_ptr<HistoryNodes> nodes);

      std::string
      name() const override;

      std::vector<std::string>
      history_columns() const override;

      void
      history_values(const SimulationView &view,
                     std::vector<double>  &values) override;

    private:
      std::unique_ptr<HistoryNodes> nodes;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
