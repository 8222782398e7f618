/**
 * @file verification/slider.cc
 * The 1D slider: characteristic roots of its linearised motion and the
 * explicit run with the FE contact's friction step.
 */

#include <deal.II/lac/lapack_full_matrix.h>

#include <wheelrail/verification/slider.h>

#include <algorithm>
#include <cmath>

namespace WheelRail
{
  namespace Slider
  {
    namespace
    {
      /** Roots of c[0] l^n + ... + c[n] (c[0] != 0), largest real part
       *  first: the eigenvalues of the companion matrix. */
      std::vector<std::complex<double>>
      polynomial_roots(const std::vector<double> &c)
      {
        const unsigned int               n = c.size() - 1;
        dealii::LAPACKFullMatrix<double> companion(n, n);
        for (unsigned int j = 0; j < n; ++j)
          companion(0, j) = -c[j + 1] / c[0];
        for (unsigned int i = 1; i < n; ++i)
          companion(i, i - 1) = 1;
        companion.compute_eigenvalues();
        std::vector<std::complex<double>> roots;
        for (unsigned int i = 0; i < n; ++i)
          roots.push_back(companion.eigenvalue(i));
        std::sort(roots.begin(), roots.end(), [](const auto &a, const auto &b) {
          return a.real() > b.real() || (a.real() == b.real() && a.imag() > b.imag());
        });
        return roots;
      }



      /** f'(s) by central differences (fourth order). */
      double
      slope(const FrictionLaw &law, const double s)
      {
        const double h = 1e-4 * std::max(s, 1e-3);
        return (law.coefficient(s - 2 * h) - 8 * law.coefficient(s - h) +
                8 * law.coefficient(s + h) - law.coefficient(s + 2 * h)) /
               (12 * h);
      }
    } // namespace



    std::vector<std::complex<double>>
    characteristic_roots(const FrictionModel &model, const Parameters &p)
    {
      const auto  &o = model.options();
      const double m = p.mass, K = p.stiffness, C = p.damping;
      if (p.speed == 0)
        {
          const double c_t = 2. * o.damping_ratio * std::sqrt(p.tangential_stiffness * m);
          return polynomial_roots({m, C + c_t, K + p.tangential_stiffness});
        }
      const double D = -p.normal_force * slope(model.law(), p.speed);
      if (o.relaxes())
        {
          const double r = (o.relaxation_length > 0 ? p.speed / o.relaxation_length : 0.) +
                           (o.relaxation_time > 0 ? 1. / o.relaxation_time : 0.);
          return polynomial_roots({m, C + m * r, K + C * r - D * r, K * r});
        }
      if (o.irreversible_slip_rate)
        {
          const double b = D / p.tangential_stiffness;
          return polynomial_roots({-b * m, m - b * C, C - b * K - D, K});
        }
      return polynomial_roots({m, C - D, K});
    }



    Run
    run(const FrictionModel &model,
        const Parameters    &p,
        const double         perturbation,
        const double         end_time,
        const double         window,
        const double         velocity_limit)
    {
      Run                   result;
      FrictionModel::Memory memory = model.new_contact();
      if (p.speed > 0)
        {
          const double f_v        = model.law().coefficient(p.speed);
          result.x_steady         = f_v * p.normal_force / p.stiffness;
          memory.elastic_force[0] = f_v * p.normal_force;
          memory.state            = f_v;
        }
      else
        // at rest the contact sticks: the perturbation stretches the
        // tangential spring
        memory.elastic_force[0] = -p.tangential_stiffness * perturbation;
      const dealii::Tensor<1, 3> normal({0., 0., 1.});
      const double               dt = p.time_step;
      double                     x = result.x_steady + perturbation, v = 0;

      // maxima of |v| (0 in the steady state) over consecutive windows
      std::vector<std::pair<double, double>> maxima;
      double                                 window_max = 0;
      const unsigned long steps_per_window              = std::max(1l, std::lround(window / dt));
      unsigned long       n                             = 0;
      for (; n * dt < end_time; ++n)
        {
          dealii::Tensor<1, 3> de;
          de[0] = (v - p.speed) * dt;
          const FrictionModel::Result r =
            model.step(de, normal, p.normal_force, p.tangential_stiffness, p.mass, dt, memory);
          result.largest_slip = std::max(result.largest_slip, r.slip);
          result.stuck |= !r.slipping;
          const double a = (r.force[0] - p.stiffness * x - p.damping * v) / p.mass;
          v += dt * a;
          x += dt * v;

          const double amplitude = std::abs(v);
          window_max             = std::max(window_max, amplitude);
          if ((n + 1) % steps_per_window == 0)
            {
              maxima.emplace_back((n + 1 - 0.5 * steps_per_window) * dt, window_max);
              window_max = 0;
            }
          if (amplitude > velocity_limit)
            break;
        }
      result.end_time = n * dt;

      // least-squares slope of log(maximum) over the later 60 % of the
      // windows (the first 40 % hold the other modes' transient)
      const unsigned int first = maxima.size() * 2 / 5;
      double             st = 0, sl = 0, stt = 0, stl = 0, count = 0;
      for (unsigned int i = first; i < maxima.size(); ++i)
        if (maxima[i].second > 0)
          {
            const double t = maxima[i].first, l = std::log(maxima[i].second);
            st += t;
            sl += l;
            stt += t * t;
            stl += t * l;
            ++count;
          }
      result.rate = count >= 3 ? (count * stl - st * sl) / (count * stt - st * st) : 0.;
      return result;
    }
  } // namespace Slider
} // namespace WheelRail
