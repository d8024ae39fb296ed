// A parameter-file fuzzer: mutated copies of every shipped parameter file
// (parameter_files/*.prm, globbed, so a new file is fuzzed without a change
// here) are given to 'rubberdyn --check', and a few, shortened, to a real
// run. Every case must either succeed or fail cleanly:
//
// - no signal (crash, abort), no hang (each case has a time limit);
// - on success of '--check', stdout ending in the one line that says the
//   study is valid (a study with a model reports it before);
// - on failure a non-zero exit code below 100 and exactly one line on
//   stderr that names the input file and the entry (or subsection) that is
//   wrong, and for a changed value that entry's full path ("A/B/Name");
// - never a deal.II banner ("An error occurred", a line of dashes);
// - 'rubberdyn --check' writes nothing, and a rejected input writes nothing:
//   each case runs in an empty directory (the shipped files' output
//   directories are relative) that must stay empty.
//
// The mutations: a number set to 0, negative, NaN, 1e308, 1e-320 (a
// denormal); a value emptied or made 100 000 characters long; an entry
// deleted, duplicated or misspelt; a subsection left unclosed; the file
// truncated at a random byte. The cases are drawn from a fixed seed, so a
// run is reproducible; each kind of mutation meets each file (the kind
// cycles fastest, then the file).
//
// Speed: starting the executable costs about 0.7 s of CPU time (loading
// deal.II and its dependencies, about 200 shared libraries), which would
// make 300 cases take minutes. So most '--check' cases run in a child
// forked from this program, which has the libraries loaded already and runs
// exactly what app/main.cc runs (MPI_InitFinalize, then
// rubberdyn::app::run_command_line()) in a fresh process, with the same
// isolation: its own directory, exit code, signals and time limit. The real
// runs (every 40th case) and every 25th '--check' case run the executable
// itself. Open MPI is told to start quickly (see main()). Two cases run at
// a time.
//
// Usage:
//   fuzz_parameter_files EXECUTABLE PARAMETER_DIR WORK_DIR
//                        [--seed N] [--cases N] [--timeout SECONDS]
//                        [--jobs N] [--verbose 1]
//
// WORK_DIR is emptied first. The mutated input of every failing case is
// kept in WORK_DIR/failures/ (with a README holding the mutation, the
// failure and the command to rerun it, and the case's stdout and stderr)
// so it can be reproduced by hand; the other cases leave nothing. The last
// line is a summary "fuzz: N cases (...): P passed, F failed"; the exit
// code is non-zero if any case failed.

#include <deal.II/base/mpi.h>

#include <rubberdyn/app/command_line.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <signal.h>
#include <sstream>
#include <string>
#include <sys/types.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace
{
  std::string
  read_file(const fs::path &path)
  {
    std::ifstream      in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  void
  write_file(const fs::path &path, const std::string &text)
  {
    std::ofstream out(path, std::ios::binary);
    out << text;
  }

  std::string
  trim(const std::string &s)
  {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos)
      return "";
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
  }

  /** A line of a parameter file, as far as the mutations need to know. */
  struct Line
  {
    enum class Kind
    {
      set,
      subsection,
      end,
      other
    };
    std::string text;
    Kind        kind = Kind::other;
    std::string name;  // of a 'set' line
    std::string value; // of a 'set' line, without comment

    /** Whether the value is a finite number (the numeric mutations). */
    bool
    numeric() const
    {
      if (kind != Kind::set || value.empty())
        return false;
      char        *end = nullptr;
      const double x   = std::strtod(value.c_str(), &end);
      return *end == '\0' && std::isfinite(x);
    }
  };

  std::vector<Line>
  parse_lines(const std::string &text)
  {
    std::vector<Line>  lines;
    std::istringstream in(text);
    std::string        raw;
    while (std::getline(in, raw))
      {
        Line line;
        line.text               = raw;
        const std::string plain = trim(raw.substr(0, raw.find('#')));
        if (plain.rfind("set ", 0) == 0 && plain.find('=') != std::string::npos)
          {
            line.kind  = Line::Kind::set;
            line.name  = trim(plain.substr(4, plain.find('=') - 4));
            line.value = trim(plain.substr(plain.find('=') + 1));
          }
        else if (plain.rfind("subsection ", 0) == 0)
          line.kind = Line::Kind::subsection;
        else if (plain == "end")
          line.kind = Line::Kind::end;
        lines.push_back(line);
      }
    return lines;
  }

  /** The subsections ("A/B/") that line @p n of @p lines lies in. */
  std::string
  subsection_path(const std::vector<Line> &lines, const std::size_t n)
  {
    std::vector<std::string> path;
    for (std::size_t i = 0; i < n; ++i)
      if (lines[i].kind == Line::Kind::subsection)
        path.push_back(trim(trim(lines[i].text).substr(11)));
      else if (lines[i].kind == Line::Kind::end && !path.empty())
        path.pop_back();
    std::string result;
    for (const std::string &name : path)
      result += name + '/';
    return result;
  }

  std::string
  join_lines(const std::vector<Line> &lines)
  {
    std::string text;
    for (const Line &line : lines)
      text += line.text + '\n';
    return text;
  }

  /** The text of a 'set' line with another value (comment dropped). */
  std::string
  with_value(const Line &line, const std::string &value)
  {
    const std::string indent =
      line.text.substr(0, line.text.find_first_not_of(" \t"));
    return indent + "set " + line.name + " = " + value;
  }

  enum class Mutation
  {
    zero,
    negative,
    nan,
    huge,
    denormal,
    empty,
    long_value,
    delete_entry,
    duplicate_entry,
    misspell_entry,
    unclose_subsection,
    truncate
  };
  constexpr unsigned int n_mutations = 12;

  const char *
  mutation_name(const Mutation m)
  {
    static const char *names[n_mutations] = {"zero",
                                             "negative",
                                             "NaN",
                                             "1e308",
                                             "1e-320",
                                             "empty value",
                                             "100000-character value",
                                             "deleted entry",
                                             "duplicated entry",
                                             "misspelt entry",
                                             "unclosed subsection",
                                             "truncated file"};
    return names[static_cast<unsigned int>(m)];
  }

  bool
  changes_a_value(const Mutation m)
  {
    return static_cast<unsigned int>(m) <=
           static_cast<unsigned int>(Mutation::long_value);
  }

  /** A deterministic generator (std::mt19937_64 is fully specified). */
  class Random
  {
  public:
    explicit Random(const std::uint64_t seed)
      : engine(seed)
    {}

    /** A number in [0, n), n > 0 (the slight modulo bias does not
     * matter here). */
    std::size_t
    below(const std::size_t n)
    {
      return engine() % n;
    }

  private:
    std::mt19937_64 engine;
  };

  /** One mutated input. */
  struct Case
  {
    unsigned int index;
    fs::path     source;
    Mutation     mutation;
    std::string  description; // what was changed
    std::string  entry;       // if a value changed, its entry's path A/B/Name
    std::string  text;        // the mutated file
    bool         real_run;    // run the study instead of --check
  };

  /** Indices of the lines of @p lines that satisfy @p pred. */
  template <typename Predicate>
  std::vector<std::size_t>
  lines_where(const std::vector<Line> &lines, Predicate pred)
  {
    std::vector<std::size_t> result;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (pred(lines[i]))
        result.push_back(i);
    return result;
  }

  /**
   * Entries a real run must keep: they set its size and length (the real
   * runs are shortened through them) or where it writes.
   */
  bool
  protected_in_real_run(const Line &line)
  {
    return line.name == "End time" || line.name == "Global refinement" ||
           line.name == "Number of steps" || line.name == "Output directory" ||
           line.name == "Study" || line.name == "Quasi-static end time";
  }

  /**
   * Shorten a study for a real run: the drop test on its coarsest mesh
   * (80 cells) for a few hundredths of a millisecond, a quasi-static load
   * path to a fiftieth of its usual end (t = 0.02 of 1: two of the ironing
   * benchmark's steps of 0.01, 10 s, where five took 25 s on a loaded
   * machine against the 30 s timeout), no field output.
   */
  std::vector<Line>
  shortened(std::vector<Line> lines)
  {
    for (Line &line : lines)
      if (line.kind == Line::Kind::set)
        {
          std::string value;
          if (line.name == "Global refinement")
            value = "1";
          else if (line.name == "End time")
            value = "0.02";
          else if (line.name == "Quasi-static end time")
            value = "0.02";
          else if (line.name == "Field output interval")
            value = "0";
          else
            continue;
          line.text  = with_value(line, value);
          line.value = value;
        }
    return lines;
  }

  /**
   * Make case @p index from the file @p source (text @p text). Returns
   * false if the mutation has nothing to act on in this file.
   */
  bool
  make_case(const unsigned int index,
            const fs::path    &source,
            const std::string &original,
            const Mutation     mutation,
            const bool         real_run,
            Random            &random,
            Case              &c)
  {
    std::vector<Line> lines = parse_lines(original);
    if (real_run)
      lines = shortened(lines);
    c.index    = index;
    c.source   = source;
    c.mutation = mutation;
    c.real_run = real_run;
    c.entry.clear();

    const auto pick = [&](const std::vector<std::size_t> &candidates,
                          std::size_t                    &i) {
      if (candidates.empty())
        return false;
      i = candidates[random.below(candidates.size())];
      return true;
    };
    const auto allowed = [&](const Line &line) {
      return line.kind == Line::Kind::set &&
             !(real_run && protected_in_real_run(line));
    };

    std::size_t i = 0;
    if (changes_a_value(mutation))
      {
        const bool numeric_only =
          (mutation != Mutation::empty && mutation != Mutation::long_value);
        if (!pick(lines_where(lines,
                              [&](const Line &line) {
                                return allowed(line) &&
                                       (!numeric_only || line.numeric());
                              }),
                  i))
          return false;
        std::string value;
        switch (mutation)
          {
            case Mutation::zero:
              value = "0";
              break;
            case Mutation::negative:
              value =
                (lines[i].value[0] == '-' ? "-1e3" : "-" + lines[i].value);
              break;
            case Mutation::nan:
              value = (random.below(2) ? "nan" : "NaN");
              break;
            case Mutation::huge:
              value = "1e308";
              break;
            case Mutation::denormal:
              value = "1e-320";
              break;
            case Mutation::empty:
              value = "";
              break;
            case Mutation::long_value:
              {
                // Digits (a number too large for a double), letters, or
                // a number with a long run of spaces inside.
                const std::size_t n = 100000;
                switch (random.below(3))
                  {
                    case 0:
                      value = std::string(n, '7');
                      break;
                    case 1:
                      value = std::string(n, 'x');
                      break;
                    default:
                      value = "1" + std::string(n - 2, ' ') + "2";
                  }
                break;
              }
            default:
              break;
          }
        c.entry       = subsection_path(lines, i) + lines[i].name;
        c.description = "line " + std::to_string(i + 1) + ": '" +
                        lines[i].name + "' set to " +
                        (mutation == Mutation::long_value ?
                           std::string("a 100000-character value") :
                           "'" + value + "'");
        lines[i].text = with_value(lines[i], value);
        c.text        = join_lines(lines);
        return true;
      }

    switch (mutation)
      {
        case Mutation::delete_entry:
          if (!pick(lines_where(lines, allowed), i))
            return false;
          c.description = "line " + std::to_string(i + 1) + " ('" +
                          lines[i].name + "') deleted";
          lines.erase(lines.begin() + i);
          break;
        case Mutation::duplicate_entry:
          if (!pick(lines_where(lines, allowed), i))
            return false;
          c.description = "line " + std::to_string(i + 1) + " ('" +
                          lines[i].name + "') duplicated";
          lines.insert(lines.begin() + i, lines[i]);
          break;
        case Mutation::misspell_entry:
          {
            if (!pick(lines_where(lines, allowed), i))
              return false;
            // Swap two neighbouring characters that differ, or drop one.
            std::string       name = lines[i].name;
            const std::size_t k    = random.below(name.size());
            if (k + 1 < name.size() && name[k] != name[k + 1])
              std::swap(name[k], name[k + 1]);
            else
              name.erase(k, 1);
            if (name.empty())
              name = "x";
            c.description = "line " + std::to_string(i + 1) + ": '" +
                            lines[i].name + "' misspelt as '" + name + "'";
            Line misspelt = lines[i];
            misspelt.name = name;
            lines[i].text = with_value(misspelt, lines[i].value);
            break;
          }
        case Mutation::unclose_subsection:
          if (real_run || !pick(lines_where(lines,
                                            [](const Line &line) {
                                              return line.kind ==
                                                     Line::Kind::end;
                                            }),
                                i))
            return false;
          c.description = "line " + std::to_string(i + 1) + " ('end') deleted";
          lines.erase(lines.begin() + i);
          break;
        case Mutation::truncate:
          {
            if (real_run)
              return false;
            const std::size_t at = random.below(original.size());
            c.description = "truncated after " + std::to_string(at) + " of " +
                            std::to_string(original.size()) + " bytes";
            c.text = original.substr(0, at);
            return true;
          }
        default:
          return false;
      }
    c.text = join_lines(lines);
    return true;
  }

  struct Outcome
  {
    bool        timed_out = false;
    bool        signaled  = false;
    int         signal    = 0;
    int         exit_code = 0;
    double      seconds   = 0.;
    std::string out, err;
  };

  /** A case whose process is running. */
  struct Running
  {
    Case     c;
    bool     in_process;
    fs::path input, directory, out_file, err_file, mpi_directory;
    pid_t    pid;
    std::chrono::steady_clock::time_point start;
  };

  /**
   * Start @p arguments in @p r.directory, stdout and stderr redirected to
   * r.out_file and r.err_file, in a process group of its own (so that a
   * time-out kills everything it started). With r.in_process, arguments[0]
   * is not executed: the forked child runs what app/main.cc runs with
   * these arguments.
   */
  void
  start(const std::vector<std::string> &arguments, Running &r)
  {
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = fork();
    if (pid < 0)
      {
        std::perror("fork");
        std::exit(2);
      }
    if (pid == 0)
      {
        setpgid(0, 0);
        // A session directory of its own: isolated singletons share one
        // name below /tmp, and one's clean-up removed another's.
        setenv("OMPI_MCA_orte_tmpdir_base", r.mpi_directory.c_str(), 1);
        if (chdir(r.directory.c_str()) != 0)
          _exit(120);
        const int out =
          open(r.out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err =
          open(r.err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_RDONLY);
        if (out < 0 || err < 0 || null < 0)
          _exit(121);
        dup2(null, 0);
        dup2(out, 1);
        dup2(err, 2);
        std::vector<char *> argv;
        for (const std::string &a : arguments)
          argv.push_back(const_cast<char *>(a.c_str()));
        argv.push_back(nullptr);
        if (r.in_process)
          {
            int    argc = arguments.size();
            char **args = argv.data();
            int    exit_code;
            {
              // As app/main.cc.
              dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, args, 1);
              exit_code = rubberdyn::app::run_command_line(argc, args);
            }
            // Without the static destructors of the 200 libraries, which
            // cost more than the case (0.17 s of CPU time); the cases run
            // through the executable have them.
            std::cout.flush();
            std::cerr.flush();
            std::fflush(nullptr);
            _exit(exit_code);
          }
        execv(argv[0], argv.data());
        _exit(122);
      }
    setpgid(pid, pid);
    r.pid   = pid;
    r.start = std::chrono::steady_clock::now();
  }

  /**
   * If the process of @p r has ended, or has run longer than @p timeout
   * seconds (then it is killed with its process group), fill @p outcome
   * and return true.
   */
  bool
  finished(const Running &r, const double timeout, Outcome &outcome)
  {
    int          status = 0;
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start)
        .count();
    if (waitpid(r.pid, &status, WNOHANG) != r.pid)
      {
        if (elapsed <= timeout)
          return false;
        outcome.timed_out = true;
        kill(-r.pid, SIGKILL);
        waitpid(r.pid, &status, 0);
      }
    outcome.seconds = elapsed;
    if (!outcome.timed_out)
      {
        if (WIFSIGNALED(status))
          {
            outcome.signaled = true;
            outcome.signal   = WTERMSIG(status);
          }
        else
          outcome.exit_code = WEXITSTATUS(status);
      }
    outcome.out = read_file(r.out_file);
    outcome.err = read_file(r.err_file);
    return true;
  }

  std::size_t
  count_lines(const std::string &text)
  {
    return std::count(text.begin(), text.end(), '\n') +
           (!text.empty() && text.back() != '\n' ? 1 : 0);
  }

  bool
  has_banner(const std::string &text)
  {
    return text.find("An error occurred") != std::string::npos ||
           text.find("--------") != std::string::npos ||
           text.find("Stacktrace") != std::string::npos;
  }

  /**
   * What is wrong with the outcome of case @p c, or an empty string.
   * @p input is the path the executable was given.
   */
  std::string
  judge(const Case     &c,
        const Outcome  &o,
        const fs::path &input,
        const fs::path &run_directory)
  {
    if (o.timed_out)
      return "timed out (a hang?)";
    if (o.signaled)
      return "killed by signal " + std::to_string(o.signal) + " (" +
             strsignal(o.signal) + ")";
    if (o.exit_code >= 100)
      return "exit code " + std::to_string(o.exit_code) +
             " (>= 100: a crash or an uncaught error)";
    if (has_banner(o.err) || has_banner(o.out))
      return "a deal.II banner instead of a one-line message";
    const bool empty_directory = fs::is_empty(run_directory);
    if (o.exit_code == 0)
      {
        if (!c.real_run)
          {
            if (!o.err.empty())
              return "'--check' succeeded but wrote to stderr";
            // A study with a model reports it first (cells, parts,
            // masses, smallest step); the last line says it is valid, once.
            const std::string valid = "' is a valid '";
            const std::size_t first = o.out.find(valid);
            if (first == std::string::npos ||
                o.out.find(valid, first + 1) != std::string::npos ||
                o.out.find('\n', first) + 1 != o.out.size())
              return "'--check' succeeded but did not end with one line "
                     "saying the study is valid";
            if (!empty_directory)
              return "'--check' wrote files";
          }
        return "";
      }
    if (count_lines(o.err) != 1)
      return "failed with " + std::to_string(count_lines(o.err)) +
             " lines on stderr instead of one";
    if (o.err.find(input.string()) == std::string::npos)
      return "the message does not name the input file";
    // A rejected input (exit code 2, and any failure of --check) writes
    // nothing and names the entry or subsection.
    if (!c.real_run || o.exit_code == 2)
      {
        if (!empty_directory)
          return "the input was rejected, but files were written";
        // A line that is no statement at all at the top level (a file
        // truncated in its first word) has only its number to name.
        if (o.err.find("entry '") == std::string::npos &&
            o.err.find("subsection '") == std::string::npos &&
            o.err.find(", at the top level: ") == std::string::npos)
          return "the message names no entry or subsection";
        // The changed entry, or, where the change makes another entry of
        // the same subsection wrong (an emptied constant list makes the
        // expression that uses it unparsable, an emptied list of names
        // leaves its subsections undeclared, an overflowing yield stress
        // makes a derived constant overflow), that subsection.
        const std::string subsection =
          c.entry.find('/') == std::string::npos ?
            c.entry :
            c.entry.substr(0, c.entry.rfind('/'));
        if (!c.entry.empty() && o.err.find(c.entry) == std::string::npos &&
            o.err.find("'" + subsection) == std::string::npos)
          return "the message does not name the changed entry '" + c.entry +
                 "'";
      }
    return "";
  }

  std::string
  one_line(std::string text, const std::size_t max_length = 300)
  {
    std::replace(text.begin(), text.end(), '\n', ' ');
    if (text.size() > max_length)
      text = text.substr(0, max_length) + "...";
    return text;
  }
} // namespace



int
main(int argc, char *argv[])
{
  if (argc < 4)
    {
      std::cerr << "usage: " << argv[0]
                << " EXECUTABLE PARAMETER_DIR WORK_DIR [--seed N] "
                   "[--cases N] [--timeout SECONDS] [--jobs N] "
                   "[--verbose 1]\n";
      return 2;
    }
  const fs::path executable = fs::absolute(argv[1]);
  const fs::path parameter_dir(argv[2]);
  const fs::path work    = fs::absolute(argv[3]);
  std::uint64_t  seed    = 20240611;
  unsigned int   n_cases = 312;
  double         timeout = 30.;
  unsigned int   n_jobs  = 2;
  bool           verbose = false;
  // Every real_run_every-th case is a (shortened) real run, and every
  // exec_every-th '--check' runs the executable rather than a fork.
  const unsigned int real_run_every = 40;
  const unsigned int exec_every     = 25;
  for (int a = 4; a + 1 < argc; a += 2)
    {
      const std::string option = argv[a];
      if (option == "--seed")
        seed = std::stoull(argv[a + 1]);
      else if (option == "--cases")
        n_cases = std::stoul(argv[a + 1]);
      else if (option == "--timeout")
        timeout = std::stod(argv[a + 1]);
      else if (option == "--jobs")
        n_jobs = std::max(1ul, std::stoul(argv[a + 1]));
      else if (option == "--verbose")
        verbose = (std::string(argv[a + 1]) == "1");
      else
        {
          std::cerr << "unknown option " << option << '\n';
          return 2;
        }
    }
  // Each process is a single-rank MPI job (Open MPI: a singleton without
  // a daemon, and the ob1 messaging layer, whose start-up does not probe
  // for network devices as UCX's does: 0.2 s instead of 0.5 s).
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 1);
  setenv("OMPI_MCA_pml", "ob1", 1);

  std::vector<fs::path> sources;
  for (const auto &entry : fs::directory_iterator(parameter_dir))
    if (entry.path().extension() == ".prm")
      sources.push_back(entry.path());
  std::sort(sources.begin(), sources.end());
  if (sources.empty())
    {
      std::cerr << "no .prm files in " << parameter_dir << '\n';
      return 2;
    }
  std::vector<std::string> originals;
  for (const fs::path &source : sources)
    originals.push_back(read_file(source));

  fs::remove_all(work);
  const fs::path inputs   = work / "inputs";
  const fs::path runs     = work / "runs";
  const fs::path failures = work / "failures";
  fs::create_directories(inputs);
  // Model studies name their meshes relative to the parameter file: the
  // mutated copies find them as the originals do.
  if (fs::exists(parameter_dir / "meshes"))
    fs::create_directory_symlink(fs::absolute(parameter_dir / "meshes"),
                                 inputs / "meshes");
  fs::create_directories(runs);

  std::cout << "fuzz: " << sources.size() << " parameter files from "
            << parameter_dir.string() << ", seed " << seed << ", " << n_cases
            << " cases, " << timeout << " s per case, " << n_jobs
            << " at a time" << std::endl;

  // The cases, made in a fixed order from the seed. The kind of mutation
  // cycles fastest, then the file; a combination with nothing to act on
  // (a value mutation in a file without numbers, an unclosed subsection in
  // a real run) is passed over.
  std::vector<Case> cases;
  {
    Random random(seed);
    for (unsigned int attempt = 0; cases.size() < n_cases; ++attempt)
      {
        if (attempt > 100 * (n_cases + 1))
          {
            std::cerr << "cannot make enough cases\n";
            return 2;
          }
        const unsigned int index = cases.size();
        const Mutation mutation  = static_cast<Mutation>(attempt % n_mutations);
        const std::size_t file   = (attempt / n_mutations) % sources.size();
        const bool real_run = (index % real_run_every == real_run_every - 1);
        Case       c;
        if (make_case(index,
                      sources[file],
                      originals[file],
                      mutation,
                      real_run,
                      random,
                      c))
          cases.push_back(std::move(c));
      }
  }

  const auto           start_time = std::chrono::steady_clock::now();
  unsigned int         n_passed = 0, n_failed = 0, n_real_runs = 0;
  unsigned int         n_executed = 0;
  std::vector<Running> running;
  std::size_t          next = 0;
  while (next < cases.size() || !running.empty())
    {
      while (next < cases.size() && running.size() < n_jobs)
        {
          Running r;
          r.c          = cases[next++];
          r.in_process = !r.c.real_run && (r.c.index % exec_every != 0);
          n_real_runs += r.c.real_run;
          n_executed += !r.in_process;
          const std::string stem = "case_" + std::to_string(r.c.index) + "_" +
                                   r.c.source.stem().string();
          r.input         = inputs / (stem + ".prm");
          r.directory     = runs / stem;
          r.out_file      = runs / (stem + ".stdout");
          r.err_file      = runs / (stem + ".stderr");
          r.mpi_directory = runs / (stem + ".mpi");
          fs::create_directories(r.mpi_directory);
          write_file(r.input, r.c.text);
          fs::create_directories(r.directory);
          std::vector<std::string> arguments = {executable.string()};
          if (!r.c.real_run)
            arguments.push_back("--check");
          arguments.push_back(r.input.string());
          start(arguments, r);
          running.push_back(std::move(r));
        }

      bool any_finished = false;
      for (auto r = running.begin(); r != running.end();)
        {
          Outcome o;
          if (!finished(*r, timeout, o))
            {
              ++r;
              continue;
            }
          any_finished = true;
          fs::remove_all(r->mpi_directory);
          const Case       &c       = r->c;
          const std::string verdict = judge(c, o, r->input, r->directory);
          if (verbose)
            std::cout << "case " << c.index << " ("
                      << c.source.filename().string() << ", "
                      << mutation_name(c.mutation) << ", " << c.description
                      << (c.real_run    ? ", real run" :
                          r->in_process ? ", --check in a fork" :
                                          ", --check")
                      << "): " << std::fixed << std::setprecision(2)
                      << o.seconds << " s, exit code " << o.exit_code
                      << (verdict.empty() ? "" : ", FAILED") << "\n  "
                      << one_line(o.err.empty() ? o.out : o.err) << std::endl;
          if (verdict.empty())
            {
              ++n_passed;
              fs::remove_all(r->directory);
              fs::remove(r->input);
              fs::remove(r->out_file);
              fs::remove(r->err_file);
              r = running.erase(r);
              continue;
            }

          ++n_failed;
          // Keep the input, the outputs and what was found for a rerun.
          const fs::path kept       = failures / r->input.stem();
          const fs::path kept_input = kept / r->input.filename();
          fs::create_directories(kept);
          fs::rename(r->input, kept_input);
          fs::rename(r->out_file, kept / "stdout");
          fs::rename(r->err_file, kept / "stderr");
          if (!fs::is_empty(r->directory))
            fs::rename(r->directory, kept / "written");
          else
            fs::remove(r->directory);
          write_file(kept / "README",
                     "case " + std::to_string(c.index) + " from " +
                       c.source.string() + ": " + mutation_name(c.mutation) +
                       ", " + c.description + "\nfailure: " + verdict +
                       "\nexit code " + std::to_string(o.exit_code) +
                       (o.signaled ? ", signal " + std::to_string(o.signal) :
                                     std::string()) +
                       "\nrerun in an empty directory: " + executable.string() +
                       (c.real_run ? " " : " --check ") + kept_input.string() +
                       "\n");
          std::cout << "FAILED case " << c.index << " ("
                    << c.source.filename().string() << ", "
                    << mutation_name(c.mutation) << ", " << c.description
                    << (c.real_run ? ", real run" : ", --check")
                    << "): " << verdict << "\n  stderr: " << one_line(o.err)
                    << "\n  input kept: " << kept_input.string() << std::endl;
          r = running.erase(r);
        }
      if (!any_finished)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }

  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time)
      .count();
  std::cout << "fuzz: " << cases.size() << " cases (" << n_real_runs
            << " real runs, " << n_executed
            << " through the executable, the others in a fork) in "
            << std::fixed << std::setprecision(1) << seconds
            << " s: " << n_passed << " passed, " << n_failed << " failed"
            << std::endl;
  if (n_failed > 0)
    std::cout << "fuzz: the failing inputs are in " << failures.string()
              << std::endl;
  return n_failed == 0 ? 0 : 1;
}
