#ifndef rubberdyn_base_binary_io_h
#define rubberdyn_base_binary_io_h

#include <cstddef>
#include <iosfwd>
#include <stdexcept>
#include <string>

namespace rubberdyn
{
  /**
   * A checkpoint that cannot be read or does not fit the model. The
   * message says which values and why.
   */
  class CheckpointError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * Binary records of checkpoints: a count followed by the values, so that
   * a reader can tell a checkpoint of another model from a damaged one.
   */
  namespace binary_io
  {
    /** Write @p n doubles with their count. */
    void
    write_doubles(std::ostream &out, const double *data, const std::size_t n);

    /**
     * Read @p n doubles written by write_doubles().
     *
     * @param what Names the values in the error message.
     * @throws CheckpointError if the stored count differs or the stream ends.
     */
    void
    read_doubles(std::istream &     in,
                 double *           data,
                 const std::size_t  n,
                 const std::string &what);
  } // namespace binary_io
} // namespace rubberdyn

#endif
