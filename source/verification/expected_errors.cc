/**
 * @file verification/expected_errors.cc
 * The convergence study's errors per mesh size and the limits derived from
 * them.
 */

#include <deal.II/base/exceptions.h>

#include <wheelrail/simulator/format.h>
#include <wheelrail/verification/expected_errors.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace WheelRail
{
  namespace Verification
  {
    using Report::fmt;



    const std::vector<ExpectedError> &
    expected_errors()
    {
      // doc/notes/convergence.md, "Convergence at F_x / F_N = 0.3": Coulomb f = 0.5,
      // creepage held at -2.93e-3, paper step, half-space on 96 x 65
      // elements; runs of 2026-11-25 (h 1.32, 0.66, 0.33 mm)
      static const std::vector<ExpectedError> table = {
        {"p0",
         "peak pressure p0 of the fitted ellipse against Hertz, relative",
         0.02,
         {{0.0362, 0.0202, 0.0109}}},
        {"a",
         "semi-axis a (rolling direction) against Hertz, relative",
         0.02,
         {{0.0016, 0.0012, 0.0005}}},
        {"b", "semi-axis b (lateral) against Hertz, relative", 0.02, {{0.0000, 0.0050, 0.0048}}},
        {"creep",
         "rigid creepage against the half-space creepage at the same F_x, relative",
         0.05,
         {{0.0096, 0.0131, 0.0135}}},
        {"slip",
         "slip-area fraction (eq. 5) minus the half-space's",
         0.03,
         {{0.041, 0.005, 0.005}}},
        {"rms_p",
         "RMS difference of the pressure along y = 0, of p0",
         0.05,
         {{0.027, 0.018, 0.013}}},
        {"rms_q",
         "RMS difference of the shear q_x along y = 0, of f p0",
         0.05,
         {{0.022, 0.016, 0.012}}}};
      return table;
    }



    const ExpectedError &
    expected_error(const std::string &key)
    {
      for (const ExpectedError &e : expected_errors())
        if (e.key == key)
          return e;
      AssertThrow(false, dealii::ExcMessage("No expected error for the quantity '" + key + "'."));
      return expected_errors().front();
    }



    Expectation
    expectation(const ExpectedError &quantity, const double h)
    {
      const auto &m = quantity.measured;
      Expectation e;
      e.paper_mesh = m[2];
      e.in_study   = h <= 2 * study_h[0];
      if (h <= study_h[2])
        e.expected = m[2];
      else if (h <= study_h[1])
        e.expected = m[2] + (m[1] - m[2]) * (h - study_h[2]) / (study_h[1] - study_h[2]);
      else
        // between 0.66 and 1.32 mm, and linearly extrapolated beyond
        e.expected = m[1] + (m[0] - m[1]) * (h - study_h[1]) / (study_h[0] - study_h[1]);
      e.expected = std::max(e.expected, 0.);
      e.limit    = e.in_study ? std::max(quantity.target, expected_error_margin * e.expected) :
                                quantity.target;
      return e;
    }



    std::string
    expected_errors_csv(const double h)
    {
      std::ostringstream csv;
      csv << "# The errors of the patch at t that the convergence study (doc/convergence.md) "
             "measured, at this run's smallest cell size h; limit = max(target, "
          << fmt(expected_error_margin, 3) << " x expected)\n"
          << "key,h_m,expected,limit,in_study,paper_mesh,target,what\n";
      csv.precision(4);
      for (const ExpectedError &q : expected_errors())
        {
          const Expectation e = expectation(q, h);
          csv << q.key << ',' << h << ',' << e.expected << ',' << e.limit << ',' << e.in_study
              << ',' << e.paper_mesh << ',' << q.target << ',' << q.what << '\n';
        }
      return csv.str();
    }



    std::string
    expectation_verdict(const std::string &key, const double error, const double h)
    {
      const Expectation  e  = expectation(expected_error(key), h);
      const bool         ok = std::abs(error) <= e.limit;
      std::ostringstream out;
      out << std::fixed;
      out.precision(3);
      if (!e.in_study)
        out << (ok ? "within" : "OUTSIDE") << " the target " << e.limit
            << " (h = " << fmt(h * 1e3, 3) << " mm is coarser than the convergence study's meshes)";
      else
        out << (ok ? "as expected" : "OUTSIDE the expectation") << " for h = " << fmt(h * 1e3, 3)
            << " mm (limit " << e.limit << "; paper mesh " << e.paper_mesh << ")";
      return out.str();
    }
  } // namespace Verification
} // namespace WheelRail
