#ifndef rubberdyn_app_command_line_h
#define rubberdyn_app_command_line_h

namespace rubberdyn
{
  /**
   * The command-line interface of the `rubberdyn` executable.
   */
  namespace app
  {
    /**
     * Interpret the command line and do what it asks:
     *
     * - `rubberdyn FILE.prm`: run the study the file describes;
     * - `rubberdyn --check FILE.prm`: read and validate the file and build
     *   its study (Study::check()) without running it or writing anything;
     *   one line on stdout and exit code 0 if it would run;
     * - `rubberdyn --default`: run the default study, every parameter at
     *   its default;
     * - `rubberdyn --print-parameters`: print every parameter with its
     *   documentation, allowed values and default, as a valid .prm file;
     * - `rubberdyn --fit-yeoh MODE=FILE.csv ...`: fit Yeoh constants to test
     *   data;
     * - `rubberdyn --help`.
     *
     * Bad input gives one readable message on stderr that names the file,
     * the entry and what is wrong, and a non-zero return value, before
     * anything is written.
     *
     * @return The process exit code.
     */
    int
    run_command_line(int argc, char *argv[]);
  } // namespace app
} // namespace rubberdyn

#endif
