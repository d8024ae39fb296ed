#include <deal.II/base/utilities.h>

#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/base/durable_files.h>
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/simulation/preload.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace rubberdyn
{
  namespace simulation
  {
    using namespace model;

    namespace
    {
      // (2: with the contacts' friction states; 3: with the poses of the
      // rigid parts in equilibrium; 4: the material history in blocks of 8
      // elements, internal::lanes, instead of 4.)
      constexpr char preload_magic[8] = "RDYNPL4";
      /** Doubles per rigid part pose: part, centre, displacement, R. */
      constexpr unsigned int pose_size = 16;

      /** The entries only the explicit run reads. */
      bool
      explicit_only(const std::string &line, const bool with_gravity)
      {
        static const char *const names[] = {"Initial velocity",
                                            "Initial angular velocity",
                                            "Density",
                                            "Mass",
                                            "Free directions",
                                            "Velocity function",
                                            "Time step scale factor",
                                            "Minimum time step",
                                            "Mass scaling time step",
                                            "Selective mass scaling time step",
                                            "Selective mass scaling tolerance",
                                            "Bulk viscosity linear",
                                            "Bulk viscosity quadratic",
                                            "Segment reuse slip"};
        // "set <name> = <value>", the name padded to a common width.
        const auto equals = line.find('=');
        if (line.rfind("set ", 0) != 0 || equals == std::string::npos)
          return false;
        const std::string entry =
          dealii::Utilities::trim(line.substr(4, equals - 4));
        for (const char *name : names)
          if (entry == name)
            return !(with_gravity && entry == "Density");
        return false;
      }
    } // namespace



    std::string
    preload_parameters_text(const std::string &model_parameters,
                            const bool         with_gravity)
    {
      std::istringstream lines(model_parameters);
      std::string        line, text;
      while (std::getline(lines, line))
        if (!explicit_only(line, with_gravity))
          text += line + '\n';
      return text;
    }



    void
    write_preload(const PreloadState &state,
                  const std::string  &directory,
                  const std::string  &parameters,
                  const MPI_Comm      comm)
    {
      namespace fs                 = std::filesystem;
      const std::string  entry     = "Time integration/Scheme";
      const unsigned int rank      = dealii::Utilities::MPI::this_mpi_process(comm);
      const std::string  new_directory = directory + ".new";
      std::string        error;
      durable_files::create_empty_directory(new_directory, comm, entry);
      try
        {
          std::ostringstream out;
          out.write(preload_magic, sizeof(preload_magic));
          const unsigned int n_owned =
            state.displacement.get_partitioner()->locally_owned_size();
          binary_io::write_doubles(out, state.displacement.begin(), n_owned);
          binary_io::write_doubles(out,
                                   state.history.data(),
                                   state.history.size());
          binary_io::write_doubles(out,
                                   state.shortenings.data(),
                                   state.shortenings.size());
          binary_io::write_doubles(out,
                                   state.section_forces.data(),
                                   state.section_forces.size());
          for (const std::vector<double> &contact : state.contact_states)
            binary_io::write_doubles(out, contact.data(), contact.size());
          // (Two records: their number, then the poses.)
          const double n_poses = state.rigid_part_poses.size();
          binary_io::write_doubles(out, &n_poses, 1);
          std::vector<double> poses;
          for (const RigidPartPose &pose : state.rigid_part_poses)
            {
              poses.push_back(pose.part);
              for (unsigned int d = 0; d < 3; ++d)
                poses.push_back(pose.centre[d]);
              for (unsigned int d = 0; d < 3; ++d)
                poses.push_back(pose.displacement[d]);
              for (unsigned int d = 0; d < 3; ++d)
                for (unsigned int e = 0; e < 3; ++e)
                  poses.push_back(pose.rotation[d][e]);
            }
          binary_io::write_doubles(out, poses.data(), poses.size());
          durable_files::write(new_directory + "/rank_" +
                                 std::to_string(rank) + ".bin",
                               out.str());
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
      durable_files::throw_if_any(comm, entry, error);
      if (rank == 0)
        try
          {
            std::ostringstream text;
            text << std::setprecision(17) << "time " << state.time << '\n'
                 << "ranks " << dealii::Utilities::MPI::n_mpi_processes(comm)
                 << '\n'
                 << "preload parameters\n"
                 << parameters;
            durable_files::write(new_directory + "/preload.txt", text.str());
            durable_files::sync_directory(new_directory);
            fs::remove_all(directory);
            fs::rename(new_directory, directory);
            durable_files::sync_directory(
              fs::path(directory).parent_path().string());
          }
        catch (const std::exception &e)
          {
            error = e.what();
          }
      durable_files::throw_if_any(comm, entry, error);
    }



    PreloadState
    read_preload(
      const std::string                                        &directory,
      const std::string                                        &parameters,
      const std::shared_ptr<const dealii::Utilities::MPI::Partitioner> &partitioner,
      const std::size_t                                         history_size,
      const unsigned int                                        n_sections,
      const std::vector<std::size_t>                           &contact_state_sizes,
      const MPI_Comm                                            comm)
    {
      const std::string entry = "Output/Restart from checkpoint";
      PreloadState      state;
      std::string       error;
      try
        {
          const std::string path = directory + "/preload.txt";
          std::ifstream     text(path);
          if (!text)
            throw InputError(entry,
                             "there is no preload checkpoint in " + directory +
                               " (written by a 'quasi-static then explicit' "
                               "run)");
          std::string  key[2], line, stored;
          unsigned int ranks = 0;
          text >> key[0] >> state.time >> key[1] >> ranks;
          std::getline(text, line);
          std::getline(text, line);
          if (!text || key[0] != "time" || key[1] != "ranks" ||
              line != "preload parameters")
            throw InputError(entry, path + " is damaged");
          while (std::getline(text, line))
            stored += line + '\n';
          if (stored != parameters)
            {
              const auto [here, there] =
                parameter_tools::first_difference(parameters, stored);
              throw InputError(entry,
                               "the model differs from the preload's in " +
                                 directory + " ('" + here + "' here, '" +
                                 there +
                                 "' there); only the explicit run's entries "
                                 "(End time, initial velocities, densities "
                                 "without gravity, explicit step settings) "
                                 "and the Output settings may change");
            }
          if (ranks != dealii::Utilities::MPI::n_mpi_processes(comm))
            throw InputError(entry,
                             "the preload in " + directory +
                               " was written by " + std::to_string(ranks) +
                               " ranks; run with as many");
          const unsigned int rank =
            dealii::Utilities::MPI::this_mpi_process(comm);
          std::ifstream in(directory + "/rank_" + std::to_string(rank) +
                             ".bin",
                           std::ios::binary);
          char magic[sizeof(preload_magic)] = {};
          in.read(magic, sizeof(magic));
          if (!in || std::string(magic) != preload_magic)
            throw InputError(entry,
                             "rank " + std::to_string(rank) +
                               "'s file of the preload in " + directory +
                               " is missing or damaged");
          state.displacement.reinit(partitioner);
          state.history.resize(history_size);
          state.shortenings.resize(n_sections);
          state.section_forces.resize(n_sections);
          binary_io::read_doubles(in,
                                  state.displacement.begin(),
                                  partitioner->locally_owned_size(),
                                  "displacements");
          binary_io::read_doubles(in,
                                  state.history.data(),
                                  history_size,
                                  "material history");
          binary_io::read_doubles(in,
                                  state.shortenings.data(),
                                  n_sections,
                                  "section shortenings");
          binary_io::read_doubles(in,
                                  state.section_forces.data(),
                                  n_sections,
                                  "section forces");
          for (const std::size_t size : contact_state_sizes)
            {
              state.contact_states.emplace_back(size);
              binary_io::read_doubles(in,
                                      state.contact_states.back().data(),
                                      size,
                                      "contact states");
            }
          double n_poses = 0.;
          binary_io::read_doubles(in, &n_poses, 1, "rigid part poses");
          if (!(n_poses >= 0. && n_poses < 1e6))
            throw CheckpointError("the number of rigid part poses is damaged");
          std::vector<double> poses(pose_size * std::size_t(n_poses));
          binary_io::read_doubles(in,
                                  poses.data(),
                                  poses.size(),
                                  "rigid part poses");
          for (std::size_t k = 0; k < std::size_t(n_poses); ++k)
            {
              const double  *values = &poses[pose_size * k];
              RigidPartPose pose;
              pose.part = static_cast<unsigned int>(values[0]);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  pose.centre[d]     = values[1 + d];
                  pose.displacement[d] = values[4 + d];
                  for (unsigned int e = 0; e < 3; ++e)
                    pose.rotation[d][e] = values[7 + 3 * d + e];
                }
              state.rigid_part_poses.push_back(pose);
            }
        }
      catch (const InputError &e)
        {
          error = e.message;
        }
      catch (const CheckpointError &e)
        {
          error = std::string("the preload in ") + directory +
                  " does not fit this model: " + e.what();
        }
      durable_files::throw_if_any(comm, entry, error);
      state.displacement.update_ghost_values();
      return state;
    }
  } // namespace simulation
} // namespace rubberdyn
