/**
 * @file contact/friction_law.h
 * Friction laws f(s_n) of the local coefficient of friction as a function of
 * the micro-slip velocity s_n (SPEC 4), and the return map onto the friction
 * cone. Each law is one file in source/contact/friction_laws/; a new law is
 * such a file plus its line in the registry (source/contact/friction_law.cc).
 */
#ifndef wheelrail_contact_friction_law_h
#define wheelrail_contact_friction_law_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

namespace WheelRail
{
  /**
   * Interface of a friction law, and the registry of the laws by name.
   *
   * A law is one file that defines a class derived from FrictionLaw and a
   * FrictionLaw::Plugin: its name for Contact/Friction law, a line for the
   * parameter's documentation, a function that declares the entries only
   * it reads (in subsection Contact) and one that makes the law from the
   * parsed parameters. The laws of the library are listed in
   * source/contact/friction_law.cc (one line each); a law compiled into
   * another executable registers itself with
   * WHEELRAIL_REGISTER_FRICTION_LAW (doc/developer.md).
   */
  class FrictionLaw
  {
  public:
    /** What a law's file defines for the registry. */
    struct Plugin
    {
      /** The name Contact/Friction law selects it by. */
      const char *name;
      /** What it computes, for the documentation of Contact/Friction law. */
      const char *description;
      /** Declare the entries only this law reads, in subsection Contact
       *  (the handler is in it); nullptr if it has none. */
      void (*declare_parameters)(dealii::ParameterHandler &prm);
      /** The law from the parsed parameters, the handler in subsection
       *  Contact. */
      std::unique_ptr<FrictionLaw> (*create)(const dealii::ParameterHandler &prm);
    };

    virtual ~FrictionLaw() = default;

    /** Local coefficient of friction at micro-slip velocity @p s [m/s]. */
    virtual double
    coefficient(const double s) const = 0;

    /** Name as selected in the parameter file. */
    virtual std::string
    name() const = 0;

    /** The coefficient that fully developed sliding (s -> infinity) tends
     *  to: the traction limit of a saturated wheel (SPEC 8). */
    virtual double
    sliding_coefficient() const = 0;

    /** The law's coefficients as the run's summary prints them, each
     *  number written by @p format, e.g. "f = 0.5". */
    virtual std::string
    describe(const std::function<std::string(double)> &format) const = 0;

    /**
     * Declare Contact/Friction law (a selection of "none" and the
     * registered names), the coefficients several laws read (Static and
     * Dynamic friction coefficient, Decay coefficient) and every
     * registered law's own entries. The handler is in subsection Contact.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** The law selected by Contact/Friction law, nullptr for "none"; the
     *  handler is in subsection Contact. */
    static std::unique_ptr<FrictionLaw>
    create(const dealii::ParameterHandler &prm);

    /**
     * The law registered as @p name with the shared coefficients f_S, f_D
     * and k and every other entry at its default (unit tests, the 1D
     * slider).
     */
    static std::unique_ptr<FrictionLaw>
    create(const std::string &name,
           const double       static_coefficient,
           const double       dynamic_coefficient,
           const double       decay);

    /** Names of the registered laws, sorted, as a Patterns::Selection
     *  string ("constant|exponential"). */
    static std::string
    names();

    /** Add @p plugin to the registry; a second law of the same name is an
     *  error. Returns true (for a static initialiser). */
    static bool
    register_law(const Plugin &plugin);
  };



/**
 * Register the FrictionLaw::Plugin @p plugin of a law compiled outside the
 * library (a test's or a user's executable) when the program starts.
 */
#define WHEELRAIL_REGISTER_FRICTION_LAW(plugin)                              \
  namespace                                                                 \
  {                                                                         \
    [[maybe_unused]] const bool wheelrail_friction_law_registered_##plugin = \
      ::WheelRail::FrictionLaw::register_law(plugin);                       \
  }



  /**
   * Return to the friction cone (LS-DYNA): the trial force @p trial is kept
   * if |trial| <= @p limit (stick), else scaled back onto the cone (slip).
   * Returns the force; @p slipping tells which case held, and @p dissipated
   * the energy f|F_n| (|trial| - limit)/k_t lost in the slip when
   * @p tangential_stiffness k_t is given.
   */
  inline dealii::Tensor<1, 3>
  return_map(const dealii::Tensor<1, 3> &trial,
             const double                limit,
             const double                tangential_stiffness,
             bool                       &slipping,
             double                     &dissipated)
  {
    const double norm = trial.norm();
    if (norm <= limit)
      {
        slipping   = false;
        dissipated = 0;
        return trial;
      }
    slipping   = true;
    dissipated = limit * (norm - limit) / tangential_stiffness;
    return (limit / norm) * trial;
  }
} // namespace WheelRail

#endif
