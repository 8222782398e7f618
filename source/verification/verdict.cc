/**
 * @file verification/verdict.cc
 * The checks' verdicts, counted, and the test-mode rule on them.
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <wheelrail/parameters/parameters.h>
#include <wheelrail/verification/verdict.h>

#include <string>

namespace WheelRail
{
  namespace Verification
  {
    namespace
    {
      unsigned int failed = 0;
    }



    const char *
    verdict(const bool ok)
    {
      failed += !ok;
      return ok ? "yes" : "no";
    }



    unsigned int
    n_failed_verdicts()
    {
      return failed;
    }



    void
    check_verdicts(const Parameters &parameters, const MPI_Comm comm)
    {
      if (!parameters.problem.test_mode)
        return;
      const unsigned int n           = dealii::Utilities::MPI::max(failed, comm);
      const bool         expect_fail = parameters.verification.expect_failure;
      AssertThrow(n == 0 || expect_fail,
                  dealii::ExcMessage(
                    "Test mode: " + std::to_string(n) +
                    " verification check(s) above said 'no'. A test's reference must not store a "
                    "failed check; where the test shows a check failing on purpose, set "
                    "Verification/Expected verdict = no."));
      AssertThrow(n > 0 || !expect_fail,
                  dealii::ExcMessage("Test mode: Verification/Expected verdict = no, but every "
                                     "verification check said 'yes'."));
    }
  } // namespace Verification
} // namespace WheelRail
