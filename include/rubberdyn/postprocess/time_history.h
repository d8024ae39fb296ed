#ifndef rubberdyn_postprocess_time_history_h
#define rubberdyn_postprocess_time_history_h

#include <cstdio>
#include <iosfwd>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace postprocess
  {
    /**
     * The file time_history.csv: a header of column names and one row per
     * output time, written by rank 0 only. It counts its rows, so that a
     * restart keeps exactly the rows that were written before its
     * checkpoint (by count, never by reparsing printed times), and it can
     * be made durable (flushed and synced to disk) before a checkpoint is
     * committed: a run killed after a checkpoint has all rows up to it on
     * disk.
     */
    class TimeHistory
    {
    public:
      /**
       * Start @p path anew with @p columns as header (rank 0: @p active).
       */
      TimeHistory(const std::string &             path,
                  const std::vector<std::string> &columns,
                  const bool                      active);

      /**
       * Continue @p path after a restart: keep its header and first
       * @p n_rows rows, drop the rest (rows the interrupted run wrote after
       * its checkpoint).
       *
       * @throws std::runtime_error naming the file if it has fewer rows or
       *   another header.
       */
      TimeHistory(const std::string &             path,
                  const std::vector<std::string> &columns,
                  const bool                      active,
                  const unsigned long             n_rows);

      ~TimeHistory();

      TimeHistory(const TimeHistory &) = delete;
      TimeHistory &
      operator=(const TimeHistory &) = delete;

      /** Append a row (9 significant digits); returns its text. */
      std::string
      write_row(const std::vector<double> &values);

      /** Flush and fsync the file (before a checkpoint is committed). */
      void
      make_durable();

      /** Rows written so far (including those kept on a restart). */
      unsigned long
      n_rows() const
      {
        return rows;
      }

      /** The header line (without newline). */
      static std::string
      header(const std::vector<std::string> &columns);

    private:
      std::string   path;
      std::FILE *   file = nullptr;
      unsigned long rows = 0;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
