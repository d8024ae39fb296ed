#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>

#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/model/rigid_body.h>
#include <rubberdyn/postprocess/drop_test_monitor.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <map>
#include <ostream>
#include <sstream>

namespace rubberdyn
{
  namespace postprocess
  {
    using namespace dealii;

    FaceAverage::FaceAverage(const DoFHandler<3> &              dof_handler,
                             const Utilities::MPI::Partitioner &partitioner,
                             const types::boundary_id           boundary_id,
                             const MPI_Comm                     comm)
    {
      const FiniteElement<3> &fe = dof_handler.get_fe();
      FEFaceValues<3>         fe_face_values(fe,
                                     QGauss<2>(2),
                                     update_values | update_JxW_values);
      std::vector<types::global_dof_index>      dofs(fe.n_dofs_per_cell());
      std::map<types::global_dof_index, double> weight_of_dof;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == boundary_id)
              {
                fe_face_values.reinit(cell, f);
                cell->get_dof_indices(dofs);
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  if (fe.system_to_component_index(i).first == 2)
                    for (const unsigned int q :
                         fe_face_values.quadrature_point_indices())
                      weight_of_dof[dofs[i]] +=
                        fe_face_values.shape_value(i, q) *
                        fe_face_values.JxW(q);
              }
      double local_area = 0.;
      for (const auto &[dof, weight] : weight_of_dof)
        {
          local_indices.push_back(partitioner.global_to_local(dof));
          weights.push_back(weight);
          local_area += weight;
        }
      area = Utilities::MPI::sum(local_area, comm);
    }



    double
    FaceAverage::local_integral(const VectorType &u) const
    {
      double sum = 0.;
      for (unsigned int k = 0; k < weights.size(); ++k)
        sum += weights[k] * u.local_element(local_indices[k]);
      return sum;
    }



    DropTestMonitor::DropTestMonitor(
      const DoFHandler<3> &              dof_handler,
      const Utilities::MPI::Partitioner &partitioner,
      const types::boundary_id           top_face_id,
      const types::boundary_id           bottom_face_id,
      const unsigned int                 impactor,
      const bool                         stop_after_rebound,
      const double                       rebound_margin,
      const MPI_Comm                     comm)
      : top_face(dof_handler, partitioner, top_face_id, comm)
      , bottom_face(dof_handler, partitioner, bottom_face_id, comm)
      , impactor(impactor)
      , stop_after_rebound(stop_after_rebound)
      , rebound_margin(rebound_margin)
      , comm(comm)
    {}



    std::string
    DropTestMonitor::name() const
    {
      return "drop test";
    }



    std::vector<std::string>
    DropTestMonitor::history_columns() const
    {
      return {"impactor_displacement",
              "impactor_force",
              "rubber_top_displacement",
              "rubber_bottom_displacement",
              "friction_work"};
    }



    void
    DropTestMonitor::history_values(const SimulationView &view,
                                    std::vector<double> &  values)
    {
      // One MPI sum per row (never per step) for the two face probes.
      double face_integrals[2] = {
        top_face.local_integral(view.displacement()),
        bottom_face.local_integral(view.displacement())};
      Utilities::MPI::sum(ArrayView<const double>(face_integrals, 2),
                          comm,
                          ArrayView<double>(face_integrals, 2));
      const double top    = -face_integrals[0] / top_face.area;
      const double bottom = -face_integrals[1] / bottom_face.area;
      max_rubber_compression = std::max(max_rubber_compression, top - bottom);
      const model::RigidBody &body = view.bodies()[impactor];
      values.push_back(-body.displacement[2]);
      values.push_back(body.contact_force[2]);
      values.push_back(top);
      values.push_back(bottom);
      values.push_back(
        explicit_solver_of(view, name()).energies().friction_work);
    }



    void
    DropTestMonitor::after_step(const SimulationView &view)
    {
      const double            t    = view.time();
      const model::RigidBody &body = view.bodies()[impactor];
      max_force = std::max(max_force, body.contact_force[2]);
      if (-body.displacement[2] > max_displacement)
        {
          max_displacement         = -body.displacement[2];
          time_of_max_displacement = t;
        }
      // Every rank holds the same (reduced) impactor force and velocity,
      // so all ranks take the same decisions below.
      if (body.velocity[2] > 0.)
        rebounding = true;
      if (rebounding)
        {
          if (body.contact_force[2] > 0.)
            separation_time = -1.;
          else if (separation_time < 0.)
            {
              separation_time  = t;
              rebound_velocity = body.velocity[2];
            }
        }
      stop = stop_after_rebound && separation_time >= 0. &&
             t >= separation_time + rebound_margin;
    }



    bool
    DropTestMonitor::stop_requested() const
    {
      return stop;
    }



    void
    DropTestMonitor::summary(const SimulationView &     view,
                             std::vector<SummaryEntry> &entries)
    {
      const auto text = [](const double value) {
        std::ostringstream s;
        s.precision(9);
        s << value;
        return s.str();
      };
      entries.emplace_back("stopped_after_rebound", stop ? "true" : "false");
      entries.emplace_back("rubber_mass", text(explicit_solver_of(view, name()).physical_mass()));
      entries.emplace_back("top_face_area", text(top_face.area));
      entries.emplace_back("bottom_face_area", text(bottom_face.area));
      entries.emplace_back("max_impactor_force", text(max_force));
      entries.emplace_back("max_impactor_displacement", text(max_displacement));
      entries.emplace_back("time_of_max_impactor_displacement",
                           text(time_of_max_displacement));
      entries.emplace_back("max_rubber_compression",
                           text(max_rubber_compression));
      entries.emplace_back("separation_time",
                           separation_time >= 0. ? text(separation_time) :
                                                   std::string("null"));
      entries.emplace_back("rebound_velocity", text(rebound_velocity));
    }



    void
    DropTestMonitor::final_log(std::ostream &log) const
    {
      if (stop)
        log << "Stopped " << rebound_margin
            << " ms after the impactor left the rubber at t = "
            << separation_time << " ms, rebound velocity " << rebound_velocity
            << " mm/ms" << std::endl;
      log << "  Largest impactor force " << max_force
          << " kN, largest compression " << max_displacement << " mm"
          << std::endl;
    }



    void
    DropTestMonitor::save(std::ostream &out) const
    {
      const double values[8] = {max_force,
                                max_displacement,
                                time_of_max_displacement,
                                max_rubber_compression,
                                rebounding ? 1. : 0.,
                                separation_time,
                                rebound_velocity,
                                stop ? 1. : 0.};
      binary_io::write_doubles(out, values, 8);
    }



    void
    DropTestMonitor::load(std::istream &in)
    {
      double values[8];
      binary_io::read_doubles(in, values, 8, "drop-test monitor state");
      max_force                = values[0];
      max_displacement         = values[1];
      time_of_max_displacement = values[2];
      max_rubber_compression   = values[3];
      rebounding               = values[4] != 0.;
      separation_time          = values[5];
      rebound_velocity         = values[6];
      stop                     = values[7] != 0.;
    }
  } // namespace postprocess
} // namespace rubberdyn
