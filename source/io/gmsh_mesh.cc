#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/io/gmsh_mesh.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

// deal.II 9.4's Gmsh readers, as observed, and why this file checks the
// whole file before handing it to one of them:
// - GridIn::read_msh(const std::string &) goes through the Gmsh API, which
//   merges coincident nodes (two blocks touching at a corner become one
//   body) and, with Debian's Gmsh 4.8, drops all physical tags (every
//   material and boundary id 0). We use GridIn::read_msh(std::istream &),
//   which keeps distinct nodes distinct and maps the first tag of a
//   msh 2.2 element, or the physical tag of a msh 4.1 entity, to the
//   material id (cells) or boundary id (faces).
// - The stream reader checks little, and mostly with debug-only assertions:
//   in the release library, a quadrangle that uses an undefined node
//   segfaults; a msh 2.2 body under a 4.1 header ends in "double free or
//   corruption" and hangs; a tetrahedron among hexahedra gives a mixed mesh
//   that the hexahedral code cannot use; the material id 4294967295
//   (deal.II's invalid id) is accepted; a quadrangle that is not a face of
//   the mesh is ignored; physical surface tag 0 and untagged cells become
//   id 0. Truncated or garbled files and binary files give exceptions
//   whose text is a paragraph about I/O errors in general.
// - A hexahedron whose vertices are listed mirrored (negative Jacobian
//   everywhere) is silently turned inside out again
//   (GridTools::invert_cells_with_negative_measure), and a tangled one
//   whose total volume is still positive is accepted as it is. Neither is
//   visible after reading (cell->measure() is then positive), so the
//   orientation is checked here on the file's own vertex order, before
//   deal.II reorders anything (GridTools::consistently_order_cells only
//   orients edges consistently, it does not fix or detect a sign).

namespace rubberdyn
{
  namespace io
  {
    namespace
    {
      /** Largest tag (node, element, entity or physical) accepted: Gmsh's
       * tags are `int`. */
      constexpr long long max_tag = std::numeric_limits<int>::max();

      /** An element type of Gmsh's numbering that we accept. */
      struct AcceptedType
      {
        int          type;
        unsigned int n_nodes;
        int          dim;
        const char  *name;
      };

      constexpr std::array<AcceptedType, 4> accepted_types = {
        {{15, 1, 0, "point"},
         {1, 2, 1, "line"},
         {3, 4, 2, "quadrangle"},
         {5, 8, 3, "hexahedron"}}};

      constexpr int quadrangle_type = 3;
      constexpr int hexahedron_type = 5;

      const AcceptedType *
      accepted_type(const long long type)
      {
        for (const AcceptedType &accepted : accepted_types)
          if (accepted.type == type)
            return &accepted;
        return nullptr;
      }

      /** Gmsh's element type in words, e.g. "tetrahedron (type 4)". */
      std::string
      type_in_words(const long long type)
      {
        static const std::map<long long, std::string> names = {
          {1, "line"},
          {2, "triangle"},
          {3, "quadrangle"},
          {4, "tetrahedron"},
          {5, "hexahedron"},
          {6, "prism"},
          {7, "pyramid"},
          {8, "second-order line"},
          {9, "second-order triangle"},
          {10, "second-order quadrangle (9 nodes)"},
          {11, "second-order tetrahedron"},
          {12, "second-order hexahedron (27 nodes)"},
          {13, "second-order prism (18 nodes)"},
          {14, "second-order pyramid (14 nodes)"},
          {15, "point"},
          {16, "second-order quadrangle (8 nodes)"},
          {17, "second-order hexahedron (20 nodes)"},
          {18, "second-order prism (15 nodes)"},
          {19, "second-order pyramid (13 nodes)"}};
        const auto name = names.find(type);
        if (name != names.end())
          return name->second + " (type " + std::to_string(type) + ")";
        if (type > 19 && type < 200)
          return "higher-order element (type " + std::to_string(type) + ")";
        return "element of unknown type " + std::to_string(type);
      }

      const char *
      entity_name(const long long dim)
      {
        static const char *names[4] = {"point", "curve", "surface", "volume"};
        return (dim >= 0 && dim < 4) ? names[dim] : "entity";
      }

      std::string_view
      trim(std::string_view text)
      {
        const char *space = " \t\r\f\v";
        const auto  first = text.find_first_not_of(space);
        if (first == std::string_view::npos)
          return {};
        const auto last = text.find_last_not_of(space);
        return text.substr(first, last - first + 1);
      }

      std::vector<std::string_view>
      tokens_of(const std::string_view line)
      {
        std::vector<std::string_view> tokens;
        const char                   *space = " \t\r\f\v";
        std::size_t                   begin = line.find_first_not_of(space);
        while (begin != std::string_view::npos)
          {
            const std::size_t end = line.find_first_of(space, begin);
            tokens.push_back(line.substr(begin, end - begin));
            begin = (end == std::string_view::npos) ?
                      end :
                      line.find_first_not_of(space, end);
          }
        return tokens;
      }

      /**
       * At most 40 characters of @p text, for messages. Bytes that are not
       * printable ASCII become '?' (a tab a space): a binary file must not
       * put control characters (which a terminal may act on) or broken
       * UTF-8 into the one-line message.
       */
      std::string
      excerpt(const std::string_view text)
      {
        const std::string_view trimmed = trim(text);
        std::string            result(trimmed.size() <= 40 ?
                                        trimmed :
                                        trimmed.substr(0, 37));
        for (char &c : result)
          if (c == '\t')
            c = ' ';
          else if (static_cast<unsigned char>(c) < 0x20 ||
                   static_cast<unsigned char>(c) >= 0x7f)
            c = '?';
        return trimmed.size() <= 40 ? result : result + "...";
      }

      /**
       * The "additional information" of a deal.II exception, without the
       * banner, whitespace folded to one line.
       */
      std::string
      exception_message(const dealii::ExceptionBase &exception)
      {
        std::ostringstream info;
        exception.print_info(info);
        std::string text =
          std::regex_replace(info.str(), std::regex("\\s+"), " ");
        return std::regex_replace(text, std::regex("^ +| +$"), "");
      }

      using NodeList = std::array<long long, 8>;

      /** An accepted element of the file. */
      struct Element
      {
        long long    number;
        int          type;
        long long    physical_tag; // -1: none
        unsigned int n_nodes;
        // Node tags, Gmsh's order; the unused entries stay distinct and
        // negative.
        NodeList    nodes = {{-1, -2, -3, -4, -5, -6, -7, -8}};
        std::size_t line; // index into the lines
        // msh 4.1: the entity whose physical group gives the tag.
        long long entity = 0;
      };

      struct HashNodes
      {
        template <std::size_t n>
        std::size_t
        operator()(const std::array<long long, n> &nodes) const
        {
          std::size_t hash = 0;
          for (const long long node : nodes)
            hash = hash * 1000003u ^ std::hash<long long>()(node);
          return hash;
        }
      };

      /**
       * The checks of the whole file, in the order in which the file is
       * read, and the text handed to deal.II.
       */
      class MshScanner
      {
      public:
        MshScanner(const std::string &file_name,
                   const std::string &entry_path,
                   const std::string &text);

        /** Check everything; return the text for GridIn::read_msh(). */
        std::string
        scan();

        [[noreturn]] void
        fail(const std::string &message) const
        {
          throw InputError(entry_path, file_name + ": " + message);
        }

      private:
        [[noreturn]] void
        fail(const std::size_t line, const std::string &message) const
        {
          fail("line " + std::to_string(line + 1) + ": " + message);
        }

        long long
        integer(const std::size_t      line,
                const std::string_view token,
                const std::string     &what,
                const long long        min,
                const long long        max) const;

        double
        real(const std::size_t      line,
             const std::string_view token,
             const std::string     &what) const;

        std::vector<std::string_view>
        tokens(const std::size_t  line,
               const std::size_t  n_expected,
               const std::string &what) const;

        /** The next non-blank line of a section, or an error saying what
         * was still missing. */
        std::size_t
        next_record(std::size_t       &position,
                    const std::size_t  section,
                    const std::string &missing) const;

        void
        find_sections();
        void
        scan_mesh_format();
        void
        scan_physical_names();
        void
        scan_entities();
        /**
         * msh 2.2's $Nodes and $Elements: the count line, then one record
         * a line. The records' lines, after checking that there are as
         * many as announced; @p item is "node" or "element", @p section
         * "Nodes" or "Elements".
         */
        std::vector<std::size_t>
        counted_records(std::size_t       &position,
                        const std::size_t  end,
                        const std::string &item,
                        const std::string &section) const;

        /** msh 4.1's header of a section of blocks: its line and counts. */
        struct BlockHeader
        {
          std::size_t line;
          long long   n_blocks;
          long long   n_items;
        };

        /**
         * msh 4.1: the header "numBlocks numItems minTag maxTag" of the
         * $Nodes or $Elements section (@p item "node" or "element").
         */
        BlockHeader
        block_header(std::size_t       &position,
                     const std::size_t  end,
                     const std::string &item) const;

        /** msh 4.1: the line of block @p b (from 0) of @p header. */
        std::size_t
        next_block(std::size_t       &position,
                   const std::size_t  end,
                   const std::string &item,
                   const long long    b,
                   const BlockHeader &header) const;

        /**
         * msh 4.1: nothing after the blocks, and as many items in them
         * (@p n_read) as the header announces.
         */
        void
        check_blocks_end(std::size_t        position,
                         const std::size_t  end,
                         const std::string &item,
                         const std::string &section,
                         const BlockHeader &header,
                         const long long    n_read) const;

        void
        add_node(const std::size_t       tag_line,
                 const long long         tag,
                 const std::size_t       line,
                 const std::string_view *coordinates);
        void
        scan_nodes();
        [[noreturn]] void
        refuse_type(const std::size_t line,
                    const long long   number,
                    const long long   type) const;
        /** msh 2.2: the element of line @p l. */
        Element
        element_of_record(const std::size_t l) const;
        /**
         * msh 4.1: a block of elements of @p type that no hexahedral mesh
         * has: refused, naming its first element if it can.
         */
        [[noreturn]] void
        refuse_block(const std::size_t block,
                     const std::size_t position,
                     const std::size_t end,
                     const long long   type) const;
        void
        scan_elements();
        void
        add_element(Element element);
        void
        check_hexahedra();
        void
        check_quadrangles() const;
        std::string
        text_for_deal_ii() const;

        /** "hexahedron 12", for the element a message is about. */
        static std::string
        name_of(const Element &element);

        /** "hexahedron 12 (line 40)", for another element. */
        static std::string
        describe(const Element &element);

        const std::string &file_name;
        const std::string &entry_path;

        std::vector<std::string_view> lines;

        /** Section name -> index of its $Name and $EndName lines. */
        std::map<std::string, std::pair<std::size_t, std::size_t>> sections;

        bool        version_4 = false;
        std::string format_line;

        /** msh 4.1 entities: (dim, tag) -> physical tag (-1: none). */
        std::map<std::pair<long long, long long>, long long> entity_physical;

        std::unordered_map<long long, std::size_t>      node_line;
        std::unordered_map<long long, dealii::Point<3>> node_position;

        std::vector<Element>          hexahedra;
        std::vector<Element>          quadrangles;
        std::unordered_set<long long> element_numbers;

        /** msh 4.1: the kept element blocks, as (header line, element
         * lines). */
        std::vector<std::pair<std::size_t, std::vector<std::size_t>>>
          kept_blocks;
      };



      MshScanner::MshScanner(const std::string &file_name,
                             const std::string &entry_path,
                             const std::string &text)
        : file_name(file_name)
        , entry_path(entry_path)
      {
        std::size_t begin = 0;
        while (begin < text.size())
          {
            std::size_t end = text.find('\n', begin);
            if (end == std::string::npos)
              end = text.size();
            lines.emplace_back(text.data() + begin, end - begin);
            begin = end + 1;
          }
      }



      long long
      MshScanner::integer(const std::size_t      line,
                          const std::string_view token,
                          const std::string     &what,
                          const long long        min,
                          const long long        max) const
      {
        std::string_view digits = token;
        if (!digits.empty() && digits[0] == '+')
          digits.remove_prefix(1);
        long long  value = 0;
        const auto result =
          std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (digits.empty() || result.ec != std::errc() ||
            result.ptr != digits.data() + digits.size() || value < min ||
            value > max)
          fail(line,
               "expected " + what + ", an integer " +
                 (max == std::numeric_limits<long long>::max() ?
                    ">= " + std::to_string(min) :
                    "from " + std::to_string(min) + " to " +
                      std::to_string(max)) +
                 ", found '" + excerpt(token) + "'");
        return value;
      }



      double
      MshScanner::real(const std::size_t      line,
                       const std::string_view token,
                       const std::string     &what) const
      {
        std::string_view digits = token;
        if (!digits.empty() && digits[0] == '+')
          digits.remove_prefix(1);
        double     value  = 0.;
        const auto result = std::from_chars(digits.data(),
                                            digits.data() + digits.size(),
                                            value,
                                            std::chars_format::general);
        if (digits.empty() || result.ec != std::errc() ||
            result.ptr != digits.data() + digits.size() ||
            !std::isfinite(value))
          fail(line,
               "expected " + what + ", a finite real number, found '" +
                 excerpt(token) + "'");
        return value;
      }



      std::vector<std::string_view>
      MshScanner::tokens(const std::size_t  line,
                         const std::size_t  n_expected,
                         const std::string &what) const
      {
        std::vector<std::string_view> result = tokens_of(lines[line]);
        if (result.size() != n_expected)
          fail(line,
               "expected " + std::to_string(n_expected) +
                 (n_expected == 1 ? " number (" : " numbers (") + what +
                 "), found " + std::to_string(result.size()) + ": '" +
                 excerpt(lines[line]) + "'");
        return result;
      }



      std::size_t
      MshScanner::next_record(std::size_t       &position,
                              const std::size_t  section,
                              const std::string &missing) const
      {
        for (; position < section; ++position)
          if (!trim(lines[position]).empty())
            return position++;
        fail(section,
             "the section ends before " + missing +
               " (a count announced more than the section lists)");
      }



      void
      MshScanner::find_sections()
      {
        for (std::size_t i = 0; i < lines.size(); ++i)
          {
            const std::string_view text = trim(lines[i]);
            if (text.empty())
              continue;
            if (text[0] != '$' || text.rfind("$End", 0) == 0 ||
                tokens_of(text).size() != 1)
              fail(i,
                   "expected the start of a section ($Name), found '" +
                     excerpt(text) + "'");
            const std::string name(text.substr(1));
            const std::string end_marker = "$End" + name;
            std::size_t       j          = i + 1;
            for (; j < lines.size(); ++j)
              {
                const std::string_view inner = trim(lines[j]);
                if (inner == end_marker)
                  break;
                if (!inner.empty() && inner[0] == '$')
                  fail(j,
                       "found '" + excerpt(inner) + "' inside the section $" +
                         name + " of line " + std::to_string(i + 1) +
                         ", which is not closed by " + end_marker);
              }
            if (j == lines.size())
              fail(i,
                   "the section $" + name + " is not closed: " + end_marker +
                     " is missing (is the file truncated?)");
            if (sections.count(name) != 0)
              fail(i,
                   "a second $" + name + " section (the first is in line " +
                     std::to_string(sections[name].first + 1) + ")");
            sections[name] = {i, j};
            i              = j;
          }
        for (const char *required : {"Nodes", "Elements"})
          if (sections.count(required) == 0)
            fail(std::string("the file has no $") + required + " section");
      }



      void
      MshScanner::scan_mesh_format()
      {
        // The header alone first: a binary file is only text up to here.
        std::size_t i = 0;
        while (i < lines.size() && trim(lines[i]).empty())
          ++i;
        if (i == lines.size())
          fail("the file is empty");
        const std::string_view first = trim(lines[i]);
        if (first == "$NOD" || first == "$NOE")
          fail(i,
               "this is Gmsh's format 1, which is not supported: export as "
               "2.2 ASCII (gmsh -format msh22, or Mesh.MshFileVersion = 2.2 "
               "in the .geo) or as 4.1 ASCII");
        if (first != "$MeshFormat")
          fail(i,
               "not a Gmsh mesh file: expected '$MeshFormat', found '" +
                 excerpt(first) + "'");
        std::size_t header = i + 1;
        while (header < lines.size() && trim(lines[header]).empty())
          ++header;
        if (header == lines.size())
          fail(i, "the file ends after $MeshFormat (is it truncated?)");
        const auto fields = tokens_of(lines[header]);
        if (fields.size() != 3)
          fail(header,
               "expected 'version file-type data-size' (e.g. '2.2 0 8'), "
               "found '" +
                 excerpt(lines[header]) + "'");
        if (fields[1] == "1")
          fail(header,
               "this is a binary Gmsh file, which is not supported: export "
               "as ASCII (Mesh.Binary = 0, the default), format 2.2 (gmsh "
               "-format msh22, or Mesh.MshFileVersion = 2.2) or 4.1");
        if (fields[1] != "0")
          fail(header,
               "expected the file type 0 (ASCII), found '" +
                 excerpt(fields[1]) + "'");
        if (fields[0] == "4.1")
          version_4 = true;
        else if (fields[0] != "2.2" && fields[0] != "2.1" &&
                 fields[0] != "2.0" && fields[0] != "2")
          fail(header,
               "Gmsh file format version " + excerpt(fields[0]) +
                 " is not supported: export as 2.2 ASCII (gmsh -format "
                 "msh22, or Mesh.MshFileVersion = 2.2 in the .geo) or as "
                 "4.1 ASCII");
        if (fields[2] != "8")
          fail(header,
               "expected the data size 8 (bytes per real number), found '" +
                 excerpt(fields[2]) + "'");
        format_line = std::string(fields[0]) + " 0 8";

        // Everything else must be text: a NUL or another control
        // character means a binary or damaged file.
        for (std::size_t l = 0; l < lines.size(); ++l)
          for (const char c : lines[l])
            {
              const auto byte = static_cast<unsigned char>(c);
              if ((byte < 0x20 && std::string_view(" \t\r\f\v").find(c) ==
                                    std::string_view::npos) ||
                  byte == 0x7f)
                {
                  const char *hex = "0123456789abcdef";
                  fail(l,
                       std::string("contains the control character 0x") +
                         hex[byte / 16] + hex[byte % 16] +
                         ": this is not a text file (a binary or damaged "
                         "file?)");
                }
            }

        // $MeshFormat is the first section (checked above).
        find_sections();
        const auto &format   = sections.at("MeshFormat");
        std::size_t position = format.first + 1;
        next_record(position, format.second, "the format line");
        for (; position < format.second; ++position)
          if (!trim(lines[position]).empty())
            fail(position,
                 "unexpected '" + excerpt(lines[position]) +
                   "' in the $MeshFormat section");
      }



      void
      MshScanner::scan_physical_names()
      {
        if (sections.count("PhysicalNames") == 0)
          return;
        const auto [begin, end]    = sections.at("PhysicalNames");
        std::size_t       position = begin + 1;
        const std::size_t count_line =
          next_record(position, end, "the number of physical names");
        const long long n =
          integer(count_line,
                  tokens(count_line, 1, "the number of physical names")[0],
                  "the number of physical names",
                  0,
                  max_tag);
        long long n_listed = 0;
        for (std::size_t l = position; l < end; ++l)
          if (!trim(lines[l]).empty())
            {
              ++n_listed;
              const auto fields = tokens_of(lines[l]);
              if (fields.size() < 3 || fields[2][0] != '"' ||
                  lines[l].find_last_of('"') == lines[l].find('"'))
                fail(l,
                     "expected 'dimension tag \"name\"', found '" +
                       excerpt(lines[l]) + "'");
              integer(l, fields[0], "the dimension of a physical group", 0, 3);
              integer(l, fields[1], "a physical tag", 0, max_tag);
            }
        if (n_listed != n)
          fail(count_line,
               "the $PhysicalNames section announces " + std::to_string(n) +
                 " names but lists " + std::to_string(n_listed));
      }



      void
      MshScanner::scan_entities()
      {
        if (!version_4)
          return; // msh 2.2 has no entities; a stray section is ignored.
        if (sections.count("Entities") == 0)
          fail("this 4.1 file has no $Entities section, which holds the "
               "physical tags");
        const auto [begin, end]    = sections.at("Entities");
        std::size_t       position = begin + 1;
        const std::size_t header =
          next_record(position, end, "the numbers of entities");
        const auto               counts = tokens(header,
                                   4,
                                   "numbers of points, curves, surfaces and "
                                                 "volumes");
        std::array<long long, 4> n_entities;
        for (unsigned int d = 0; d < 4; ++d)
          n_entities[d] = integer(header,
                                  counts[d],
                                  std::string("the number of ") +
                                    entity_name(d) + " entities",
                                  0,
                                  max_tag);
        for (unsigned int d = 0; d < 4; ++d)
          for (long long e = 0; e < n_entities[d]; ++e)
            {
              const std::size_t l =
                next_record(position,
                            end,
                            std::string(entity_name(d)) + " entity " +
                              std::to_string(e + 1) + " of " +
                              std::to_string(n_entities[d]));
              const auto fields = tokens_of(lines[l]);
              // point: tag x y z n_physicals physicals...
              // others: tag 6 box coordinates n_physicals physicals...
              //         n_bounding bounding...
              const std::size_t n_reals = (d == 0) ? 3 : 6;
              if (fields.size() < 2 + n_reals)
                fail(l,
                     std::string("too few numbers for a ") + entity_name(d) +
                       " entity: '" + excerpt(lines[l]) + "'");
              const long long tag =
                integer(l,
                        fields[0],
                        std::string(entity_name(d)) + " tag",
                        1,
                        max_tag);
              for (std::size_t r = 1; r <= n_reals; ++r)
                real(l, fields[r], "a coordinate of the bounding box");
              const long long n_physicals =
                integer(l,
                        fields[1 + n_reals],
                        "the number of physical groups",
                        0,
                        max_tag);
              std::size_t expected = 2 + n_reals + n_physicals;
              if (fields.size() < expected)
                fail(l,
                     std::string("too few numbers for a ") + entity_name(d) +
                       " entity: '" + excerpt(lines[l]) + "'");
              if (n_physicals > 1)
                fail(l,
                     std::string(entity_name(d)) + " " + std::to_string(tag) +
                       " is in " + std::to_string(n_physicals) +
                       " physical groups; deal.II takes one physical group "
                       "per entity");
              long long physical = -1;
              if (n_physicals == 1)
                physical =
                  integer(l, fields[2 + n_reals], "a physical tag", 0, max_tag);
              if (d > 0)
                {
                  if (fields.size() < expected + 1)
                    fail(l,
                         std::string("too few numbers for a ") +
                           entity_name(d) + " entity: '" + excerpt(lines[l]) +
                           "'");
                  const long long n_bounding =
                    integer(l,
                            fields[expected],
                            "the number of bounding entities",
                            0,
                            max_tag);
                  for (long long b = 0;
                       b < n_bounding && expected + 1 + b < fields.size();
                       ++b)
                    integer(l,
                            fields[expected + 1 + b],
                            "a bounding entity tag",
                            -max_tag,
                            max_tag);
                  expected += 1 + n_bounding;
                }
              if (fields.size() != expected)
                fail(l,
                     "expected " + std::to_string(expected) + " numbers for " +
                       entity_name(d) + " " + std::to_string(tag) + ", found " +
                       std::to_string(fields.size()));
              if (!entity_physical.emplace(std::make_pair(d, tag), physical)
                     .second)
                fail(l,
                     std::string(entity_name(d)) + " " + std::to_string(tag) +
                       " is defined twice");
            }
        for (; position < end; ++position)
          if (!trim(lines[position]).empty())
            fail(position,
                 "unexpected '" + excerpt(lines[position]) +
                   "' after the entities the $Entities section announces");
      }



      std::vector<std::size_t>
      MshScanner::counted_records(std::size_t       &position,
                                  const std::size_t  end,
                                  const std::string &item,
                                  const std::string &section) const
      {
        const std::string what = "the number of " + item + "s";
        const std::size_t count_line = next_record(position, end, what);
        const long long   n =
          integer(count_line, tokens(count_line, 1, what)[0], what, 0, max_tag);
        std::vector<std::size_t> records;
        for (std::size_t l = position; l < end; ++l)
          if (!trim(lines[l]).empty())
            records.push_back(l);
        if (static_cast<long long>(records.size()) != n)
          fail(count_line,
               "the $" + section + " section announces " + std::to_string(n) +
                 " " + item + "s but lists " + std::to_string(records.size()));
        return records;
      }



      MshScanner::BlockHeader
      MshScanner::block_header(std::size_t       &position,
                               const std::size_t  end,
                               const std::string &item) const
      {
        const std::size_t line =
          next_record(position,
                      end,
                      "the numbers of " + item + " blocks and " + item + "s");
        const auto fields = tokens(line,
                                   4,
                                   "numbers of blocks and " + item +
                                     "s, smallest and largest " + item +
                                     " tag");
        BlockHeader header;
        header.line     = line;
        header.n_blocks = integer(
          line, fields[0], "the number of " + item + " blocks", 0, max_tag);
        header.n_items =
          integer(line, fields[1], "the number of " + item + "s", 0, max_tag);
        integer(line, fields[2], "the smallest " + item + " tag", 0, max_tag);
        integer(line, fields[3], "the largest " + item + " tag", 0, max_tag);
        return header;
      }



      std::size_t
      MshScanner::next_block(std::size_t       &position,
                             const std::size_t  end,
                             const std::string &item,
                             const long long    b,
                             const BlockHeader &header) const
      {
        return next_record(position,
                           end,
                           item + " block " + std::to_string(b + 1) + " of " +
                             std::to_string(header.n_blocks));
      }



      void
      MshScanner::check_blocks_end(std::size_t        position,
                                   const std::size_t  end,
                                   const std::string &item,
                                   const std::string &section,
                                   const BlockHeader &header,
                                   const long long    n_read) const
      {
        for (; position < end; ++position)
          if (!trim(lines[position]).empty())
            fail(position,
                 "unexpected '" + excerpt(lines[position]) + "' after the " +
                   item + " blocks the $" + section + " section announces");
        if (n_read != header.n_items)
          fail(header.line,
               "the $" + section + " section announces " +
                 std::to_string(header.n_items) + " " + item +
                 "s but its blocks hold " + std::to_string(n_read));
      }



      void
      MshScanner::add_node(const std::size_t       tag_line,
                           const long long         tag,
                           const std::size_t       line,
                           const std::string_view *coordinates)
      {
        dealii::Point<3> x;
        for (unsigned int d = 0; d < 3; ++d)
          x[d] = real(line, coordinates[d], "a node coordinate");
        const auto inserted = node_line.emplace(tag, tag_line);
        if (!inserted.second)
          fail(tag_line,
               "node " + std::to_string(tag) +
                 " is defined twice (first in line " +
                 std::to_string(inserted.first->second + 1) + ")");
        node_position.emplace(tag, x);
      }



      void
      MshScanner::scan_nodes()
      {
        const auto [begin, end] = sections.at("Nodes");
        std::size_t position    = begin + 1;

        if (!version_4)
          {
            for (const std::size_t l :
                 counted_records(position, end, "node", "Nodes"))
              {
                const auto fields =
                  tokens(l, 4, "node tag and coordinates x y z");
                const long long tag =
                  integer(l, fields[0], "a node tag", 1, max_tag);
                add_node(l, tag, l, &fields[1]);
              }
            return;
          }

        // msh 4.1: numEntityBlocks numNodes minNodeTag maxNodeTag, then per
        // block: entityDim entityTag parametric numNodesInBlock, the block's
        // node tags (one a line), then their coordinates (one a line).
        const BlockHeader header = block_header(position, end, "node");
        long long         n_read = 0;
        for (long long b = 0; b < header.n_blocks; ++b)
          {
            const std::size_t block =
              next_block(position, end, "node", b, header);
            const auto block_fields =
              tokens(block,
                     4,
                     "entity dimension and tag, parametric, number of nodes");
            integer(block, block_fields[0], "an entity dimension", 0, 3);
            integer(block, block_fields[1], "an entity tag", 1, max_tag);
            const long long parametric =
              integer(block, block_fields[2], "parametric (0 or 1)", 0, 1);
            if (parametric != 0)
              fail(block,
                   "parametric node coordinates are not supported: export "
                   "with Mesh.SaveParametric = 0 (the default)");
            const long long n_in_block =
              integer(block, block_fields[3], "a number of nodes", 0, max_tag);
            std::vector<std::pair<std::size_t, long long>> tags;
            for (long long k = 0; k < n_in_block; ++k)
              {
                const std::size_t l =
                  next_record(position,
                              end,
                              "the tag of node " + std::to_string(k + 1) +
                                " of the block in line " +
                                std::to_string(block + 1));
                tags.emplace_back(l,
                                  integer(l,
                                          tokens(l, 1, "a node tag")[0],
                                          "a node tag",
                                          1,
                                          max_tag));
              }
            for (long long k = 0; k < n_in_block; ++k)
              {
                const std::size_t l =
                  next_record(position,
                              end,
                              "the coordinates of node " +
                                std::to_string(tags[k].second));
                const auto xyz = tokens(l, 3, "node coordinates x y z");
                add_node(tags[k].first, tags[k].second, l, xyz.data());
              }
            n_read += n_in_block;
          }
        check_blocks_end(position, end, "node", "Nodes", header, n_read);
      }



      std::string
      MshScanner::name_of(const Element &element)
      {
        return std::string(element.type == hexahedron_type ? "hexahedron " :
                                                             "quadrangle ") +
               std::to_string(element.number);
      }



      std::string
      MshScanner::describe(const Element &element)
      {
        return name_of(element) + " (line " + std::to_string(element.line + 1) +
               ")";
      }



      void
      MshScanner::add_element(Element element)
      {
        const std::size_t l = element.line;
        if (!element_numbers.insert(element.number).second)
          fail(l,
               "element number " + std::to_string(element.number) +
                 " is used twice");
        for (unsigned int k = 0; k < element.n_nodes; ++k)
          if (node_position.count(element.nodes[k]) == 0)
            fail(l,
                 "element " + std::to_string(element.number) + " uses node " +
                   std::to_string(element.nodes[k]) +
                   ", which the $Nodes section does not define");
        NodeList sorted = element.nodes;
        std::sort(sorted.begin(), sorted.end());
        for (unsigned int k = 1; k < sorted.size(); ++k)
          if (sorted[k] == sorted[k - 1])
            fail(l,
                 "element " + std::to_string(element.number) + " uses node " +
                   std::to_string(sorted[k]) + " twice");

        // msh 4.1 takes the physical tag from the element's entity.
        const std::string where =
          version_4 ? std::string(" (") +
                        entity_name(element.type == hexahedron_type ? 3 : 2) +
                        " " + std::to_string(element.entity) + ")" :
                      std::string();
        if (element.type == hexahedron_type)
          {
            if (element.physical_tag <= 0)
              fail(l,
                   "hexahedron " + std::to_string(element.number) + where +
                     " has no physical volume tag" +
                     (element.physical_tag == 0 ? " (its tag is 0)" : "") +
                     ": every cell needs one, it becomes the material id "
                     "(put the volume in a Physical Volume with a tag >= 1)");
            hexahedra.push_back(element);
          }
        else if (element.type == quadrangle_type)
          {
            if (element.physical_tag < 0)
              fail(l,
                   "quadrangle " + std::to_string(element.number) + where +
                     " has no physical surface tag: boundary quadrangles "
                     "are only needed to carry one");
            if (element.physical_tag == 0)
              fail(l,
                   "quadrangle " + std::to_string(element.number) + where +
                     " has the physical surface tag 0: number physical "
                     "surfaces from 1, as deal.II gives the boundary id 0 "
                     "to every boundary face without a physical surface");
            quadrangles.push_back(element);
          }
      }



      void
      MshScanner::refuse_type(const std::size_t line,
                              const long long   number,
                              const long long   type) const
      {
        fail(line,
             "element " + std::to_string(number) + " is a " +
               type_in_words(type) +
               ": only hexahedral meshes are supported (hexahedra, with "
               "quadrangles for the physical surfaces; points and lines "
               "are ignored)");
      }



      Element
      MshScanner::element_of_record(const std::size_t l) const
      {
        // number type n_tags tags... nodes...
        const auto fields = tokens_of(lines[l]);
        if (fields.size() < 3)
          fail(l,
               "expected 'number type number-of-tags tags... nodes...', "
               "found '" +
                 excerpt(lines[l]) + "'");
        Element element;
        element.line   = l;
        element.number = integer(l, fields[0], "an element number", 1, max_tag);
        const long long type =
          integer(l, fields[1], "an element type", 1, max_tag);
        const AcceptedType *accepted = accepted_type(type);
        if (accepted == nullptr)
          refuse_type(l, element.number, type);
        element.type = accepted->type;
        const long long n_tags =
          integer(l, fields[2], "the number of tags", 0, 100);
        element.n_nodes            = accepted->n_nodes;
        const std::size_t expected = 3 + n_tags + element.n_nodes;
        if (fields.size() != expected)
          fail(l,
               "a " + std::string(accepted->name) + " with " +
                 std::to_string(n_tags) + " tags needs " +
                 std::to_string(expected) + " numbers, found " +
                 std::to_string(fields.size()) + ": '" + excerpt(lines[l]) +
                 "'");
        element.physical_tag = -1;
        for (long long t = 0; t < n_tags; ++t)
          {
            const long long tag = integer(l,
                                          fields[3 + t],
                                          t == 0 ? "a physical tag" : "a tag",
                                          t == 0 ? 0 : -max_tag,
                                          max_tag);
            if (t == 0)
              element.physical_tag = tag;
          }
        for (unsigned int k = 0; k < element.n_nodes; ++k)
          element.nodes[k] =
            integer(l, fields[3 + n_tags + k], "a node tag", 1, max_tag);
        return element;
      }



      void
      MshScanner::refuse_block(const std::size_t block,
                               const std::size_t position,
                               const std::size_t end,
                               const long long   type) const
      {
        // Name the first element of the block.
        std::size_t l = position;
        while (l < end && trim(lines[l]).empty())
          ++l;
        const auto first = (l < end) ? tokens_of(lines[l]) :
                                       std::vector<std::string_view>();
        long long  number = 0;
        if (first.empty() ||
            std::from_chars(first[0].data(),
                            first[0].data() + first[0].size(),
                            number)
                .ec != std::errc())
          fail(block,
               "the elements of this block are " + type_in_words(type) +
                 "s: only hexahedral meshes are supported");
        refuse_type(l, number, type);
      }



      void
      MshScanner::scan_elements()
      {
        const auto [begin, end] = sections.at("Elements");
        std::size_t position    = begin + 1;

        if (!version_4)
          {
            for (const std::size_t l :
                 counted_records(position, end, "element", "Elements"))
              add_element(element_of_record(l));
            return;
          }

        // msh 4.1: numEntityBlocks numElements minTag maxTag, then per
        // block: entityDim entityTag elementType numElementsInBlock and one
        // line per element: tag node tags...
        const BlockHeader header = block_header(position, end, "element");
        long long         n_read = 0;
        for (long long b = 0; b < header.n_blocks; ++b)
          {
            const std::size_t block =
              next_block(position, end, "element", b, header);
            const auto block_fields = tokens(block,
                                             4,
                                             "entity dimension and tag, "
                                             "element type, number of "
                                             "elements");
            const long long dim =
              integer(block, block_fields[0], "an entity dimension", 0, 3);
            const long long entity =
              integer(block, block_fields[1], "an entity tag", 1, max_tag);
            const long long type =
              integer(block, block_fields[2], "an element type", 1, max_tag);
            const long long n_in_block = integer(
              block, block_fields[3], "a number of elements", 0, max_tag);
            const AcceptedType *accepted = accepted_type(type);
            if (accepted == nullptr)
              refuse_block(block, position, end, type);
            if (accepted->dim != dim)
              fail(block,
                   "a block of " + std::string(accepted->name) +
                     "s in an entity of dimension " + std::to_string(dim));
            const auto physical = entity_physical.find({dim, entity});
            if (physical == entity_physical.end())
              fail(block,
                   "the elements of this block belong to " +
                     std::string(entity_name(dim)) + " " +
                     std::to_string(entity) +
                     ", which the $Entities section does not define");
            const bool keep = (accepted->type == hexahedron_type ||
                               accepted->type == quadrangle_type);
            if (keep)
              kept_blocks.emplace_back(block, std::vector<std::size_t>());
            for (long long k = 0; k < n_in_block; ++k)
              {
                const std::size_t l =
                  next_record(position,
                              end,
                              "element " + std::to_string(k + 1) +
                                " of the block in line " +
                                std::to_string(block + 1));
                const auto element_fields =
                  tokens(l,
                         1 + accepted->n_nodes,
                         std::string("the tag and the nodes of a ") +
                           accepted->name);
                Element element;
                element.line = l;
                element.type = accepted->type;
                element.number =
                  integer(l, element_fields[0], "an element tag", 1, max_tag);
                element.n_nodes      = accepted->n_nodes;
                element.physical_tag = physical->second;
                element.entity       = entity;
                for (unsigned int j = 0; j < element.n_nodes; ++j)
                  element.nodes[j] =
                    integer(l, element_fields[1 + j], "a node tag", 1, max_tag);
                add_element(element);
                if (keep)
                  kept_blocks.back().second.push_back(l);
              }
            n_read += n_in_block;
          }
        check_blocks_end(position, end, "element", "Elements", header, n_read);
      }



      void
      MshScanner::check_hexahedra()
      {
        if (hexahedra.empty())
          fail("the file has no hexahedra (" +
               std::to_string(quadrangles.size()) +
               " quadrangles): export the volume mesh of hexahedra, with "
               "Physical Volume groups");

        // The corners of Gmsh's reference hexahedron, as bits (x, y, z):
        // nodes 0-3 counter-clockwise at z = 0, 4-7 above them.
        constexpr std::array<unsigned int, 8> node_of_bits = {
          {0, 1, 3, 2, 4, 5, 7, 6}};
        constexpr std::array<unsigned int, 8> bits_of_node = {
          {0, 1, 3, 2, 4, 5, 7, 6}};

        std::unordered_map<NodeList, std::size_t, HashNodes> cells;
        for (std::size_t h = 0; h < hexahedra.size(); ++h)
          {
            const Element &hex = hexahedra[h];

            NodeList sorted = hex.nodes;
            std::sort(sorted.begin(), sorted.end());
            const auto inserted = cells.emplace(sorted, h);
            if (!inserted.second)
              fail(hex.line,
                   name_of(hex) + " has the same nodes as " +
                     describe(hexahedra[inserted.first->second]) +
                     ": is the volume in two physical groups?");

            // The Jacobian of the trilinear map at each corner is, up to a
            // positive factor, the triple product of the three edges that
            // leave the corner in the directions of increasing x, y, z of
            // the reference cell. All eight must be positive; all eight
            // negative is a mirrored vertex order.
            std::array<dealii::Point<3>, 8> x;
            for (unsigned int v = 0; v < 8; ++v)
              x[v] = node_position.at(hex.nodes[v]);
            unsigned int n_negative = 0;
            int          first_bad  = -1;
            for (unsigned int v = 0; v < 8; ++v)
              {
                const unsigned int                  bits = bits_of_node[v];
                std::array<dealii::Tensor<1, 3>, 3> edge;
                for (unsigned int d = 0; d < 3; ++d)
                  edge[d] = x[node_of_bits[bits | (1u << d)]] -
                            x[node_of_bits[bits & ~(1u << d)]];
                const double jacobian =
                  dealii::scalar_product(edge[0],
                                         dealii::cross_product_3d(edge[1],
                                                                  edge[2]));
                if (jacobian < 0.)
                  ++n_negative;
                if (!(jacobian > 0.) && first_bad < 0)
                  first_bad = v;
              }
            if (n_negative == 8)
              fail(hex.line,
                   name_of(hex) +
                     " is mirrored: its Jacobian is negative at all eight "
                     "corners (its nodes are listed in the opposite "
                     "orientation to Gmsh's hexahedron)");
            if (first_bad >= 0)
              fail(hex.line,
                   name_of(hex) +
                     " is inverted or degenerate: its Jacobian is not "
                     "positive at its corner node " +
                     std::to_string(hex.nodes[first_bad]));
          }
      }



      void
      MshScanner::check_quadrangles() const
      {
        // Gmsh's hexahedron faces, each as a cycle of its local nodes.
        constexpr unsigned int faces[6][4] = {{0, 3, 2, 1},
                                              {0, 1, 5, 4},
                                              {0, 4, 7, 3},
                                              {1, 2, 6, 5},
                                              {2, 3, 7, 6},
                                              {4, 5, 6, 7}};
        struct Face
        {
          unsigned int             n_cells = 0;
          std::size_t              hex     = 0;
          std::array<long long, 4> cycle   = {};
          const Element           *quad    = nullptr;
        };
        std::unordered_map<std::array<long long, 4>, Face, HashNodes> face_map;
        for (std::size_t h = 0; h < hexahedra.size(); ++h)
          for (const auto &face : faces)
            {
              std::array<long long, 4> cycle;
              for (unsigned int k = 0; k < 4; ++k)
                cycle[k] = hexahedra[h].nodes[face[k]];
              std::array<long long, 4> key = cycle;
              std::sort(key.begin(), key.end());
              Face &entry = face_map[key];
              if (++entry.n_cells == 1)
                {
                  entry.hex   = h;
                  entry.cycle = cycle;
                }
              else if (entry.n_cells == 3)
                fail(hexahedra[h].line,
                     "a face of " + name_of(hexahedra[h]) +
                       " is shared by three or more hexahedra (" +
                       describe(hexahedra[entry.hex]) + " is one)");
            }

        for (const Element &quad : quadrangles)
          {
            std::array<long long, 4> key = {
              {quad.nodes[0], quad.nodes[1], quad.nodes[2], quad.nodes[3]}};
            std::sort(key.begin(), key.end());
            const auto found = face_map.find(key);
            if (found == face_map.end())
              fail(quad.line,
                   name_of(quad) + " (physical surface " +
                     std::to_string(quad.physical_tag) +
                     ") is not a face of any hexahedron: is the surface "
                     "mesh conforming to the volume mesh?");
            Face &face = found->second;
            if (face.n_cells != 1)
              fail(quad.line,
                   name_of(quad) + " (physical surface " +
                     std::to_string(quad.physical_tag) +
                     ") is an interior face (between " +
                     describe(hexahedra[face.hex]) +
                     " and another): a physical surface must lie on the "
                     "boundary");
            if (face.quad != nullptr)
              fail(quad.line,
                   name_of(quad) + " covers the same face as " +
                     describe(*face.quad) +
                     ": a boundary face takes one physical surface tag (is "
                     "the surface in two physical groups?)");
            face.quad = &quad;
            // The same cycle, in either direction, from any start.
            bool same_cycle = false;
            for (unsigned int shift = 0; shift < 4; ++shift)
              {
                bool forward = true, backward = true;
                for (unsigned int k = 0; k < 4; ++k)
                  {
                    forward &= (quad.nodes[k] == face.cycle[(shift + k) % 4]);
                    backward &=
                      (quad.nodes[k] == face.cycle[(shift + 4 - k) % 4]);
                  }
                same_cycle |= forward || backward;
              }
            if (!same_cycle)
              fail(quad.line,
                   name_of(quad) +
                     " lists the nodes of a face in a crossed order (not "
                     "around the face)");
          }
      }



      std::string
      MshScanner::text_for_deal_ii() const
      {
        // Only what GridIn::read_msh() needs, in the order it expects:
        // points and lines, the physical names and any other section left
        // out. The nodes (and the msh 4.1 entities) go as they are in the
        // file.
        const auto section_text = [&](const std::string &name) {
          std::string text;
          const auto  range = sections.at(name);
          for (std::size_t l = range.first; l <= range.second; ++l)
            {
              text += lines[l];
              text += '\n';
            }
          return text;
        };
        std::string text = "$MeshFormat\n" + format_line + "\n$EndMeshFormat\n";
        if (version_4)
          text += section_text("Entities");
        text += section_text("Nodes");
        text += "$Elements\n";
        if (!version_4)
          {
            // number type 1 physical-tag nodes...: the validated numbers,
            // without the other tags (partition tags may be negative, which
            // deal.II reads as unsigned).
            text += std::to_string(hexahedra.size() + quadrangles.size());
            text += '\n';
            for (const auto *elements : {&quadrangles, &hexahedra})
              for (const Element &element : *elements)
                {
                  text += std::to_string(element.number) + ' ' +
                          std::to_string(element.type) + " 1 " +
                          std::to_string(element.physical_tag);
                  for (unsigned int k = 0; k < element.n_nodes; ++k)
                    text += ' ' + std::to_string(element.nodes[k]);
                  text += '\n';
                }
          }
        else
          {
            long long min_tag = max_tag, max_number = 0;
            for (const auto *elements : {&quadrangles, &hexahedra})
              for (const Element &element : *elements)
                {
                  min_tag    = std::min(min_tag, element.number);
                  max_number = std::max(max_number, element.number);
                }
            text += std::to_string(kept_blocks.size()) + ' ' +
                    std::to_string(hexahedra.size() + quadrangles.size()) +
                    ' ' + std::to_string(min_tag) + ' ' +
                    std::to_string(max_number) + '\n';
            for (const auto &block : kept_blocks)
              {
                text += lines[block.first];
                text += '\n';
                for (const std::size_t l : block.second)
                  {
                    text += lines[l];
                    text += '\n';
                  }
              }
          }
        text += "$EndElements\n";
        return text;
      }



      std::string
      MshScanner::scan()
      {
        scan_mesh_format();
        scan_physical_names();
        scan_entities();
        scan_nodes();
        scan_elements();
        check_hexahedra();
        check_quadrangles();
        return text_for_deal_ii();
      }
    } // namespace



    void
    read_gmsh_mesh(dealii::Triangulation<3, 3> &triangulation,
                   const std::string           &file_name,
                   const std::string           &entry_path)
    {
      AssertThrow(triangulation.n_levels() == 0,
                  dealii::ExcMessage(
                    "read_gmsh_mesh() needs an empty triangulation"));

      // Read the file once, into memory: the checks and deal.II then see
      // the same text.
      std::error_code error;
      if (std::filesystem::is_directory(file_name, error))
        throw InputError(entry_path,
                         file_name +
                           ": cannot open the mesh file (it is a directory)");
      std::ifstream file(file_name, std::ios::binary);
      std::string   text;
      if (file)
        {
          std::ostringstream contents;
          contents << file.rdbuf();
          text = contents.str();
        }
      if (!file || file.bad())
        throw InputError(entry_path, file_name + ": cannot open the mesh file");

      MshScanner        scanner(file_name, entry_path, text);
      const std::string checked = scanner.scan();

      dealii::GridIn<3> grid_in;
      grid_in.attach_triangulation(triangulation);
      std::istringstream stream(checked);
      try
        {
          grid_in.read_msh(stream);
        }
      catch (const dealii::ExceptionBase &exception)
        {
          scanner.fail("deal.II cannot build a mesh from this file: " +
                       exception_message(exception));
        }
    }
  } // namespace io
} // namespace rubberdyn
