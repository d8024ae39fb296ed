#include <rubberdyn/base/binary_io.h>

#include <cstdint>
#include <istream>
#include <ostream>

namespace rubberdyn
{
  namespace binary_io
  {
    void
    write_doubles(std::ostream &out, const double *data, const std::size_t n)
    {
      const std::uint64_t size = n;
      out.write(reinterpret_cast<const char *>(&size), sizeof(size));
      out.write(reinterpret_cast<const char *>(data), n * sizeof(double));
    }



    void
    read_doubles(std::istream &     in,
                 double *           data,
                 const std::size_t  n,
                 const std::string &what)
    {
      std::uint64_t size = 0;
      in.read(reinterpret_cast<char *>(&size), sizeof(size));
      if (!in)
        throw CheckpointError("the checkpoint ends early (before " + what +
                              ")");
      if (size != n)
        throw CheckpointError("the checkpoint does not fit this model: it has " +
                              std::to_string(size) + " values of " + what +
                              ", the model " + std::to_string(n));
      in.read(reinterpret_cast<char *>(data), n * sizeof(double));
      if (!in)
        throw CheckpointError("the checkpoint ends early (in " + what + ")");
    }
  } // namespace binary_io
} // namespace rubberdyn
