/**
 * @file geometry/smoothing_spline.h
 * The cubic smoothing spline of Reinsch (1967) in the value/second-derivative
 * form of Green and Silverman (1994): natural end conditions, unit weights.
 */
#ifndef wheelrail_geometry_smoothing_spline_h
#define wheelrail_geometry_smoothing_spline_h

#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    /** A natural cubic spline: its values and second derivatives at the knots. */
    struct SplineFit
    {
      /** s(x_i) [units of z]. */
      std::vector<double> values;
      /** s''(x_i) [z/x^2], 0 at both ends. */
      std::vector<double> second_derivatives;
      /** The smoothing parameter alpha [z^2 x^3 / z^2 = x^3]; 0: interpolation. */
      double alpha = 0;
      /** RMS of z_i - s(x_i). */
      double rms_deviation = 0;
      /** Largest |z_i - s(x_i)|. */
      double max_deviation = 0;
    };

    /**
     * The spline minimising sum (z_i - s(x_i))^2 + alpha int s''^2 dx over the
     * knots x (strictly increasing, at least 3): with Q (n x n-2) and R (n-2 x
     * n-2) of Green and Silverman, (R + alpha Q^T Q) gamma = Q^T z and
     * s(x_i) = z - alpha Q gamma. alpha = 0 is the interpolating spline.
     */
    SplineFit
    fit_smoothing_spline(const std::vector<double> &x,
                         const std::vector<double> &z,
                         const double               alpha);

    /**
     * The smoothing spline whose RMS deviation from the points is `tolerance`
     * (relative accuracy 1e-6), alpha found by bisection on log alpha. Where
     * the tolerance is 0 the interpolating spline; where even the least-squares
     * straight line (alpha -> infinity) is within the tolerance, the spline of
     * the largest alpha tried (1e30 times the mean spacing cubed), which is that
     * line to rounding.
     */
    SplineFit
    fit_smoothing_spline_to_tolerance(const std::vector<double> &x,
                                      const std::vector<double> &z,
                                      const double               tolerance);
  } // namespace Geometry
} // namespace WheelRail

#endif
