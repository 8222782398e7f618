/**
 * @file contact/friction_law.cc
 * The registry of the friction laws: their names, in the order in which
 * Contact/Friction law offers them, and the factories that make them.
 */

#include <deal.II/base/exceptions.h>

#include <wheelrail/contact/friction_law.h>

#include <utility>

namespace WheelRail
{
  namespace FrictionLaws
  {
    // each defined in source/contact/friction_laws/NAME.cc
    FrictionLaw::Factory constant;
    FrictionLaw::Factory exponential;
  } // namespace FrictionLaws



  namespace
  {
    /** The registry: one line per law, in the order of the parameter's
     *  Selection and of the --help text. */
    const std::pair<const char *, FrictionLaw::Factory *> registry[] = {
      {"constant", &FrictionLaws::constant},
      {"exponential", &FrictionLaws::exponential},
    };
  } // namespace



  std::unique_ptr<FrictionLaw>
  FrictionLaw::create(const std::string &name,
                      const double       static_coefficient,
                      const double       dynamic_coefficient,
                      const double       decay)
  {
    for (const auto &[law_name, factory] : registry)
      if (name == law_name)
        return factory({static_coefficient, dynamic_coefficient, decay});
    AssertThrow(false,
                dealii::ExcMessage("Unknown friction law '" + name + "' (known: " + names() +
                                   ")."));
    return nullptr;
  }



  std::string
  FrictionLaw::names()
  {
    std::string selection;
    for (const auto &entry : registry)
      selection += (selection.empty() ? "" : "|") + std::string(entry.first);
    return selection;
  }
} // namespace WheelRail
