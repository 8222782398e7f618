/**
 * @file tests/plugins/stribeck_friction.cc
 * The worked example of doc/developer.md, "a friction law with a
 * coefficient of its own": a Stribeck-type law
 *
 *   f(s) = f_D + (f_S - f_D) exp(-(k s)^delta),
 *
 * the exponential law of the paper for delta = 1 (Contact/Friction law =
 * stribeck, Contact/Stribeck exponent = delta). This one file is the whole
 * law: the class, its parameter, and its registration. The library's laws
 * are the same but for the last line, which is a line in the registry
 * (source/contact/friction_law.cc) instead.
 */

#include <wheelrail/contact/friction_law.h>
#include <wheelrail/parameters/entry_flags.h>

#include <cmath>

namespace
{
  using namespace WheelRail;

  class StribeckFriction : public FrictionLaw
  {
  public:
    StribeckFriction(const double f_static,
                     const double f_dynamic,
                     const double decay,
                     const double exponent)
      : f_s(f_static)
      , f_d(f_dynamic)
      , k(decay)
      , delta(exponent)
    {}

    double
    coefficient(const double s) const override
    {
      return f_d + (f_s - f_d) * std::exp(-std::pow(k * s, delta));
    }

    std::string
    name() const override
    {
      return "stribeck";
    }

    double
    sliding_coefficient() const override
    {
      return f_d;
    }

    std::string
    describe(const std::function<std::string(double)> &format) const override
    {
      return "f_S = " + format(f_s) + ", f_D = " + format(f_d) + ", k = " + format(k) +
             " s/m, delta = " + format(delta);
    }

  private:
    const double f_s, f_d, k, delta;
  };



  const FrictionLaw::Plugin stribeck = {
    "stribeck",
    "f = f_D + (f_S - f_D) exp(-(k s_n)^delta), delta = Stribeck exponent",
    // the entry only this law reads (the handler is in subsection Contact)
    [](dealii::ParameterHandler &prm) {
      prm.declare_entry("Stribeck exponent",
                        "1",
                        dealii::Patterns::Double(0.1, 10),
                        "delta of the stribeck law [-], range [0.1, 10]; 1: the exponential "
                        "law.");
      // like every friction entry, the static start does not depend on it
      EntryFlags("Contact").mark("Stribeck exponent", EntryFlag::static_start_free);
    },
    [](const dealii::ParameterHandler &prm) -> std::unique_ptr<FrictionLaw> {
      return std::make_unique<StribeckFriction>(prm.get_double("Static friction coefficient"),
                                                prm.get_double("Dynamic friction coefficient"),
                                                prm.get_double("Decay coefficient"),
                                                prm.get_double("Stribeck exponent"));
    }};
} // namespace

WHEELRAIL_REGISTER_FRICTION_LAW(stribeck)
