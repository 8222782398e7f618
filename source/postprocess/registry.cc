/**
 * @file postprocess/registry.cc
 * The registry of the selectable postprocessors and Output/Postprocessors.
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/postprocess/registry.h>

#include <algorithm>
#include <map>

namespace WheelRail
{
  namespace Postprocessors
  {
    namespace
    {
      /** The registry, by name: the library's selectable postprocessors
       *  (one line each in the list below; none yet), then what
       *  register_plugin() adds. */
      std::map<std::string, PostprocessorPlugin> &
      registry()
      {
        static std::map<std::string, PostprocessorPlugin> plugins = [] {
          std::map<std::string, PostprocessorPlugin> library;
          for (const PostprocessorPlugin *plugin : std::initializer_list<const PostprocessorPlugin *>{})
            library.emplace(plugin->name, *plugin);
          return library;
        }();
        return plugins;
      }

      std::string
      known_names()
      {
        std::string names;
        for (const auto &entry : registry())
          names += (names.empty() ? "'" : ", '") + entry.first + "'";
        return names.empty() ? "none is registered" : names;
      }
    } // namespace



    bool
    register_plugin(const PostprocessorPlugin &plugin)
    {
      AssertThrow(registry().emplace(plugin.name, plugin).second,
                  dealii::ExcMessage("A second postprocessor named '" + std::string(plugin.name) +
                                     "' was registered."));
      return true;
    }



    void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      // nothing to select without a registered postprocessor: no entry,
      // and the record of a run's parameters stays as it was
      if (registry().empty())
        return;
      std::string documentation =
        "Postprocessors to run beside those of every run, by name, separated by commas; empty: "
        "none. Each adds its columns to the statistics and keeps its state in the checkpoint.";
      for (const auto &[name, plugin] : registry())
        documentation += " '" + name + "': " + plugin.description + ".";
      prm.declare_entry("Postprocessors", "", dealii::Patterns::Anything(), documentation);
      for (const auto &[name, plugin] : registry())
        if (plugin.declare_parameters)
          {
            prm.enter_subsection(name);
            plugin.declare_parameters(prm);
            prm.leave_subsection();
          }
    }



    std::vector<std::pair<std::string, PostprocessorFactory>>
    parse_parameters(dealii::ParameterHandler &prm)
    {
      std::vector<std::pair<std::string, PostprocessorFactory>> selected;
      if (registry().empty())
        return selected;
      for (const std::string &name :
           dealii::Utilities::split_string_list(prm.get("Postprocessors"), ','))
        {
          const auto plugin = registry().find(name);
          AssertThrow(plugin != registry().end(),
                      dealii::ExcMessage("Output/Postprocessors: unknown postprocessor '" + name +
                                         "' (known: " + known_names() + ")."));
          AssertThrow(std::none_of(selected.begin(),
                                   selected.end(),
                                   [&](const auto &s) { return s.first == name; }),
                      dealii::ExcMessage("Output/Postprocessors: '" + name +
                                         "' is selected twice."));
          prm.enter_subsection(name);
          selected.emplace_back(name, plugin->second.parse_parameters(prm));
          prm.leave_subsection();
        }
      return selected;
    }
  } // namespace Postprocessors
} // namespace WheelRail
