// The SVG plotter of time histories (write_time_history_plot) and its tick
// algorithm (nice_ticks), checked by properties of what they produce, not
// by comparison with a stored picture:
//
// - ticks: on a few ranges, every tick lies in the range, the ticks are
//   evenly spaced by 1, 2 or 5 times a power of ten, there are 3 to 8 of
//   them for the target of 5, and each label reads back as its value and
//   is its shortest decimal (e.g. 0.3, not 0.30000000000000004). The
//   labels are printed;
// - a CSV of 100 000 rows, time 0 to 9.7 ms, with a sine, a constant, a
//   column with a block of NaN and one inf, a column that is zero but for
//   a one-row spike of 5, and a column whose name holds the five XML
//   special characters; four panels asked for, one with a column that is
//   not in the file and one with none that is. The SVG must be
//   well-formed XML (a small checker of tag nesting, attribute quoting and
//   entities below, then boost's XML parser), under 1 MB, with three
//   panels, the names read back unescaped, one polyline per column (three
//   for the column with two breaks), x tick labels 0 2 4 6 8, y tick labels
//   -1 -0.5 0 0.5 1 for the sine panel, finite coordinates increasing in
//   x along each polyline, and it must draw what the data say: the sine
//   spans the pixels between the tick labels -1 and 1, the spike rises
//   from the label 0 to the label 5 (its peak survives the thinning to at
//   most 4 points per pixel column), and the NaN block is a gap from
//   t(39 999) to t(50 000). Pixel positions are compared with the tick
//   labels' positions, which are rounded to 0.1 px, as are the
//   polylines' points: hence the tolerance of 0.25 px;
// - the same input gives the same file, byte for byte;
// - a single row (drawn as a dot), a constant column, a file with only a
//   header: finite coordinates and a nonzero axis range (ticks printed);
// - a missing file and a file without any of the columns are errors that
//   name the file.
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <rubberdyn/postprocess/time_history_plot.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "../tests.h"

using boost::property_tree::ptree;
using namespace rubberdyn::postprocess;

namespace
{
  std::string
  read_file(const std::string &name)
  {
    std::ifstream      in(name, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }



  std::string
  join(const std::vector<std::string> &items)
  {
    std::string text;
    for (const std::string &item : items)
      text += (text.empty() ? "" : " ") + item;
    return text;
  }



  /**
   * A small well-formedness checker, independent of boost's parser: every
   * tag is closed in order, attribute values are quoted and hold no '<',
   * every '&' starts one of the five predefined entities, and there is one
   * root element.
   */
  bool
  well_formed(const std::string &xml, std::string &problem)
  {
    const auto entity_ok = [&](const std::size_t i) {
      for (const char *entity : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"})
        if (xml.compare(i, std::string(entity).size(), entity) == 0)
          return true;
      return false;
    };
    std::vector<std::string> open;
    unsigned int             n_roots = 0;
    for (std::size_t i = 0; i < xml.size();)
      {
        if (xml[i] == '&' && !entity_ok(i))
          return problem = "bad entity at " + std::to_string(i), false;
        if (xml[i] != '<')
          {
            ++i;
            continue;
          }
        if (xml.compare(i, 2, "<?") == 0)
          {
            i = xml.find("?>", i);
            if (i == std::string::npos)
              return problem = "unterminated <?", false;
            i += 2;
            continue;
          }
        const bool  closing = xml.compare(i, 2, "</") == 0;
        std::size_t j       = i + (closing ? 2 : 1);
        std::size_t k       = j;
        while (k < xml.size() && (std::isalnum(xml[k]) || xml[k] == '-'))
          ++k;
        const std::string name = xml.substr(j, k - j);
        if (name.empty())
          return problem = "empty tag name at " + std::to_string(i), false;
        // Attributes: name="value" or name='value'.
        while (k < xml.size() && xml[k] != '>' && xml[k] != '/')
          {
            if (std::isspace(xml[k]))
              {
                ++k;
                continue;
              }
            const std::size_t equals = xml.find('=', k);
            if (closing || equals == std::string::npos ||
                (xml[equals + 1] != '"' && xml[equals + 1] != '\''))
              return problem = "bad attribute in <" + name + ">", false;
            const std::size_t end = xml.find(xml[equals + 1], equals + 2);
            if (end == std::string::npos ||
                xml.substr(equals + 2, end - equals - 2).find('<') !=
                  std::string::npos)
              return problem = "bad attribute value in <" + name + ">", false;
            for (std::size_t a = equals + 2; a < end; ++a)
              if (xml[a] == '&' && !entity_ok(a))
                return problem = "bad entity in <" + name + ">", false;
            k = end + 1;
          }
        if (k >= xml.size())
          return problem = "unterminated <" + name + ">", false;
        const bool self_closing = xml[k] == '/';
        if (self_closing && (closing || xml[k + 1] != '>'))
          return problem = "bad end of <" + name + ">", false;
        if (closing)
          {
            if (open.empty() || open.back() != name)
              return problem = "</" + name + "> closes nothing open", false;
            open.pop_back();
          }
        else
          {
            if (open.empty())
              ++n_roots;
            if (!self_closing)
              open.push_back(name);
          }
        i = k + (self_closing ? 2 : 1);
      }
    if (!open.empty())
      return problem = "<" + open.back() + "> is never closed", false;
    if (n_roots != 1)
      return problem = std::to_string(n_roots) + " root elements", false;
    return true;
  }



  /** The checker rejects what it should. */
  void
  check_checker()
  {
    std::string problem;
    testing::check(
      well_formed(
        "<?xml version=\"1.0\"?>\n<a x=\"1 &amp; 2\"><b/>t &lt; u</a>\n",
        problem),
      "the checker accepts a well-formed document: " + problem);
    for (const std::string bad : {"<a><b></a></b>",
                                  "<a>x & y</a>",
                                  "<a x=1></a>",
                                  "<a x=\"<\"></a>",
                                  "<a>",
                                  "<a></a><b></b>"})
      testing::check(!well_formed(bad, problem), "the checker rejects " + bad);
  }



  /** The children of @p node with tag @p tag and, if given, class @p cls. */
  std::vector<const ptree *>
  children(const ptree       &node,
           const std::string &tag,
           const std::string &cls = "")
  {
    std::vector<const ptree *> found;
    for (const auto &child : node)
      if (child.first == tag &&
          (cls.empty() ||
           child.second.get<std::string>("<xmlattr>.class", "") == cls))
        found.push_back(&child.second);
    return found;
  }



  const ptree &
  child(const ptree &node, const std::string &tag, const std::string &cls = "")
  {
    const auto found = children(node, tag, cls);
    testing::check(found.size() == 1, "one <" + tag + " class=" + cls + ">");
    return *found[0];
  }



  /** The texts of the <text> elements of a group, and their positions. */
  struct Labels
  {
    std::vector<std::string> texts;
    std::vector<double>      x, y;

    double
    y_of(const std::string &text) const
    {
      const auto it = std::find(texts.begin(), texts.end(), text);
      testing::check(it != texts.end(), "a tick label '" + text + "'");
      return y[it - texts.begin()];
    }

    double
    x_of(const std::string &text) const
    {
      const auto it = std::find(texts.begin(), texts.end(), text);
      testing::check(it != texts.end(), "a tick label '" + text + "'");
      return x[it - texts.begin()];
    }
  };

  Labels
  labels(const ptree &group)
  {
    Labels result;
    for (const ptree *text : children(group, "text"))
      {
        result.texts.push_back(text->data());
        result.x.push_back(text->get<double>("<xmlattr>.x"));
        result.y.push_back(text->get<double>("<xmlattr>.y"));
      }
    return result;
  }



  /** A polyline's points, checked to be finite and increasing in x. */
  std::vector<std::pair<double, double>>
  points(const ptree &polyline)
  {
    std::istringstream in(polyline.get<std::string>("<xmlattr>.points"));
    std::vector<std::pair<double, double>> result;
    std::string                            pair;
    while (in >> pair)
      {
        const std::size_t comma = pair.find(',');
        testing::check(comma != std::string::npos, "points are x,y pairs");
        char        *end = nullptr;
        const double x   = std::strtod(pair.c_str(), &end);
        testing::check(end == pair.c_str() + comma, "x is a number: " + pair);
        const double y = std::strtod(pair.c_str() + comma + 1, &end);
        testing::check(*end == '\0', "y is a number: " + pair);
        testing::check(std::isfinite(x) && std::isfinite(y),
                       "finite point " + pair);
        testing::check(result.empty() || x >= result.back().first,
                       "x increases along a polyline");
        result.emplace_back(x, y);
      }
    return result;
  }

  /** Smallest and largest y of some points. */
  std::pair<double, double>
  y_extent(const std::vector<std::pair<double, double>> &p)
  {
    double lo = p.at(0).second, hi = lo;
    for (const auto &xy : p)
      {
        lo = std::min(lo, xy.second);
        hi = std::max(hi, xy.second);
      }
    return {lo, hi};
  }



  /** Well-formed (both checkers) and parsed. */
  ptree
  parse_svg(const std::string &name)
  {
    std::string problem;
    testing::check(well_formed(read_file(name), problem),
                   name + " is well-formed XML: " + problem);
    ptree tree;
    // Throws on malformed XML.
    boost::property_tree::read_xml(name, tree);
    return tree.get_child("svg");
  }



  /** The polylines and dots of a panel, by the column named in their title. */
  std::map<std::string, std::vector<const ptree *>>
  curves_by_name(const ptree &panel, const std::string &tag)
  {
    std::map<std::string, std::vector<const ptree *>> found;
    for (const ptree *curve : children(child(panel, "g", "curves"), tag))
      found[curve->get<std::string>("title")].push_back(curve);
    return found;
  }



  void
  check_ticks()
  {
    testing::out() << "Ticks for a target of 5 (min max: step: labels)\n";
    const std::vector<std::pair<double, double>> ranges = {{0., 9.7},
                                                           {0., 1.},
                                                           {0.1, 0.7},
                                                           {0., 0.3},
                                                           {-1.3, 2.7},
                                                           {-0.05, 1.05},
                                                           {-2.2e-3, 0.},
                                                           {1e-6, 5e-6},
                                                           {0., 1.2e6},
                                                           {100., 100.01},
                                                           {-7e5, -6.1e5}};
    for (const auto &[min, max] : ranges)
      {
        const AxisTicks ticks = nice_ticks(min, max);
        testing::out() << "  " << min << " " << max << ": " << ticks.step
                       << ": " << join(ticks.labels) << "\n";
        testing::check(ticks.values.size() >= 3 && ticks.values.size() <= 8,
                       "3 to 8 ticks");
        testing::check(ticks.labels.size() == ticks.values.size(),
                       "a label per tick");
        // The step is 1, 2 or 5 times a power of ten.
        const double power = std::pow(10., std::floor(std::log10(ticks.step)));
        const double mantissa = ticks.step / power;
        testing::check(std::abs(mantissa - 1.) < 1e-12 ||
                         std::abs(mantissa - 2.) < 1e-12 ||
                         std::abs(mantissa - 5.) < 1e-12,
                       "step 1, 2 or 5 times a power of ten");
        for (std::size_t k = 0; k < ticks.values.size(); ++k)
          {
            const double value = ticks.values[k];
            testing::check(value >= min - 1e-9 * ticks.step &&
                             value <= max + 1e-9 * ticks.step,
                           "tick inside the range");
            if (k > 0)
              testing::check(std::abs(value - ticks.values[k - 1] -
                                      ticks.step) < 1e-9 * ticks.step,
                             "evenly spaced ticks");
            // The label reads back as the value, and no shorter decimal
            // with 15 significant digits (all a tick needs) differs.
            testing::check(std::strtod(ticks.labels[k].c_str(), nullptr) ==
                             value,
                           "label " + ticks.labels[k] + " reads back");
            char shortest[32];
            std::snprintf(shortest, sizeof(shortest), "%.15g", value);
            testing::check(ticks.labels[k].size() <=
                             std::string(shortest).size(),
                           "label " + ticks.labels[k] + " is short");
          }
      }
    testing::check(nice_ticks(3., 3.).values.empty() &&
                     nice_ticks(1., 0.).values.empty() &&
                     nice_ticks(0., std::nan("")).values.empty(),
                   "empty, inverted and NaN ranges give no ticks");
    testing::out() << "  empty, inverted and NaN ranges: no ticks\n";
  }



  void
  check_large_file()
  {
    const unsigned int n_rows = 100000;
    const std::string  weird  = "weird <&>\"' name";
    const auto         t      = [&](const unsigned int row) {
      return 9.7 * row / (n_rows - 1);
    };
    {
      std::ofstream csv("history.csv");
      csv << "time,sine,constant,gappy,spike," << weird << "\n";
      csv << std::setprecision(9);
      for (unsigned int row = 0; row < n_rows; ++row)
        {
          csv << t(row) << ',' << std::sin(2. * M_PI * t(row) / 3.) << ",0.5,";
          if (row >= 40000 && row < 50000)
            csv << "nan";
          else if (row == 60000)
            csv << "inf";
          else
            csv << std::cos(t(row));
          csv << ',' << (row == 77777 ? 5 : 0) << ',' << t(row) * t(row)
              << "\n";
        }
    }
    const std::vector<PlotPanel> panels = {
      {"Sine & constant", "value (-)", {"sine", "constant", "missing_column"}},
      {"Gaps and a spike", "value (-)", {"gappy", "spike"}},
      {"Left out", "value (-)", {"not_in_file"}},
      {"Escaping <&>", "time^2 (ms^2)", {weird}}};
    write_time_history_plot("history.csv", "history.svg", panels);
    write_time_history_plot("history.csv", "history_again.svg", panels);
    testing::out()
      << "100000 rows, 4 panels asked for, 5 of 7 columns in the file\n";

    const std::string text = read_file("history.svg");
    testing::check(text.size() < 1000000, "SVG under 1 MB");
    testing::out() << "  SVG under 1 MB: yes\n";
    testing::check(text == read_file("history_again.svg"),
                   "the same input gives the same SVG");
    testing::out() << "  the same input gives the same bytes: yes\n";
    testing::check(text.find(weird) == std::string::npos &&
                     text.find("weird &lt;&amp;&gt;&quot;&apos; name") !=
                       std::string::npos,
                   "the name is escaped");

    const ptree svg = parse_svg("history.svg");
    testing::out()
      << "  well-formed XML (own checker and boost's parser): yes\n";
    const auto panel_nodes = children(svg, "g", "panel");
    testing::check(panel_nodes.size() == 3, "three panels");
    testing::out() << "  panels: " << panel_nodes.size() << "\n";

    unsigned int n_polylines = 0;
    for (const ptree *panel : panel_nodes)
      {
        const auto legend = labels(child(*panel, "g", "legend"));
        const auto lines  = curves_by_name(*panel, "polyline");
        const auto dots   = curves_by_name(*panel, "circle");
        testing::check(dots.empty(), "no dots");
        testing::out() << "  panel '" << panel->get<std::string>("text")
                       << "': legend:";
        for (const std::string &name : legend.texts)
          {
            testing::check(lines.count(name) == 1, "a polyline for " + name);
            testing::out() << " '" << name << "' (" << lines.at(name).size()
                           << " polyline"
                           << (lines.at(name).size() > 1 ? "s" : "") << ")";
            n_polylines += lines.at(name).size();
            for (const ptree *line : lines.at(name))
              testing::check(points(*line).size() <= 4 * 640,
                             "at most 4 points per pixel column");
          }
        testing::check(lines.size() == legend.texts.size(),
                       "one curve per legend entry");
        testing::out() << "; y ticks: "
                       << join(
                            labels(child(*panel, "g", "y-tick-labels")).texts)
                       << "\n";
      }
    testing::check(n_polylines == 7, "7 polylines");
    testing::out() << "  polylines: " << n_polylines
                   << " (one per column, three for the column with a NaN "
                      "block and an inf)\n";
    testing::check(children(*panel_nodes[0], "g", "x-tick-labels").empty(),
                   "x tick labels only under the bottom panel");
    const Labels x_ticks = labels(child(*panel_nodes[2], "g", "x-tick-labels"));
    testing::check(join(x_ticks.texts) == "0 2 4 6 8", "x ticks 0 2 4 6 8");
    testing::out() << "  x ticks (range 0 to 9.7): " << join(x_ticks.texts)
                   << "\n";
    testing::check(svg.get<std::string>("text") == "time (ms)", "x label");
    testing::check(child(*panel_nodes[2], "text", "y-label").data() ==
                     "time^2 (ms^2)",
                   "y label");

    // What is drawn, in pixels, against the tick labels.
    const double tolerance = 0.25;
    {
      const Labels y_ticks =
        labels(child(*panel_nodes[0], "g", "y-tick-labels"));
      testing::check(join(y_ticks.texts) == "-1 -0.5 0 0.5 1",
                     "sine panel ticks");
      const auto [top, bottom] = y_extent(
        points(*curves_by_name(*panel_nodes[0], "polyline").at("sine")[0]));
      testing::check(std::abs((bottom - top) - (y_ticks.y_of("-1") -
                                                y_ticks.y_of("1"))) < tolerance,
                     "the sine's height is that of -1 to 1");
      testing::out() << "  the sine spans the tick labels -1 to 1: yes\n";
    }
    {
      const auto   curves = curves_by_name(*panel_nodes[1], "polyline");
      const Labels y_ticks =
        labels(child(*panel_nodes[1], "g", "y-tick-labels"));
      const auto [top, bottom] = y_extent(points(*curves.at("spike")[0]));
      testing::check(std::abs((bottom - top) - (y_ticks.y_of("0") -
                                                y_ticks.y_of("5"))) < tolerance,
                     "the spike's height is that of 0 to 5");
      testing::out()
        << "  the one-row spike rises from the tick label 0 to 5: yes\n";

      // The gap: from t(39999) to t(50000); x in pixels from the labels 0, 2.
      const double x0 = x_ticks.x_of("0"), x2 = x_ticks.x_of("2");
      const auto   to_x = [&](const double time) {
        return x0 + time * (x2 - x0) / 2.;
      };
      const auto &gappy = curves.at("gappy");
      testing::check(std::abs(points(*gappy[0]).back().first - to_x(t(39999))) <
                         tolerance &&
                       std::abs(points(*gappy[1]).front().first -
                                to_x(t(50000))) < tolerance,
                     "the NaN block is a gap from t(39999) to t(50000)");
      testing::out()
        << "  the NaN block is a gap from t(39999) to t(50000): yes\n";
    }
  }



  void
  check_small_files()
  {
    const auto plot = [](const std::string &name, const std::string &csv_text) {
      {
        std::ofstream csv(name + ".csv");
        csv << csv_text;
      }
      write_time_history_plot(name + ".csv",
                              name + ".svg",
                              {{"", "a (-)", {"a"}}});
      const ptree svg   = parse_svg(name + ".svg");
      const auto  panel = children(svg, "g", "panel");
      testing::check(panel.size() == 1, "one panel");
      const auto polylines = curves_by_name(*panel[0], "polyline");
      const auto dots      = curves_by_name(*panel[0], "circle");
      for (const auto &[column, lines] : polylines)
        for (const ptree *line : lines)
          points(*line);
      for (const auto &[column, circles] : dots)
        for (const ptree *circle : circles)
          testing::check(std::isfinite(circle->get<double>("<xmlattr>.cx")) &&
                           std::isfinite(circle->get<double>("<xmlattr>.cy")),
                         "finite dot");
      // No "nan" or "inf" that does not continue a word (as in
      // "dominant-baseline"): no number of the SVG is NaN or infinite.
      const std::string text = read_file(name + ".svg");
      for (const std::string word : {"nan", "inf"})
        for (std::size_t i = text.find(word); i != std::string::npos;
             i             = text.find(word, i + 1))
          testing::check(i > 0 && std::isalpha(text[i - 1]),
                         "no nan or inf in the SVG");
      testing::out()
        << "  " << name << ": " << polylines.size() << " polyline(s), "
        << dots.size() << " dot(s); x ticks: "
        << join(labels(child(*panel[0], "g", "x-tick-labels")).texts)
        << "; y ticks: "
        << join(labels(child(*panel[0], "g", "y-tick-labels")).texts) << "\n";
    };
    testing::out() << "Degenerate files\n";
    plot("single_row", "time,a\n1.5,2\n");
    plot("constant", "time,a\n0,0.5\n1,0.5\n2,0.5\n");
    plot("header_only", "time,a\n");
  }



  void
  check_errors()
  {
    testing::out() << "Errors\n";
    const auto expect_error = [](const std::string &csv,
                                 const std::string &name) {
      try
        {
          write_time_history_plot(csv, "error.svg", {{"", "", {"a"}}});
        }
      catch (const std::runtime_error &error)
        {
          testing::check(std::string(error.what()).find(name) !=
                           std::string::npos,
                         "the message names the file");
          testing::out() << "  " << error.what() << "\n";
          return;
        }
      testing::check(false, "an error for " + csv);
    };
    expect_error("no_such_file.csv", "no_such_file.csv");
    {
      std::ofstream csv("other_columns.csv");
      csv << "time,b\n0,1\n";
    }
    expect_error("other_columns.csv", "other_columns.csv");
  }
} // namespace



int
main()
{
  check_checker();
  check_ticks();
  check_large_file();
  check_small_files();
  check_errors();
}
