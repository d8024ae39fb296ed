#include <rubberdyn/base/durable_files.h>
#include <rubberdyn/base/exceptions.h>

#include <cstdio>
#include <filesystem>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace rubberdyn
{
  namespace durable_files
  {
    void
    write(const std::string &path, const std::string &data)
    {
      std::FILE *file = std::fopen(path.c_str(), "wb");
      if (file == nullptr)
        throw std::runtime_error("cannot write " + path);
      const bool written =
        std::fwrite(data.data(), 1, data.size(), file) == data.size() &&
        std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
      std::fclose(file);
      if (!written)
        throw std::runtime_error("cannot write " + path);
    }



    void
    sync_directory(const std::string &path)
    {
      const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY);
      if (fd >= 0)
        {
          ::fsync(fd);
          ::close(fd);
        }
    }



    void
    create_empty_directory(const std::string &directory,
                           const MPI_Comm     comm,
                           const std::string &entry)
    {
      std::string error;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        try
          {
            std::filesystem::remove_all(directory);
            std::filesystem::create_directories(directory);
          }
        catch (const std::exception &e)
          {
            error = e.what();
          }
      throw_if_any(comm, entry, error);
    }



    void
    throw_if_any(const MPI_Comm     comm,
                 const std::string &entry,
                 const std::string &message)
    {
      for (const std::string &m : dealii::Utilities::MPI::all_gather(comm, message))
        if (!m.empty())
          throw InputError(entry, m);
    }
  } // namespace durable_files
} // namespace rubberdyn
