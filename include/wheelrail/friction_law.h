/**
 * @file friction_law.h
 * Friction laws f(s_n) of the local coefficient of friction as a function of
 * the micro-slip velocity s_n (SPEC 4). A new law is one class here plus a
 * name in create().
 */
#ifndef wheelrail_friction_law_h
#define wheelrail_friction_law_h

#include <deal.II/base/tensor.h>

#include <cmath>
#include <memory>
#include <string>

namespace WheelRail
{
  /** Interface of a friction law. */
  class FrictionLaw
  {
  public:
    virtual ~FrictionLaw() = default;

    /** Local coefficient of friction at micro-slip velocity @p s [m/s]. */
    virtual double
    coefficient(const double s) const = 0;

    /** Name as selected in the parameter file. */
    virtual std::string
    name() const = 0;

    /**
     * The law called @p name: "constant" (Coulomb, f = f_S) or
     * "exponential" (paper eq. 1, f = f_D + (f_S - f_D) exp(-k s)).
     */
    static std::unique_ptr<FrictionLaw>
    create(const std::string &name,
           const double       static_coefficient,
           const double       dynamic_coefficient,
           const double       decay);

    /** Names accepted by create(), as a Patterns::Selection string. */
    static std::string
    names()
    {
      return "constant|exponential";
    }
  };



  /** Coulomb friction with a constant coefficient. */
  class ConstantFriction : public FrictionLaw
  {
  public:
    explicit ConstantFriction(const double f)
      : f(f)
    {}
    double
    coefficient(const double) const override
    {
      return f;
    }
    std::string
    name() const override
    {
      return "constant";
    }

  private:
    const double f;
  };



  /** Velocity-dependent friction of Zhao & Li (2016), eq. (1). */
  class ExponentialFriction : public FrictionLaw
  {
  public:
    ExponentialFriction(const double f_static, const double f_dynamic, const double decay)
      : f_s(f_static)
      , f_d(f_dynamic)
      , k(decay)
    {}
    double
    coefficient(const double s) const override
    {
      return f_d + (f_s - f_d) * std::exp(-k * s);
    }
    std::string
    name() const override
    {
      return "exponential";
    }

  private:
    const double f_s, f_d, k;
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
