#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/postprocess/field_output_writer.h>
#include <rubberdyn/time_integration/explicit_solver.h>

namespace rubberdyn
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      /**
       * The smallest J = det(I + grad u) at the Gauss points and at the
       * centres of all elements (trilinear geometry, as the elements use),
       * over all ranks. Collective; meant for output times, not every step.
       */
      std::pair<double, double>
      minimum_jacobian(const DoFHandler<3> &dof_handler,
                       const VectorType &   u,
                       const MPI_Comm       comm)
      {
        const FEValuesExtractors::Vector displacement(0);
        FEValues<3> gauss(dof_handler.get_fe(), QGauss<3>(2), update_gradients);
        FEValues<3> centre(dof_handler.get_fe(),
                           QMidpoint<3>(),
                           update_gradients);
        const Tensor<2, 3>        identity = unit_symmetric_tensor<3>();
        std::vector<Tensor<2, 3>> gradients(8), centre_gradient(1);
        double min_gauss  = std::numeric_limits<double>::max();
        double min_centre = min_gauss;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              gauss.reinit(cell);
              gauss[displacement].get_function_gradients(u, gradients);
              for (const Tensor<2, 3> &H : gradients)
                min_gauss = std::min(min_gauss, determinant(identity + H));
              centre.reinit(cell);
              centre[displacement].get_function_gradients(u, centre_gradient);
              min_centre =
                std::min(min_centre, determinant(identity + centre_gradient[0]));
            }
        double values[2] = {min_gauss, min_centre};
        Utilities::MPI::min(ArrayView<const double>(values, 2),
                            comm,
                            ArrayView<double>(values, 2));
        return {values[0], values[1]};
      }
    } // namespace



    FieldOutputWriter::FieldOutputWriter(const std::string &       directory,
                                         const std::string &       basename,
                                         const FieldOutput::Format format,
                                         const double              interval,
                                         const MPI_Comm            comm)
      : fields(directory, basename, comm, format)
      , interval(interval)
      , comm(comm)
    {}



    std::string
    FieldOutputWriter::name() const
    {
      return "field output";
    }



    void
    FieldOutputWriter::after_step(const SimulationView &view)
    {
      if (interval > 0. &&
          view.time() >= next_output * (1. - 1e-12))
        {
          write(view);
          next_output += interval;
        }
    }



    void
    FieldOutputWriter::finish(const SimulationView &view)
    {
      // (The end state's after_step() may have written it already.)
      if (last_output_time != view.time())
        write(view);
    }



    std::vector<std::pair<std::string, std::vector<float>>>
    solid_cell_data(const model::Model               &model,
                    const elements::ImplicitElements &elements,
                    const VectorType                 &u)
    {
      const unsigned int n_active = model.triangulation.n_active_cells();
      const auto         averages = elements.cell_averages(u, n_active);
      const char *names[6] = {"cauchy_stress_xx", "cauchy_stress_yy",
                              "cauchy_stress_zz", "cauchy_stress_xy",
                              "cauchy_stress_xz", "cauchy_stress_yz"};
      std::vector<std::pair<std::string, std::vector<float>>> cell_data;
      for (unsigned int k = 0; k < 6; ++k)
        cell_data.emplace_back(names[k], averages.cauchy_stress[k]);
      cell_data.emplace_back("von_mises_stress", averages.von_mises);
      cell_data.emplace_back("pressure", averages.pressure);
      cell_data.emplace_back("J", averages.jacobian);
      cell_data.emplace_back("equivalent_plastic_strain",
                             averages.equivalent_plastic_strain);
      std::vector<float> part_id(n_active, 0.f), material_id(n_active, 0.f);
      for (const auto &cell : model.triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            part_id[cell->active_cell_index()] =
              model.part_of_material_id(cell->material_id());
            material_id[cell->active_cell_index()] = cell->material_id();
          }
      cell_data.emplace_back("part_id", part_id);
      cell_data.emplace_back("material_id", material_id);
      return cell_data;
    }



    void
    FieldOutputWriter::add_nodal_scalars(
      const std::array<std::string, 3>        &names,
      const std::function<void(VectorType &)> &fill)
    {
      nodal_scalar_sources.emplace_back(names, fill);
    }



    void
    FieldOutputWriter::write(const SimulationView &view)
    {
      const model::Model &model = view.model();
      const auto          cell_data =
        solid_cell_data(model, view.elements(), view.displacement());
      std::vector<VectorType>                scalar_values(
        nodal_scalar_sources.size());
      std::vector<NodalScalars>              nodal_scalars;
      for (unsigned int s = 0; s < nodal_scalar_sources.size(); ++s)
        {
          scalar_values[s].reinit(model.partitioner);
          nodal_scalar_sources[s].second(scalar_values[s]);
          scalar_values[s].update_ghost_values();
          nodal_scalars.push_back(
            {nodal_scalar_sources[s].first, &scalar_values[s]});
        }
      fields.write(model.dof_handler, view.displacement(),
                   explicit_solver_of(view, name()).velocity(), cell_data,
                   view.time(), nodal_scalars);
      last_output_time = view.time();

      const auto now = minimum_jacobian(model.dof_handler,
                                        view.displacement(), comm);
      if (now.first < min_jacobian_gauss_points)
        time_of_min_jacobian = view.time();
      min_jacobian_gauss_points = std::min(min_jacobian_gauss_points, now.first);
      min_jacobian_centres      = std::min(min_jacobian_centres, now.second);
    }



    void
    FieldOutputWriter::summary(const SimulationView &,
                               std::vector<SummaryEntry> &entries)
    {
      const auto text = [](const double value) {
        std::ostringstream s;
        s.precision(9);
        s << value;
        return s.str();
      };
      entries.emplace_back("min_jacobian_gauss_points",
                           text(min_jacobian_gauss_points));
      entries.emplace_back("min_jacobian_centres", text(min_jacobian_centres));
      entries.emplace_back("time_of_min_jacobian", text(time_of_min_jacobian));
    }



    void
    FieldOutputWriter::save(std::ostream &out) const
    {
      const double values[5] = {next_output, last_output_time,
                                min_jacobian_gauss_points, min_jacobian_centres,
                                time_of_min_jacobian};
      binary_io::write_doubles(out, values, 5);
    }



    void
    FieldOutputWriter::load(std::istream &in)
    {
      double values[5];
      binary_io::read_doubles(in, values, 5, "field output state");
      next_output               = values[0];
      last_output_time          = values[1];
      min_jacobian_gauss_points = values[2];
      min_jacobian_centres      = values[3];
      time_of_min_jacobian      = values[4];
    }



    std::string
    FieldOutputWriter::index_file() const
    {
      return fields.index_file();
    }
  } // namespace postprocess
} // namespace rubberdyn
