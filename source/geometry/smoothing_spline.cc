/**
 * @file geometry/smoothing_spline.cc
 * The smoothing spline: the pentadiagonal system of Green and Silverman
 * (Nonparametric Regression and Generalized Linear Models, 1994, sec. 2.3)
 * solved by Eigen's sparse LDL^T, and the bisection for a given RMS deviation.
 */
#include <wheelrail/geometry/smoothing_spline.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Sparse>

namespace WheelRail
{
  namespace Geometry
  {
    namespace
    {
      using SparseMatrix = Eigen::SparseMatrix<double>;

      /** Q (n x n-2) and R (n-2 x n-2) of the knots x (Green and Silverman 2.1.2). */
      void
      assemble_q_r(const std::vector<double> &x, SparseMatrix &Q, SparseMatrix &R)
      {
        const int                           n = static_cast<int>(x.size());
        std::vector<Eigen::Triplet<double>> q, r;
        for (int j = 1; j + 1 < n; ++j)
          {
            const double h0 = x[j] - x[j - 1], h1 = x[j + 1] - x[j];
            q.emplace_back(j - 1, j - 1, 1. / h0);
            q.emplace_back(j, j - 1, -1. / h0 - 1. / h1);
            q.emplace_back(j + 1, j - 1, 1. / h1);
            r.emplace_back(j - 1, j - 1, (h0 + h1) / 3.);
            if (j + 2 < n)
              {
                r.emplace_back(j - 1, j, h1 / 6.);
                r.emplace_back(j, j - 1, h1 / 6.);
              }
          }
        Q.resize(n, n - 2);
        Q.setFromTriplets(q.begin(), q.end());
        R.resize(n - 2, n - 2);
        R.setFromTriplets(r.begin(), r.end());
      }
    } // namespace



    SplineFit
    fit_smoothing_spline(const std::vector<double> &x,
                         const std::vector<double> &z,
                         const double               alpha)
    {
      const std::size_t n = x.size();
      if (n < 3 || z.size() != n || !(alpha >= 0))
        throw std::invalid_argument("fit_smoothing_spline: needs >= 3 knots, as many values, "
                                    "alpha >= 0");
      SparseMatrix Q, R;
      assemble_q_r(x, Q, R);
      const Eigen::Map<const Eigen::VectorXd> zv(z.data(), static_cast<Eigen::Index>(n));
      const SparseMatrix                      A = R + alpha * SparseMatrix(Q.transpose() * Q);
      Eigen::SimplicialLDLT<SparseMatrix>     solver(A);
      if (solver.info() != Eigen::Success)
        throw std::runtime_error("fit_smoothing_spline: the spline system is singular");
      const Eigen::VectorXd gamma = solver.solve(Q.transpose() * zv);
      Eigen::VectorXd       s     = zv;
      if (alpha > 0)
        s -= alpha * (Q * gamma);

      SplineFit fit;
      fit.alpha = alpha;
      fit.values.assign(s.data(), s.data() + n);
      fit.second_derivatives.assign(n, 0.);
      std::copy(gamma.data(), gamma.data() + n - 2, fit.second_derivatives.begin() + 1);
      double sum = 0;
      for (std::size_t i = 0; i < n; ++i)
        {
          const double e = z[i] - s[i];
          sum += e * e;
          fit.max_deviation = std::max(fit.max_deviation, std::abs(e));
        }
      fit.rms_deviation = std::sqrt(sum / n);
      return fit;
    }



    SplineFit
    fit_smoothing_spline_to_tolerance(const std::vector<double> &x,
                                      const std::vector<double> &z,
                                      const double               tolerance)
    {
      if (!(tolerance > 0))
        return fit_smoothing_spline(x, z, 0.);
      // alpha [x^3]: from the mean spacing cubed up by factors of 10 to a bracket
      const double h3 = std::pow((x.back() - x.front()) / (x.size() - 1), 3);
      double       lo = 0, hi = h3;
      SplineFit    fit = fit_smoothing_spline(x, z, hi);
      while (fit.rms_deviation < tolerance)
        {
          if (hi > 1e30 * h3)
            return fit; // the least-squares line is within the tolerance
          lo  = hi;
          hi  = 10 * hi;
          fit = fit_smoothing_spline(x, z, hi);
        }
      if (lo == 0)
        lo = hi * 1e-30;
      // bisection on log alpha: the RMS deviation grows with alpha
      for (unsigned int i = 0; i < 200 && std::abs(fit.rms_deviation / tolerance - 1) > 1e-6; ++i)
        {
          const double mid                          = std::sqrt(lo * hi);
          fit                                       = fit_smoothing_spline(x, z, mid);
          (fit.rms_deviation < tolerance ? lo : hi) = mid;
        }
      return fit;
    }
  } // namespace Geometry
} // namespace WheelRail
