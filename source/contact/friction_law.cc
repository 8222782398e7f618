/**
 * @file contact/friction_law.cc
 * The registry of the friction laws: the laws of the library (one line
 * each), those registered by other executables, and the parameters that
 * select and parametrise them.
 */

#include <deal.II/base/exceptions.h>

#include <wheelrail/contact/friction_law.h>
#include <wheelrail/parameters/entry_flags.h>

#include <iomanip>
#include <map>
#include <sstream>

namespace WheelRail
{
  namespace FrictionLaws
  {
    // each defined in source/contact/friction_laws/NAME.cc
    extern const FrictionLaw::Plugin constant;
    extern const FrictionLaw::Plugin exponential;
  } // namespace FrictionLaws



  namespace
  {
    /** The registry, by name: the library's laws, then what
     *  FrictionLaw::register_law() adds. */
    std::map<std::string, FrictionLaw::Plugin> &
    registry()
    {
      static std::map<std::string, FrictionLaw::Plugin> laws = [] {
        std::map<std::string, FrictionLaw::Plugin> library;
        for (const FrictionLaw::Plugin *plugin : {&FrictionLaws::constant, //
                                                  &FrictionLaws::exponential})
          library.emplace(plugin->name, *plugin);
        return library;
      }();
      return laws;
    }
  } // namespace



  bool
  FrictionLaw::register_law(const Plugin &plugin)
  {
    AssertThrow(plugin.name != std::string("none"),
                dealii::ExcMessage("A friction law cannot be named 'none': Contact/Friction law = "
                                   "none is no friction."));
    AssertThrow(registry().emplace(plugin.name, plugin).second,
                dealii::ExcMessage("A second friction law named '" + std::string(plugin.name) +
                                   "' was registered."));
    return true;
  }



  void
  FrictionLaw::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    std::string documentation = "'none': frictionless";
    for (const auto &[name, plugin] : registry())
      documentation += "; '" + name + "': " + plugin.description;
    prm.declare_entry("Friction law",
                      "exponential",
                      dealii::Patterns::Selection("none|" + names()),
                      documentation + ".");
    prm.declare_entry("Static friction coefficient",
                      "0.5",
                      Double(0, 10),
                      "f_S [-], range [0, 10].");
    prm.declare_entry("Dynamic friction coefficient",
                      "0.32",
                      Double(0, 10),
                      "f_D [-], range [0, 10].");
    prm.declare_entry("Decay coefficient",
                      "6",
                      Double(0, 1e6),
                      "k of the exponential law [s/m], range [0, 1e6].");
    // the static start evaluates the contact without friction
    const EntryFlags flags("Contact");
    for (const char *entry : {"Friction law",
                              "Static friction coefficient",
                              "Dynamic friction coefficient",
                              "Decay coefficient"})
      flags.mark(entry, EntryFlag::static_start_free);
    for (const auto &entry : registry())
      if (entry.second.declare_parameters)
        entry.second.declare_parameters(prm);
  }



  std::unique_ptr<FrictionLaw>
  FrictionLaw::create(const dealii::ParameterHandler &prm)
  {
    const std::string name = prm.get("Friction law");
    if (name == "none")
      return nullptr;
    const auto plugin = registry().find(name);
    AssertThrow(plugin != registry().end(),
                dealii::ExcMessage("Unknown friction law '" + name + "' (known: " + names() +
                                   ")."));
    return plugin->second.create(prm);
  }



  std::unique_ptr<FrictionLaw>
  FrictionLaw::create(const std::string &name,
                      const double       static_coefficient,
                      const double       dynamic_coefficient,
                      const double       decay)
  {
    dealii::ParameterHandler prm;
    declare_parameters(prm);
    const auto exact = [](const double x) {
      std::ostringstream text;
      text << std::setprecision(17) << x;
      return text.str();
    };
    prm.set("Friction law", name);
    prm.set("Static friction coefficient", exact(static_coefficient));
    prm.set("Dynamic friction coefficient", exact(dynamic_coefficient));
    prm.set("Decay coefficient", exact(decay));
    return create(prm);
  }



  std::string
  FrictionLaw::names()
  {
    std::string selection;
    for (const auto &entry : registry())
      selection += (selection.empty() ? "" : "|") + entry.first;
    return selection;
  }
} // namespace WheelRail
