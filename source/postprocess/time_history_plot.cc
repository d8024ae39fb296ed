// A dependency-free SVG plotter for time_history.csv (plain C++17; see the
// header for what the figure shows).
#include <rubberdyn/postprocess/time_history_plot.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace rubberdyn
{
  namespace postprocess
  {
    namespace
    {
      // ------------------------------------------------------------ numbers

      /** n times 10^e, as the double nearest to that decimal number. */
      double
      scaled(const double n, const int e)
      {
        double power = 1.;
        for (int i = 0; i < std::abs(e); ++i)
          power *= 10.;
        return e >= 0 ? n * power : n / power;
      }



      /**
       * The label of the tick n 10^e: the decimal digits of n with the
       * point moved by e, trailing zeros after the point removed; in
       * scientific notation (mantissa, 'e', exponent) if asked.
       */
      std::string
      tick_label(const long long n, const int e, const bool scientific)
      {
        if (n == 0)
          return "0";
        const std::string sign   = n < 0 ? "-" : "";
        std::string       digits = std::to_string(n < 0 ? -n : n);
        if (scientific)
          {
            const int   exponent = e + static_cast<int>(digits.size()) - 1;
            std::string mantissa = digits.substr(0, 1);
            std::string rest     = digits.substr(1);
            while (!rest.empty() && rest.back() == '0')
              rest.pop_back();
            if (!rest.empty())
              mantissa += "." + rest;
            return sign + mantissa + "e" + std::to_string(exponent);
          }
        if (e >= 0)
          return sign + digits + std::string(e, '0');
        const std::size_t n_decimals = -e;
        if (digits.size() <= n_decimals)
          digits = std::string(n_decimals + 1 - digits.size(), '0') + digits;
        std::string integer_part = digits.substr(0, digits.size() - n_decimals);
        std::string fraction     = digits.substr(digits.size() - n_decimals);
        while (!fraction.empty() && fraction.back() == '0')
          fraction.pop_back();
        return sign + integer_part + (fraction.empty() ? "" : "." + fraction);
      }



      /** A pixel coordinate with at most one decimal, "-0" written as "0". */
      void
      append_coordinate(std::string &out, const double value)
      {
        // to_chars, unlike printf, ignores the locale.
        char        buffer[64];
        const auto  result = std::to_chars(buffer,
                                          buffer + sizeof(buffer),
                                          value,
                                          std::chars_format::fixed,
                                          1);
        std::string text(buffer, result.ptr);
        if (text.size() > 2 && text.compare(text.size() - 2, 2, ".0") == 0)
          text.resize(text.size() - 2);
        if (text == "-0")
          text = "0";
        out += text;
      }



      std::string
      coordinate(const double value)
      {
        std::string text;
        append_coordinate(text, value);
        return text;
      }



      /** @p text with the five XML special characters escaped. */
      std::string
      escape_xml(const std::string &text)
      {
        std::string escaped;
        for (const char c : text)
          switch (c)
            {
              case '&':
                escaped += "&amp;";
                break;
              case '<':
                escaped += "&lt;";
                break;
              case '>':
                escaped += "&gt;";
                break;
              case '"':
                escaped += "&quot;";
                break;
              case '\'':
                escaped += "&apos;";
                break;
              default:
                escaped += c;
            }
        return escaped;
      }



      /**
       * A range that can be drawn: one of zero width (a constant column, a
       * single row) or of a width lost in the round-off of its values is
       * widened to 10 % of its value on either side, or to [-1, 1] around
       * zero; no finite values give [0, 1].
       */
      std::pair<double, double>
      drawable_range(double min, double max)
      {
        if (!(min <= max))
          return {0., 1.};
        const double magnitude = std::max(std::abs(min), std::abs(max));
        if (max - min <= 1e-9 * magnitude || !std::isfinite(max - min))
          {
            const double centre    = 0.5 * min + 0.5 * max;
            const double half_span = centre != 0. ? 0.1 * std::abs(centre) : 1.;
            return {centre - half_span, centre + half_span};
          }
        return {min, max};
      }



      // ----------------------------------------------------------- the CSV

      /** @p text without surrounding blanks, carriage returns and quotes. */
      std::string
      trim(const std::string &text)
      {
        std::size_t begin = 0, end = text.size();
        while (begin < end &&
               std::isspace(static_cast<unsigned char>(text[begin])))
          ++begin;
        while (end > begin &&
               std::isspace(static_cast<unsigned char>(text[end - 1])))
          --end;
        if (end - begin >= 2 && text[begin] == '"' && text[end - 1] == '"')
          {
            ++begin;
            --end;
          }
        return text.substr(begin, end - begin);
      }



      /** The number in [begin, end), or NaN if it is not exactly a number. */
      double
      parse_cell(const char *begin, const char *end)
      {
        while (begin < end && (*begin == ' ' || *begin == '\t'))
          ++begin;
        // from_chars, unlike strtod, ignores the locale, but it takes no
        // '+' sign.
        if (begin < end && *begin == '+')
          ++begin;
        double     value  = 0.;
        const auto result = std::from_chars(begin, end, value);
        if (result.ec != std::errc() || result.ptr == begin)
          return std::nan("");
        const char *stop = result.ptr;
        while (stop < end && std::isspace(static_cast<unsigned char>(*stop)))
          ++stop;
        return stop == end ? value : std::nan("");
      }



      /** The x column and the requested columns of a CSV file. */
      struct Table
      {
        /** The column names of the header. */
        std::vector<std::string> names;

        /** The first column. */
        std::vector<double> x;

        /** The values of each column that is drawn; others are empty. */
        std::vector<std::vector<double>> columns;

        /** The index of a column (the first of equal names), -1 if none. */
        int
        index(const std::string &name) const
        {
          const auto it = std::find(names.begin(), names.end(), name);
          return it == names.end() ? -1 : static_cast<int>(it - names.begin());
        }
      };



      Table
      read_table(const std::string            &csv_path,
                 const std::vector<PlotPanel> &panels)
      {
        std::ifstream in(csv_path, std::ios::binary);
        if (!in)
          throw std::runtime_error(csv_path +
                                   ": cannot open this file for reading");
        Table       table;
        std::string line;
        while (std::getline(in, line) && trim(line).empty())
          ;
        if (trim(line).empty())
          throw std::runtime_error(
            csv_path + ": no header line (expected the column names, "
                       "separated by commas)");
        if (line.compare(0, 3, "\xEF\xBB\xBF") == 0)
          line.erase(0, 3);
        std::size_t start = 0;
        while (true)
          {
            const std::size_t comma = line.find(',', start);
            table.names.push_back(trim(line.substr(start, comma - start)));
            if (comma == std::string::npos)
              break;
            start = comma + 1;
          }

        std::vector<bool> wanted(table.names.size(), false);
        for (const PlotPanel &panel : panels)
          for (const std::string &name : panel.columns)
            {
              const int i = table.index(name);
              if (i > 0)
                wanted[i] = true;
            }
        table.columns.resize(table.names.size());

        while (std::getline(in, line))
          {
            if (trim(line).empty())
              continue;
            const char *const end  = line.c_str() + line.size();
            const char       *cell = line.c_str();
            std::size_t       i    = 0;
            for (bool more = true; more && i < table.names.size(); ++i)
              {
                const char *const cell_end = std::find(cell, end, ',');
                if (i == 0 || wanted[i])
                  (i == 0 ? table.x : table.columns[i])
                    .push_back(parse_cell(cell, cell_end));
                more = cell_end < end;
                cell = cell_end + 1;
              }
            // A short row: the cells it lacks are missing values.
            for (; i < table.names.size(); ++i)
              if (wanted[i])
                table.columns[i].push_back(std::nan(""));
          }
        if (in.bad())
          throw std::runtime_error(csv_path + ": read error");
        return table;
      }



      // ------------------------------------------------------ the drawing

      // Okabe, M. and Ito, K. (2008), "Color universal design": the eight
      // colours of their colour-blind-safe set, ordered by contrast on
      // white (yellow, the weakest, last).
      constexpr std::array<const char *, 8> palette = {{"#0072B2",
                                                        "#D55E00",
                                                        "#009E73",
                                                        "#CC79A7",
                                                        "#E69F00",
                                                        "#56B4E9",
                                                        "#000000",
                                                        "#F0E442"}};

      // Layout in pixels. The widths of texts are estimated from their
      // lengths (DejaVu Sans: about 0.62 em per character).
      constexpr double font_size        = 12.;
      constexpr double char_width       = 0.62 * font_size;
      constexpr double plot_width       = 640.;
      constexpr double min_plot_height  = 200.;
      constexpr double title_height     = 30.;
      constexpr double untitled_gap     = 16.; // if no panel has a title
      constexpr double tick_length      = 4.;
      constexpr double legend_gap       = 16.;
      constexpr double legend_line      = 24.;
      constexpr double legend_row       = 18.;
      constexpr double outer_margin     = 10.;
      constexpr double max_total_points = 50000.;

      /** A curve of the figure: one column in one panel. */
      struct Curve
      {
        std::string name;
        int         column;
        std::string colour;
        bool        dashed;
      };

      /** A panel as it is drawn. */
      struct PanelLayout
      {
        const PlotPanel   *panel;
        std::vector<Curve> curves;
        double             y_min, y_max;
        AxisTicks          y_ticks;
        double             top, height;
      };

      /** A point in pixels and the row it comes from. */
      struct Pixel
      {
        std::size_t row;
        double      x, y;
      };



      /**
       * The pixels of one curve, thinned: for each bucket of pixel columns
       * the first, lowest, highest and last points in row order, which draw
       * the same picture (every vertical extent in every column is kept). A
       * non-finite value ends a polyline; a polyline of one point is a dot.
       */
      template <typename ToX, typename ToY>
      void
      draw_curve(std::string               &out,
                 const std::vector<double> &x,
                 const std::vector<double> &y,
                 const Curve               &curve,
                 const ToX                 &to_x,
                 const ToY                 &to_y,
                 const double               left,
                 const double               bucket_width)
      {
        std::vector<Pixel>   polyline;
        std::array<Pixel, 4> bucket{}; // first, lowest, highest, last
        bool                 bucket_used  = false;
        long long            bucket_index = 0;

        const auto flush_bucket = [&]() {
          if (!bucket_used)
            return;
          std::array<Pixel, 4> points = bucket;
          std::sort(points.begin(),
                    points.end(),
                    [](const Pixel &a, const Pixel &b) {
                      return a.row < b.row;
                    });
          for (unsigned int k = 0; k < 4; ++k)
            {
              if (k > 0 && points[k].row == points[k - 1].row)
                continue;
              // Points that round to the same tenth of a pixel are one.
              if (!polyline.empty() &&
                  std::llround(10. * polyline.back().x) ==
                    std::llround(10. * points[k].x) &&
                  std::llround(10. * polyline.back().y) ==
                    std::llround(10. * points[k].y))
                continue;
              polyline.push_back(points[k]);
            }
          bucket_used = false;
        };

        const auto end_polyline = [&]() {
          flush_bucket();
          if (polyline.size() == 1)
            {
              out += "<circle cx=\"";
              append_coordinate(out, polyline[0].x);
              out += "\" cy=\"";
              append_coordinate(out, polyline[0].y);
              out += "\" r=\"2\" fill=\"" + curve.colour +
                     "\" stroke=\"none\"><title>" + escape_xml(curve.name) +
                     "</title></circle>\n";
            }
          else if (polyline.size() > 1)
            {
              out += "<polyline stroke=\"" + curve.colour + "\"";
              if (curve.dashed)
                out += " stroke-dasharray=\"6 3\"";
              out += " points=\"";
              for (std::size_t k = 0; k < polyline.size(); ++k)
                {
                  if (k > 0)
                    out += ' ';
                  append_coordinate(out, polyline[k].x);
                  out += ',';
                  append_coordinate(out, polyline[k].y);
                }
              out +=
                "\"><title>" + escape_xml(curve.name) + "</title></polyline>\n";
            }
          polyline.clear();
        };

        for (std::size_t row = 0; row < x.size(); ++row)
          {
            if (!std::isfinite(x[row]) || !std::isfinite(y[row]))
              {
                end_polyline();
                continue;
              }
            const Pixel     p{row, to_x(x[row]), to_y(y[row])};
            const long long index =
              static_cast<long long>(std::floor((p.x - left) / bucket_width));
            if (bucket_used && index != bucket_index)
              flush_bucket();
            if (!bucket_used)
              {
                bucket       = {{p, p, p, p}};
                bucket_used  = true;
                bucket_index = index;
                continue;
              }
            // Pixel y grows downwards: the lowest value has the largest y.
            if (p.y > bucket[1].y)
              bucket[1] = p;
            if (p.y < bucket[2].y)
              bucket[2] = p;
            bucket[3] = p;
          }
        end_polyline();
      }



      void
      append_text(std::string       &out,
                  const double       x,
                  const double       y,
                  const std::string &text,
                  const std::string &attributes = "")
      {
        out += "<text x=\"" + coordinate(x) + "\" y=\"" + coordinate(y) + "\"";
        if (!attributes.empty())
          out += " " + attributes;
        out += ">" + escape_xml(text) + "</text>\n";
      }



      void
      append_line(std::string       &out,
                  const double       x1,
                  const double       y1,
                  const double       x2,
                  const double       y2,
                  const std::string &attributes = "")
      {
        out += "<line x1=\"" + coordinate(x1) + "\" y1=\"" + coordinate(y1) +
               "\" x2=\"" + coordinate(x2) + "\" y2=\"" + coordinate(y2) + "\"";
        if (!attributes.empty())
          out += " " + attributes;
        out += "/>\n";
      }



      /** A position on the pixel grid for a crisp one-pixel line. */
      double
      crisp(const double position)
      {
        return std::floor(position) + 0.5;
      }
    } // namespace



    AxisTicks
    nice_ticks(const double min, const double max, const unsigned int n_target)
    {
      AxisTicks ticks;
      if (!(std::isfinite(min) && std::isfinite(max) && max > min) ||
          n_target == 0)
        return ticks;
      const double raw = (max - min) / n_target;
      if (!std::isfinite(raw) || !(raw > 0.))
        return ticks;
      int    e        = static_cast<int>(std::floor(std::log10(raw)));
      double mantissa = raw / scaled(1., e);
      // log10 may round across a power of ten.
      if (mantissa < 1.)
        {
          --e;
          mantissa *= 10.;
        }
      else if (mantissa >= 10.)
        {
          ++e;
          mantissa /= 10.;
        }
      int m = 1;
      if (mantissa < 1.5)
        m = 1;
      else if (mantissa < 3.)
        m = 2;
      else if (mantissa < 7.)
        m = 5;
      else
        ++e;
      const double step = scaled(m, e);
      // A tick within round-off of an end of the range is inside it.
      const double k_min = std::ceil(min / step - 1e-9);
      const double k_max = std::floor(max / step + 1e-9);
      if (std::max(std::abs(k_min), std::abs(k_max)) * m > 1e15)
        return ticks;
      const bool scientific =
        std::max(std::abs(min), std::abs(max)) >= 1e6 || e < -4;
      ticks.step = step;
      for (long long k = static_cast<long long>(k_min);
           k <= static_cast<long long>(k_max);
           ++k)
        {
          ticks.values.push_back(scaled(static_cast<double>(k * m), e));
          ticks.labels.push_back(tick_label(k * m, e, scientific));
        }
      return ticks;
    }



    namespace
    {
      /** The horizontal layout all panels share, and the x axis. */
      struct Frame
      {
        /** Left edge of the plot area (px). */
        double left;
        /** Left edge of the legends (px). */
        double    legend_left;
        double    x_min, x_scale;
        AxisTicks x_ticks;
        /** Width of the thinning buckets (px). */
        double bucket_width;

        double
        to_x(const double x) const
        {
          return left + (x - x_min) * x_scale;
        }
      };



      /**
       * The panels that have at least one column of @p table, each with
       * its curves; @p n_curves counts the curves of all.
       */
      std::vector<PanelLayout>
      panels_with_data(const Table                  &table,
                       const std::vector<PlotPanel> &panels,
                       const std::string            &csv_path,
                       std::size_t                  &n_curves)
      {
        std::vector<PanelLayout> layouts;
        n_curves = 0;
        for (const PlotPanel &panel : panels)
          {
            PanelLayout layout{&panel, {}, 0., 0., {}, 0., 0.};
            for (const std::string &name : panel.columns)
              {
                const int column = table.index(name);
                if (column <= 0)
                  continue;
                const std::size_t k = layout.curves.size();
                layout.curves.push_back({name,
                                         column,
                                         palette[k % palette.size()],
                                         k >= palette.size()});
              }
            if (layout.curves.empty())
              continue;
            n_curves += layout.curves.size();
            layouts.push_back(layout);
          }
        if (layouts.empty())
          throw std::runtime_error(
            csv_path + ": none of the columns to plot is in this file");
        return layouts;
      }



      /**
       * Each panel's y axis: the range of its data plus 5 %, and its
       * ticks. Returns the longest tick label and curve name (characters),
       * which set the frame's margins.
       */
      std::pair<std::size_t, std::size_t>
      fit_y_axes(const Table &table, std::vector<PanelLayout> &layouts)
      {
        std::size_t max_tick_label = 1, max_name = 1;
        for (PanelLayout &layout : layouts)
          {
            double y_min = std::numeric_limits<double>::infinity();
            double y_max = -y_min;
            for (const Curve &curve : layout.curves)
              {
                const std::vector<double> &y = table.columns[curve.column];
                for (std::size_t row = 0; row < y.size(); ++row)
                  if (std::isfinite(y[row]) && std::isfinite(table.x[row]))
                    {
                      y_min = std::min(y_min, y[row]);
                      y_max = std::max(y_max, y[row]);
                    }
                max_name = std::max(max_name, curve.name.size());
              }
            if (y_min <= y_max)
              {
                std::tie(y_min, y_max) = drawable_range(y_min, y_max);
                const double margin    = 0.05 * (y_max - y_min);
                y_min -= margin;
                y_max += margin;
              }
            else
              std::tie(y_min, y_max) = drawable_range(y_min, y_max);
            layout.y_min   = y_min;
            layout.y_max   = y_max;
            layout.y_ticks = nice_ticks(y_min, y_max, 5);
            for (const std::string &label : layout.y_ticks.labels)
              max_tick_label = std::max(max_tick_label, label.size());
          }
        return {max_tick_label, max_name};
      }



      /**
       * Append one panel to @p out: grid, curves, frame and ticks, labels
       * and legend; the x tick labels and the x label below the @p last.
       */
      void
      draw_panel(std::string       &out,
                 const Table       &table,
                 const PanelLayout &layout,
                 const Frame       &frame,
                 const bool         last,
                 const std::string &x_label)
      {
        const double top = layout.top, bottom = top + layout.height;
        const double right = frame.left + plot_width;
        const auto   to_x  = [&frame](const double x) { return frame.to_x(x); };
        const double y_scale = layout.height / (layout.y_max - layout.y_min);
        const auto   to_y    = [&](const double value) {
          return bottom - (value - layout.y_min) * y_scale;
        };

        out += "<g class=\"panel\">\n";
        if (!layout.panel->title.empty())
          append_text(out,
                      frame.left,
                      top - 9.,
                      layout.panel->title,
                      "class=\"title\" font-size=\"13\" font-weight=\"bold\"");

        // Grid: light lines at the ticks, a darker one at y = 0.
        out += "<g class=\"grid\" stroke=\"#dddddd\" stroke-width=\"1\">\n";
        for (const double x : frame.x_ticks.values)
          append_line(out,
                      crisp(frame.to_x(x)),
                      top,
                      crisp(frame.to_x(x)),
                      bottom);
        for (const double value : layout.y_ticks.values)
          append_line(out,
                      frame.left,
                      crisp(to_y(value)),
                      right,
                      crisp(to_y(value)),
                      value == 0. ? "stroke=\"#999999\"" : "");
        out += "</g>\n";

        // Curves.
        out += "<g class=\"curves\" fill=\"none\" stroke-width=\"1.5\" "
               "stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
        for (const Curve &curve : layout.curves)
          draw_curve(out,
                     table.x,
                     table.columns[curve.column],
                     curve,
                     to_x,
                     to_y,
                     frame.left,
                     frame.bucket_width);
        out += "</g>\n";

        // Frame, ticks, tick labels.
        out += "<rect class=\"frame\" x=\"" + coordinate(crisp(frame.left)) +
               "\" y=\"" + coordinate(crisp(top)) + "\" width=\"" +
               coordinate(crisp(right) - crisp(frame.left)) + "\" height=\"" +
               coordinate(crisp(bottom) - crisp(top)) +
               "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
        out += "<g class=\"ticks\" stroke=\"#000000\" stroke-width=\"1\">\n";
        for (const double x : frame.x_ticks.values)
          append_line(out,
                      crisp(frame.to_x(x)),
                      crisp(bottom),
                      crisp(frame.to_x(x)),
                      crisp(bottom) + tick_length);
        for (const double value : layout.y_ticks.values)
          append_line(out,
                      crisp(frame.left) - tick_length,
                      crisp(to_y(value)),
                      crisp(frame.left),
                      crisp(to_y(value)));
        out += "</g>\n";
        // The labels are centred on the exact positions of their ticks:
        // 4 px below the centre is the baseline of 12 px digits.
        out += "<g class=\"y-tick-labels\" text-anchor=\"end\">\n";
        for (std::size_t k = 0; k < layout.y_ticks.values.size(); ++k)
          append_text(out,
                      frame.left - tick_length - 3.,
                      to_y(layout.y_ticks.values[k]) + 4.,
                      layout.y_ticks.labels[k]);
        out += "</g>\n";
        if (last)
          {
            out += "<g class=\"x-tick-labels\" text-anchor=\"middle\">\n";
            for (std::size_t k = 0; k < frame.x_ticks.values.size(); ++k)
              append_text(out,
                          frame.to_x(frame.x_ticks.values[k]),
                          bottom + tick_length + 14.,
                          frame.x_ticks.labels[k]);
            out += "</g>\n";
          }
        if (!layout.panel->y_label.empty())
          {
            const double label_x = outer_margin + 10.;
            const double label_y = 0.5 * (top + bottom);
            append_text(
              out,
              label_x,
              label_y,
              layout.panel->y_label,
              "class=\"y-label\" text-anchor=\"middle\" "
              "dominant-baseline=\"central\" transform=\"rotate(-90 " +
                coordinate(label_x) + " " + coordinate(label_y) + ")\"");
          }

        // Legend, to the right of the plot, top-aligned with it.
        out += "<g class=\"legend\">\n";
        for (std::size_t k = 0; k < layout.curves.size(); ++k)
          {
            const Curve &curve = layout.curves[k];
            const double row_y = top + 10. + legend_row * k;
            append_line(out,
                        frame.legend_left,
                        row_y,
                        frame.legend_left + legend_line,
                        row_y,
                        "stroke=\"" + curve.colour + "\" stroke-width=\"2\"" +
                          (curve.dashed ? " stroke-dasharray=\"6 3\"" : ""));
            append_text(out,
                        frame.legend_left + legend_line + 6.,
                        row_y + 4.,
                        curve.name);
          }
        out += "</g>\n";
        out += "</g>\n";

        if (last)
          append_text(out,
                      frame.left + 0.5 * plot_width,
                      bottom + tick_length + 18. + 18.,
                      x_label,
                      "class=\"x-label\" text-anchor=\"middle\"");
      }
    } // namespace



    std::vector<std::string>
    columns_ending_with(const std::vector<std::string> &columns,
                        const std::vector<std::string> &suffixes)
    {
      std::vector<std::string> result;
      for (const std::string &column : columns)
        for (const std::string &suffix : suffixes)
          if (column.size() >= suffix.size() &&
              column.compare(column.size() - suffix.size(),
                             suffix.size(),
                             suffix) == 0)
            {
              result.push_back(column);
              break;
            }
      return result;
    }



    void
    write_time_history_plot(const std::string            &csv_path,
                            const std::string            &svg_path,
                            const std::vector<PlotPanel> &panels,
                            const std::string            &x_label)
    {
      const Table              table    = read_table(csv_path, panels);
      std::size_t              n_curves = 0;
      std::vector<PanelLayout> layouts =
        panels_with_data(table, panels, csv_path, n_curves);

      // Axes: x spans the data, y the data of each panel plus 5 %.
      double x_min = std::numeric_limits<double>::infinity();
      double x_max = -x_min;
      for (const double x : table.x)
        if (std::isfinite(x))
          {
            x_min = std::min(x_min, x);
            x_max = std::max(x_max, x);
          }
      std::tie(x_min, x_max)                = drawable_range(x_min, x_max);
      const AxisTicks x_ticks               = nice_ticks(x_min, x_max, 6);
      const auto [max_tick_label, max_name] = fit_y_axes(table, layouts);

      // Layout: panels stacked, sharing the plot area's left and right.
      const bool any_y_label =
        std::any_of(layouts.begin(), layouts.end(), [](const PanelLayout &l) {
          return !l.panel->y_label.empty();
        });
      const bool any_title =
        std::any_of(layouts.begin(), layouts.end(), [](const PanelLayout &l) {
          return !l.panel->title.empty();
        });
      const double left =
        std::ceil(outer_margin + (any_y_label ? 20. : 0.) +
                  max_tick_label * char_width + tick_length + 6.);
      const double legend_left = left + plot_width + legend_gap;
      const double width       = std::ceil(legend_left + legend_line + 6. +
                                     max_name * char_width + outer_margin);
      double       y           = outer_margin;
      for (PanelLayout &layout : layouts)
        {
          layout.top = y + (any_title ? title_height : untitled_gap);
          layout.height =
            std::max(min_plot_height, legend_row * layout.curves.size() + 12.);
          y = layout.top + layout.height;
        }
      const double height = y + tick_length + 18. + 22. + outer_margin;

      const double x_scale = plot_width / (x_max - x_min);
      // Thin more coarsely if the figure has so many curves that four
      // points per pixel column would make the file large.
      const double bucket_width =
        std::max(1., std::ceil(4. * plot_width * n_curves / max_total_points));

      const Frame frame{left,
                        legend_left,
                        x_min,
                        x_scale,
                        x_ticks,
                        bucket_width};

      std::string out;
      out.reserve(1 << 20);
      out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
      out +=
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
        coordinate(width) + "\" height=\"" + coordinate(height) +
        "\" viewBox=\"0 0 " + coordinate(width) + " " + coordinate(height) +
        "\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\" "
        "font-size=\"" +
        coordinate(font_size) + "\">\n";
      out += "<desc>" + escape_xml(csv_path) + "</desc>\n";
      out += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";

      for (std::size_t p = 0; p < layouts.size(); ++p)
        draw_panel(out,
                   table,
                   layouts[p],
                   frame,
                   p + 1 == layouts.size(),
                   x_label);
      out += "</svg>\n";

      std::ofstream file(svg_path, std::ios::binary);
      if (!file)
        throw std::runtime_error(svg_path +
                                 ": cannot open this file for writing");
      file.write(out.data(), static_cast<std::streamsize>(out.size()));
      file.close();
      if (!file)
        throw std::runtime_error(svg_path + ": write error");
    }
  } // namespace postprocess
} // namespace rubberdyn
