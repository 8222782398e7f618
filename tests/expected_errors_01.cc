// Unit test of the limits that a rolling patch at t is judged by
// (verification/expected_errors.h): at the convergence study's own mesh
// sizes the expectation is the measured error of doc/notes/convergence.md, the
// limit max(target, 4/3 x expected); between them linear in h; below the
// paper's h the paper mesh's; beyond 2 x 1.32 mm only the target. An error
// just inside a limit reads "as expected", just outside "OUTSIDE": a wrong
// coarse run is not passed by its mesh's allowance.
#include <wheelrail/verification/expected_errors.h>

#include <cmath>
#include <cstdio>

using namespace WheelRail::Verification;

int
main()
{
  for (const ExpectedError &q : expected_errors())
    {
      std::printf("%s (target %.3f): %s\n", q.key.c_str(), q.target, q.what.c_str());
      for (const double h :
           {0.2e-3, 0.33e-3, 0.5e-3, 0.66e-3, 1.0e-3, 1.32e-3, 1.5e-3, 2.64e-3, 3e-3})
        {
          const Expectation e = expectation(q, h);
          std::printf("  h %.2f mm: expected %.4f, limit %.4f, in study %d\n",
                      h * 1e3,
                      e.expected,
                      e.limit,
                      int(e.in_study));
        }
    }

  // the study's points are reproduced exactly, and the limits of 1.32 mm
  unsigned int failures = 0;
  for (const ExpectedError &q : expected_errors())
    for (unsigned int i = 0; i < study_h.size(); ++i)
      {
        const Expectation e = expectation(q, study_h[i]);
        failures += std::abs(e.expected - q.measured[i]) > 1e-12;
        failures += std::abs(e.limit - std::max(q.target, 4. / 3. * q.measured[i])) > 1e-12;
      }
  std::printf("study points reproduced: %s\n", failures == 0 ? "yes" : "no");

  // the verdicts on either side of the p0 limit at 1.32 mm (0.0483) and 1.5 mm
  for (const double h : {1.32e-3, 1.5e-3, 3e-3})
    {
      const double limit = expectation(expected_error("p0"), h).limit;
      std::printf("p0 at h %.2f mm, error %.4f: %s\n",
                  h * 1e3,
                  0.99 * limit,
                  expectation_verdict("p0", 0.99 * limit, h).c_str());
      std::printf("p0 at h %.2f mm, error %.4f: %s\n",
                  h * 1e3,
                  1.01 * limit,
                  expectation_verdict("p0", 1.01 * limit, h).c_str());
    }
  // the default case's soft-interface p0 error of the paper's settings (-33 %)
  std::printf("p0 at h 1.50 mm, error 0.33: %s\n", expectation_verdict("p0", 0.33, 1.5e-3).c_str());
  std::printf("slip at h 1.32 mm, error -0.214: %s\n",
              expectation_verdict("slip", -0.214, 1.32e-3).c_str());
  return failures == 0 ? 0 : 1;
}
