#ifndef rubberdyn_postprocess_time_history_plot_h
#define rubberdyn_postprocess_time_history_plot_h

// Plain C++17 on purpose: no deal.II here, so that this header and its
// source compile in a moment and the plotter can be used anywhere.

#include <string>
#include <vector>

namespace rubberdyn
{
  namespace postprocess
  {
    /**
     * One panel of the figure: a title, a y-axis label (with unit) and the
     * CSV column names drawn in it.
     */
    struct PlotPanel
    {
      /** Title drawn above the panel; may be empty. */
      std::string title;

      /** Label of the y axis, with its unit, e.g. "energy (J)"; may be empty.
       */
      std::string y_label;

      /** Names of the CSV columns drawn in this panel, in legend order. */
      std::vector<std::string> columns;
    };



    /**
     * The @p columns that end with one of @p suffixes, in their order: what
     * a panel of a kind of quantity shows.
     */
    std::vector<std::string>
    columns_ending_with(const std::vector<std::string> &columns,
                        const std::vector<std::string> &suffixes);

    /** The suffixes of the force columns (`_force`, `_force_x/_y/_z`). */
    inline const std::vector<std::string> force_suffixes = {"_force",
                                                            "_force_x",
                                                            "_force_y",
                                                            "_force_z"};

    /**
     * Tick marks of one axis: "nice" values, 1, 2 or 5 times a power of ten
     * apart, that lie inside a given range, each with its label.
     */
    struct AxisTicks
    {
      /** Distance between neighbouring ticks; 0 if there are no ticks. */
      double step = 0.;

      /**
       * The tick values, increasing, all inside the range. Each is computed
       * as an integer times the step (never by repeated addition), so that
       * it is the double nearest to the decimal number it stands for.
       */
      std::vector<double> values;

      /**
       * One label per value, with as few digits as the step needs: `0.3`,
       * never `0.30000000000000004`; `0`, never `-0`. Values of magnitude
       * 10^6 and above and steps below 10^-4 are written in compact
       * scientific notation, e.g. `1.2e6`, `-5e-7`.
       */
      std::vector<std::string> labels;
    };



    /**
     * Nice tick values inside [@p min, @p max]: the step is the raw step
     * (@p max - @p min) / @p n_target rounded to 1, 2 or 5 times a power of
     * ten (P. S. Heckbert, "Nice numbers for graph labels", Graphics Gems,
     * 1990: a raw mantissa below 1.5 gives 1, below 3 gives 2, below 7
     * gives 5, otherwise 10), and the ticks are the multiples of the step
     * in the range, so that there are about @p n_target of them (the range
     * holds between 0.6 and 1.5 times @p n_target steps). For example, 0
     * to 9.7 gives 0, 2, 4, 6, 8.
     *
     * A range that is empty, of zero width or not finite gives no ticks.
     */
    AxisTicks
    nice_ticks(const double       min,
               const double       max,
               const unsigned int n_target = 5);



    /**
     * Read @p csv_path (header line of column names, then numeric rows; the
     * first column is the x axis, e.g. time in ms), and write an SVG with
     * the panels stacked vertically, sharing the x axis. Columns named in a
     * panel but absent from the file are skipped (a panel with none left is
     * left out). Throws std::runtime_error naming the file on a missing or
     * unreadable file.
     *
     * The figure: one frame per panel with nice ticks (nice_ticks()) and
     * light grid lines, the x tick labels and @p x_label under the bottom
     * panel, each panel's title above it and its legend to its right; the
     * curves are polylines in the colour-blind-safe palette of Okabe and
     * Ito (2008), dashed from the ninth curve of a panel on. The x axis
     * spans the data exactly, each y axis the data of its panel plus 5 %
     * on either side.
     *
     * Details:
     * - the first column is the x axis of every panel, not a curve: named
     *   in a panel, it is skipped like an absent column;
     * - numbers are read and written independently of the C locale;
     * - a cell that is empty, not a number, NaN or infinite breaks its
     *   curve there (a point with no neighbour on either side is drawn as
     *   a dot); a row whose x is not finite breaks every curve;
     * - constant columns, a single row or no rows give an axis of nonzero
     *   width around the value;
     * - each curve is thinned to at most four points (first, minimum,
     *   maximum, last) per pixel column of the plot, more columns wide if
     *   the figure has very many curves, which draws the same picture at
     *   the figure's resolution and keeps single-row peaks; the file stays
     *   under 1 MB whatever the number of rows (unless the curves break at
     *   tens of thousands of places: each piece is drawn);
     * - names are escaped for XML; the output is the same, byte for byte,
     *   for the same input.
     *
     * Also throws std::runtime_error naming the file if the CSV file has no
     * header line, if none of the requested columns is in it, or if
     * @p svg_path cannot be written.
     */
    void
    write_time_history_plot(const std::string            &csv_path,
                            const std::string            &svg_path,
                            const std::vector<PlotPanel> &panels,
                            const std::string &x_label = "time (ms)");
  } // namespace postprocess
} // namespace rubberdyn

#endif
