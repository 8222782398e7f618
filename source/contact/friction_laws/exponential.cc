/**
 * @file contact/friction_laws/exponential.cc
 * Velocity-dependent friction of Zhao & Li (2016), eq. (1):
 * f = f_D + (f_S - f_D) exp(-k s) (Contact/Friction law = exponential).
 */

#include <wheelrail/contact/friction_law.h>

namespace WheelRail
{
  namespace FrictionLaws
  {
    namespace
    {
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
        double
        sliding_coefficient() const override
        {
          return f_d;
        }
        std::string
        describe(const std::function<std::string(double)> &format) const override
        {
          return "f_S = " + format(f_s) + ", f_D = " + format(f_d) + ", k = " + format(k) + " s/m";
        }

      private:
        const double f_s, f_d, k;
      };
    } // namespace



    extern const FrictionLaw::Plugin exponential;
    const FrictionLaw::Plugin        exponential = {
      "exponential",
      "f = f_D + (f_S - f_D) exp(-k s_n) (paper eq. 1), s_n the micro-slip velocity",
      nullptr,
      [](const dealii::ParameterHandler &prm) -> std::unique_ptr<FrictionLaw> {
        return std::make_unique<ExponentialFriction>(prm.get_double("Static friction coefficient"),
                                                   prm.get_double("Dynamic friction coefficient"),
                                                   prm.get_double("Decay coefficient"));
      }};
  } // namespace FrictionLaws
} // namespace WheelRail
