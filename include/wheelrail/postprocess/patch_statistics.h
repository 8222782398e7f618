/**
 * @file postprocess/patch_statistics.h
 * The results per contact patch of a profile case (SPEC 10; the patches of
 * postprocess/contact_patches.h): columns of the statistics and lines of
 * the end-of-run summary.
 */
#ifndef wheelrail_postprocess_patch_statistics_h
#define wheelrail_postprocess_patch_statistics_h

#include <wheelrail/postprocess/contact_patches.h>
#include <wheelrail/postprocess/postprocessor.h>

namespace WheelRail
{
  /**
   * Per patch k = 1, 2, ... (the rigid contact points of the geometry in
   * their order, the main one first), at every statistics row: "patch k
   * F_n [N]", "F_x [N]", "F_s [N]", "M_n [N m]" (in the patch frame, on the
   * wheel), "y [m]" and "contact angle [rad]" of the centre of pressure,
   * "area [m^2]", "length [m]", "width [m]", "p_max [Pa]", "contact nodes",
   * "joined" (1 where a contact face spans two patches). At the end of a
   * rolling run, one summary line per patch and the check that the patch
   * forces turned back to the global frame sum to the contact's total.
   * Made only for a geometry that reports patches
   * (GeometryModel::reports_patches()), so other runs write what they
   * always wrote. Without state of its own (the contact's is checkpointed).
   */
  class PatchStatistics : public SerializedPostprocessor<PatchStatistics>
  {
  public:
    explicit PatchStatistics(const SimulatorAccess &access);

    /** Nothing: the columns are computed from the contact's last step. */
    void
    execute(const StepInfo &) override
    {}

    void
    add_statistics(StatisticsTable &table) const override;

    /** The patch lines of the end-of-run summary and the sum check (not in
     *  the robust output of a round-off sensitive test). */
    void
    print_summary() const;

    /** No state. */
    template <class Archive>
    void
    serialize(Archive &)
    {}

  private:
    const SimulatorAccess &access;
    const ContactPatches   contact_patches;

    /** Print the sum of the patch forces, turned back to the global frame,
     *  beside the contact's total. */
    void
    print_sum_check(const std::vector<PatchResult> &results) const;
  };
} // namespace WheelRail

#endif
