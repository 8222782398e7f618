/**
 * @file verification/hertz.h
 * Hertz's solution for two elastic bodies with an elliptic contact (exact
 * complete elliptic integrals), used as the independent reference of the
 * static contact test (SPEC 8).
 */
#ifndef wheelrail_verification_hertz_h
#define wheelrail_verification_hertz_h

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include <cmath>
#include <stdexcept>

namespace WheelRail
{
  /** Semi-axes, pressures and approach of a Hertzian contact. */
  struct HertzSolution
  {
    double a;             ///< semi-axis in the direction of the curvature A [m]
    double b;             ///< semi-axis in the direction of B [m]
    double p0;            ///< peak pressure [Pa]
    double mean_pressure; ///< F / (pi a b) [Pa]
    double approach;      ///< mutual approach of distant points [m]
  };

  /**
   * Hertz contact for the gap h = A x^2 + B y^2 (A <= B, relative curvatures
   * 1/(2R)), normal force @p F and contact modulus E* = E / (2 (1 - nu^2))
   * for two equal materials. With e^2 = 1 - b^2/a^2 and K, E the complete
   * elliptic integrals of modulus e (Johnson, Contact Mechanics, 4.2):
   *   B/A = ((a/b)^2 E - K) / (K - E),
   *   A   = 3 F (K - E) / (2 pi E* e^2 a^3),
   *   p0  = 3 F / (2 pi a b),  approach = p0 b K / E*.
   */
  inline HertzSolution
  hertz_contact(const double A, const double B, const double F, const double E_star)
  {
    if (!(A > 0 && B >= A && F > 0 && E_star > 0))
      throw std::invalid_argument("hertz_contact: needs 0 < A <= B, F > 0, E* > 0");
    using boost::math::ellint_1;
    using boost::math::ellint_2;
    const auto ratio = [](const double e) {
      const double K = ellint_1(e), E = ellint_2(e), k2 = 1 - e * e;
      return (E / k2 - K) / (K - E);
    };
    // B/A grows monotonically from 1 (e -> 0) to infinity (e -> 1): bisect
    double       lo = 1e-8, hi = 1 - 1e-15;
    const double target = B / A;
    if (target - 1 < 1e-12)
      lo = hi = 1e-8;
    for (unsigned int it = 0; it < 200 && hi - lo > 1e-15; ++it)
      {
        const double mid                = 0.5 * (lo + hi);
        (ratio(mid) < target ? lo : hi) = mid;
      }
    const double  e = 0.5 * (lo + hi);
    const double  K = ellint_1(e), E = ellint_2(e);
    HertzSolution s;
    // for e -> 0, (K - E)/e^2 -> pi/4
    const double KE_e2 = e > 1e-6 ? (K - E) / (e * e) : M_PI / 4;
    s.a                = std::cbrt(3 * F * KE_e2 / (2 * M_PI * E_star * A));
    s.b                = s.a * std::sqrt(1 - e * e);
    s.p0               = 3 * F / (2 * M_PI * s.a * s.b);
    s.mean_pressure    = F / (M_PI * s.a * s.b);
    s.approach         = s.p0 * s.b * K / E_star;
    return s;
  }
} // namespace WheelRail

#endif
