// Unit test of the friction laws, the return map and the Hertz reference:
// each value against an independent evaluation of its formula.
#include <wheelrail/contact/friction_law.h>
#include <wheelrail/verification/hertz.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace WheelRail;

int
main()
{
  // exponential law (paper eq. 1) against f_D + (f_S - f_D) exp(-k s)
  const auto law       = FrictionLaw::create("exponential", 0.5, 0.32, 6.);
  double     max_error = 0;
  std::printf("exponential law f_S = 0.5, f_D = 0.32, k = 6 s/m\n");
  for (const double s : {0., 0.01, 0.05, 0.1, 0.29, 0.4, 1., 10.})
    {
      const double f = law->coefficient(s), ref = 0.32 + 0.18 * std::exp(-6. * s);
      max_error = std::max(max_error, std::abs(f - ref));
      std::printf("  s_n = %5.2f m/s: f = %.6f\n", s, f);
    }
  std::printf("  largest |f - formula| = %.1e\n", max_error);
  const auto coulomb = FrictionLaw::create("constant", 0.5, 0.32, 6.);
  std::printf("constant law: f(0) = %.6f, f(1) = %.6f\n",
              coulomb->coefficient(0.),
              coulomb->coefficient(1.));

  // return map: |F_t| <= f |F_n| always, direction kept, stick keeps the trial
  std::mt19937                           random(42);
  std::uniform_real_distribution<double> u(-1., 1.);
  unsigned int violations = 0, direction_errors = 0, sticks = 0, slips = 0;
  for (unsigned int i = 0; i < 100000; ++i)
    {
      const dealii::Tensor<1, 3> trial({u(random), u(random), u(random)});
      const double               limit = 0.8 * std::abs(u(random));
      bool                       slipping;
      double                     lost;
      const auto                 F = return_map(trial, limit, 1e6, slipping, lost);
      violations += F.norm() > limit * (1 + 1e-14);
      direction_errors += (F - (F.norm() / trial.norm()) * trial).norm() > 1e-14;
      (slipping ? slips : sticks) += 1;
      if (!slipping && (F - trial).norm() != 0)
        ++violations;
      if (slipping && std::abs(lost - limit * (trial.norm() - limit) / 1e6) > 1e-18)
        ++violations;
    }
  std::printf("return map, 100000 random trials: %u stick, %u slip, %u violations, %u direction "
              "errors\n",
              sticks,
              slips,
              violations,
              direction_errors);

  // Hertz for the wheel on the rail (SPEC 8)
  const double E_star = 2.1e11 / (2 * (1 - 0.3 * 0.3));
  const auto   h      = hertz_contact(0.5 / 0.46, 0.5 / 0.3, 140.3e3, E_star);
  std::printf("Hertz, F = 140.3 kN, R_w = 0.46 m, R_rail = 0.30 m, E* = %.2f GPa\n", E_star * 1e-9);
  std::printf("  a = %.3f mm (SPEC 8.017), b = %.3f mm (6.031), p0 = %.1f MPa (1385)\n",
              h.a * 1e3,
              h.b * 1e3,
              h.p0 * 1e-6);
  std::printf("  mean pressure = %.1f MPa (924), area = %.1f mm^2 (151.9), approach = %.1f um "
              "(130.5)\n",
              h.mean_pressure * 1e-6,
              M_PI * h.a * h.b * 1e6,
              h.approach * 1e6);
  // circular limit: a^3 = 3 F R / (4 E*) for A = B = 1/(2R)
  const auto   c   = hertz_contact(0.5, 0.5, 1000., E_star);
  const double a_c = std::cbrt(3 * 1000. * 1. / (4 * E_star));
  std::printf("  circular contact R = 1 m, F = 1 kN: a = %.6f mm, formula %.6f mm, b/a = %.6f\n",
              c.a * 1e3,
              a_c * 1e3,
              c.b / c.a);
  return 0;
}
