#ifndef rubberdyn_base_durable_files_h
#define rubberdyn_base_durable_files_h

#include <deal.II/base/mpi.h>

#include <string>

namespace rubberdyn
{
  /**
   * Files that must survive a crash (checkpoints, the preload), and the
   * rule that an error on one rank ends all of them.
   */
  namespace durable_files
  {
    /**
     * Write @p data to @p path and fsync it.
     *
     * @throws std::runtime_error naming the path if it cannot.
     */
    void
    write(const std::string &path, const std::string &data);

    /** fsync a directory, so that renames in it are durable. */
    void
    sync_directory(const std::string &path);

    /**
     * Make @p directory exist and be empty (rank 0 removes what is there and
     * creates it). Collective.
     *
     * @throws InputError naming @p entry on every rank if it cannot.
     */
    void
    create_empty_directory(const std::string &directory,
                           const MPI_Comm     comm,
                           const std::string &entry);

    /**
     * If any rank has a non-empty @p message, throw an InputError naming
     * @p entry with the first one, on every rank (a failure on one rank
     * must end all ranks, never leave the others waiting in a
     * collective). Collective.
     */
    void
    throw_if_any(const MPI_Comm     comm,
                 const std::string &entry,
                 const std::string &message);
  } // namespace durable_files
} // namespace rubberdyn

#endif
