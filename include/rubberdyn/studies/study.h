#ifndef rubberdyn_studies_study_h
#define rubberdyn_studies_study_h

#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace rubberdyn
{
  /**
   * Studies: what `rubberdyn FILE.prm` runs. A study reads all of its
   * parameters (and rejects bad ones) in its constructor, before anything
   * is written, and does its work in run(); `rubberdyn --check FILE.prm`
   * constructs it and calls check() instead.
   */
  namespace studies
  {
    /**
     * Interface of a study.
     */
    class Study
    {
    public:
      virtual ~Study() = default;

      /**
       * Run the study, writing results below the output directory and a log
       * to @p log.
       */
      virtual void
      run(std::ostream &log) = 0;

      /**
       * Validate the study as far as is possible without running it, and
       * without writing any file: what `rubberdyn --check FILE.prm` does
       * after construction, so that a user learns of bad input before
       * submitting a long job. A study may override it to build its model
       * (mesh, parts, conditions, contacts) and compute what the run needs
       * first (the first stable time step), throwing an InputError that
       * names the entry at fault; it may write a short summary to @p log.
       *
       * The default does nothing: construction has read and validated
       * every parameter already.
       *
       * @throws InputError on invalid input.
       */
      virtual void
      check(std::ostream &log);
    };


    /**
     * The registry of studies; `set Study = ...` chooses one by name.
     */
    namespace registry
    {
      /**
       * The names listed by the parameter file's `Names` entries, by the
       * path of the subsection that holds them (see
       * io::read_listed_names()): studies declare a subsection per name.
       */
      using ListedNames = std::map<std::string, std::vector<std::string>>;

      /** Declares the study's own parameters (at the top level). */
      using DeclareFunction =
        std::function<void(dealii::ParameterHandler &, const ListedNames &)>;

      /**
       * Creates the study from the parsed parameters; the second argument is
       * the parameter file's path (empty for --default), against which a
       * study resolves relative file names.
       */
      using CreateFunction = std::function<std::unique_ptr<Study>(
        dealii::ParameterHandler &,
        const std::string &)>;

      /** Add a study; returns a dummy value for static registration. */
      int
      register_study(const std::string &    name,
                     const std::string &    description,
                     const DeclareFunction &declare,
                     const CreateFunction & create);

      /** The registered names, sorted. */
      std::vector<std::string>
      names();

      /**
       * Declare everything a parameter file may hold: `Study`, the shared
       * groups (`Time integration`, `Contact`, `Output`, see
       * rubberdyn::parameters) and every registered study's parameters.
       */
      void
      declare_parameters(dealii::ParameterHandler &prm,
                         const ListedNames &       names = {});

      /**
       * Create the study chosen by `Study`.
       *
       * @throws InputError on invalid parameters.
       */
      std::unique_ptr<Study>
      create(dealii::ParameterHandler &prm,
             const std::string &       parameter_file = "");
    } // namespace registry
  }   // namespace studies
} // namespace rubberdyn

/**
 * Register study class @p classname (constructor from a non-const
 * ParameterHandler, static `declare_parameters(ParameterHandler &, const
 * ListedNames &)`) under @p name.
 */
#define RUBBERDYN_REGISTER_STUDY(classname, name, description)        \
  namespace                                                           \
  {                                                                   \
    const int dummy_register_study_##classname =                      \
      ::rubberdyn::studies::registry::register_study(                 \
        name,                                                         \
        description,                                                  \
        &classname::declare_parameters,                               \
        [](::dealii::ParameterHandler &prm, const std::string &)      \
          -> std::unique_ptr<::rubberdyn::studies::Study> {           \
          return std::make_unique<classname>(prm);                    \
        });                                                           \
  }

#endif
