/**
 * @file contact/friction_laws/constant.cc
 * Coulomb friction with a constant coefficient, f = f_S
 * (Contact/Friction law = constant).
 */

#include <wheelrail/contact/friction_law.h>

namespace WheelRail
{
  namespace FrictionLaws
  {
    namespace
    {
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
        double
        sliding_coefficient() const override
        {
          return f;
        }
        std::string
        describe(const std::function<std::string(double)> &format) const override
        {
          return "f = " + format(f);
        }

      private:
        const double f;
      };
    } // namespace



    extern const FrictionLaw::Plugin constant;
    const FrictionLaw::Plugin        constant = {
      "constant",
      "Coulomb, f = Static friction coefficient",
      nullptr,
      [](const dealii::ParameterHandler &prm) -> std::unique_ptr<FrictionLaw> {
        return std::make_unique<ConstantFriction>(prm.get_double("Static friction coefficient"));
      }};
  } // namespace FrictionLaws
} // namespace WheelRail
