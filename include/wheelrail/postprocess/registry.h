/**
 * @file postprocess/registry.h
 * The postprocessors a parameter file selects by name (Output/Postprocessors)
 * beside those every explicit run has (statistics, probes, contact patch,
 * patch series, VTU output, energy balance, divergence check, verification
 * samples).
 *
 * A selectable postprocessor is one file: a class derived from
 * Postprocessor and a PostprocessorPlugin naming it, declaring and parsing
 * its parameters (in subsection Output/NAME) and making it for the run.
 * The library's are listed in source/postprocess/registry.cc, one line
 * each; one compiled into another executable registers itself with
 * WHEELRAIL_REGISTER_POSTPROCESSOR (doc/developer.md).
 */
#ifndef wheelrail_postprocess_registry_h
#define wheelrail_postprocess_registry_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace WheelRail
{
  class Postprocessor;
  struct SimulatorAccess;

  /** Makes a selected postprocessor for the run, with the parameters
   *  parsed into it. */
  using PostprocessorFactory = std::function<std::unique_ptr<Postprocessor>(const SimulatorAccess &)>;

  /** What a selectable postprocessor's file defines for the registry. */
  struct PostprocessorPlugin
  {
    /** The name Output/Postprocessors selects it by. */
    const char *name;
    /** What it writes, for the documentation of Output/Postprocessors. */
    const char *description;
    /** Declare its parameters, in subsection Output/NAME (the handler is
     *  in it); nullptr if it has none. */
    void (*declare_parameters)(dealii::ParameterHandler &prm);
    /** Parse its parameters (the handler in subsection Output/NAME) into
     *  the factory that makes it. */
    PostprocessorFactory (*parse_parameters)(const dealii::ParameterHandler &prm);
  };

  namespace Postprocessors
  {
    /** Declare Output/Postprocessors and every registered postprocessor's
     *  subsection; the handler is in subsection Output. */
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /** The selected postprocessors in the order of Output/Postprocessors,
     *  each with its name; the handler is in subsection Output. */
    std::vector<std::pair<std::string, PostprocessorFactory>>
    parse_parameters(dealii::ParameterHandler &prm);

    /** Add @p plugin to the registry; a second one of the same name is an
     *  error. Returns true (for a static initialiser). */
    bool
    register_plugin(const PostprocessorPlugin &plugin);
  } // namespace Postprocessors
} // namespace WheelRail

/**
 * Register the PostprocessorPlugin @p plugin of a postprocessor compiled
 * outside the library (a test's or a user's executable) when the program
 * starts.
 */
#define WHEELRAIL_REGISTER_POSTPROCESSOR(plugin)                              \
  namespace                                                                   \
  {                                                                           \
    [[maybe_unused]] const bool wheelrail_postprocessor_registered_##plugin = \
      ::WheelRail::Postprocessors::register_plugin(plugin);                   \
  }

#endif
