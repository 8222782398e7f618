/**
 * @file verification/verdict.h
 * The "yes" or "no" of a verification check, counted: in test mode a run
 * whose checks said "no" fails (check_verdicts()), so that a reference
 * output copied without reading it cannot store a failed check.
 */
#ifndef wheelrail_verification_verdict_h
#define wheelrail_verification_verdict_h

#include <deal.II/base/mpi.h>

namespace WheelRail
{
  struct Parameters;

  namespace Verification
  {
    /** "yes" if @p ok, else "no"; a "no" is counted. */
    const char *
    verdict(bool ok);

    /** The "no" verdicts of this process so far. */
    unsigned int
    n_failed_verdicts();

    /**
     * In test mode (Problem/Test mode), collective: throws if the checks'
     * verdicts differ from Verification/Expected verdict ("yes": every
     * check passed; "no": a test that shows a check failing, at least one
     * "no"). Outside test mode it does nothing.
     */
    void
    check_verdicts(const Parameters &parameters, const MPI_Comm comm);
  } // namespace Verification
} // namespace WheelRail

#endif
