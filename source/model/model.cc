#include <deal.II/fe/fe_q.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/model/model.h>

#include <map>

#include <stdexcept>

namespace rubberdyn
{
  namespace model
  {
    Model::Model(const MPI_Comm comm)
      : comm(comm)
      , triangulation(comm)
      , fe(FE_Q<3>(1), 3)
      , fe_quadratic(FE_Q<3>(2), 3)
      , dof_handler(triangulation)
    {}



    unsigned int
    Model::part_index(const std::string &name) const
    {
      for (unsigned int p = 0; p < parts.size(); ++p)
        if (parts[p].name == name)
          return p;
      throw std::invalid_argument("the model has no part named '" + name +
                                  "'");
    }



    unsigned int
    Model::part_of_material_id(const types::material_id material_id) const
    {
      for (unsigned int p = 0; p < parts.size(); ++p)
        if (parts[p].material_ids.count(material_id) > 0)
          return p;
      return numbers::invalid_unsigned_int;
    }



    std::set<types::boundary_id>
    Model::boundary_ids_in_mesh() const
    {
      std::vector<types::boundary_id> local;
      for (const types::boundary_id id : triangulation.get_boundary_ids())
        local.push_back(id);
      std::set<types::boundary_id> all;
      for (const std::vector<types::boundary_id> &ids :
           Utilities::MPI::all_gather(comm, local))
        all.insert(ids.begin(), ids.end());
      return all;
    }



    void
    Model::setup()
    {
      // Each material id in one part, every cell's id in some part.
      std::map<types::material_id, unsigned int> owner;
      for (unsigned int p = 0; p < parts.size(); ++p)
        for (const types::material_id id : parts[p].material_ids)
          {
            const auto existing = owner.find(id);
            if (existing != owner.end())
              throw InputError("Parts/" + parts[p].name + "/Material ids",
                               "material id " + std::to_string(id) +
                                 " is also in part '" +
                                 parts[existing->second].name +
                                 "'; every cell belongs to exactly one part");
            owner[id] = p;
          }
      std::set<types::material_id> orphans;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() &&
            owner.find(cell->material_id()) == owner.end())
          orphans.insert(cell->material_id());
      std::vector<types::material_id> local(orphans.begin(), orphans.end());
      std::set<types::material_id>    all;
      for (const auto &ids : Utilities::MPI::all_gather(comm, local))
        all.insert(ids.begin(), ids.end());
      if (!all.empty())
        throw InputError("Parts/Names",
                         "the mesh has cells of material id " +
                           std::to_string(*all.begin()) +
                           " (a physical volume tag) that is in no part; "
                           "list it in the 'Material ids' of one part");
      // The mixed u-p element for all deformable parts or for none: it
      // needs Q2 dofs, which the Q1 elements cannot share.
      const Part *mixed = nullptr, *other = nullptr;
      for (const Part &part : parts)
        {
          if (part.rigid)
            continue;
          const Part *&first =
            part.formulation == Formulation::mixed_up ? mixed : other;
          if (first == nullptr)
            first = &part;
        }
      if (mixed != nullptr && other != nullptr)
        throw InputError("Parts/" + other->name + "/Element formulation",
                         "the part '" + mixed->name +
                           "' uses 'mixed u-p' and this part does not; a "
                           "model uses the mixed u-p element for all its "
                           "deformable parts or for none");
      mixed_up = (mixed != nullptr);
      dof_handler.distribute_dofs(mixed_up ? fe_quadratic : fe);
      partitioner = ghosted_partitioner(dof_handler);
    }
  } // namespace model
} // namespace rubberdyn
