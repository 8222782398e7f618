/**
 * @file contact/friction_law.h
 * Friction laws f(s_n) of the local coefficient of friction as a function of
 * the micro-slip velocity s_n (SPEC 4), and the return map onto the friction
 * cone. Each law is one file in source/contact/friction_laws/; a new law is
 * such a file plus its line in the registry (source/contact/friction_law.cc).
 */
#ifndef wheelrail_contact_friction_law_h
#define wheelrail_contact_friction_law_h

#include <deal.II/base/tensor.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

namespace WheelRail
{
  /** Interface of a friction law. */
  class FrictionLaw
  {
  public:
    /** The parameters of Contact a law may use. */
    struct Coefficients
    {
      double static_coefficient;  ///< f_S [-]
      double dynamic_coefficient; ///< f_D [-]
      double decay;               ///< k [s/m]
    };

    /** What a law's file defines for the registry: the law for the
     *  coefficients. */
    using Factory = std::unique_ptr<FrictionLaw>(const Coefficients &);

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
     * The law registered as @p name (see source/contact/friction_law.cc),
     * with the coefficients it uses of those given.
     */
    static std::unique_ptr<FrictionLaw>
    create(const std::string &name,
           const double       static_coefficient,
           const double       dynamic_coefficient,
           const double       decay);

    /** Names accepted by create(), in the registry's order, as a
     *  Patterns::Selection string ("constant|exponential"). */
    static std::string
    names();
  };



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
