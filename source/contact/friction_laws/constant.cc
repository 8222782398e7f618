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



    std::unique_ptr<FrictionLaw>
    constant(const FrictionLaw::Coefficients &c)
    {
      return std::make_unique<ConstantFriction>(c.static_coefficient);
    }
  } // namespace FrictionLaws
} // namespace WheelRail
