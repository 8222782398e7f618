/**
 * @file verification/samples.h
 * The time series that the contact checks at the end of a run evaluate
 * (block on plate, rolling wheel): one Sample per statistics step, and the
 * count of friction violations over all steps.
 */
#ifndef wheelrail_verification_samples_h
#define wheelrail_verification_samples_h

#include <wheelrail/postprocess/postprocessor.h>

#include <vector>

namespace WheelRail
{
  /** The contact state at one statistics step (a trivially copyable
   *  record: the checkpoint stores the vector of them as bytes). */
  struct Sample
  {
    double         t;
    Tensor<1, dim> block_momentum, plate_momentum, block_displacement, contact_force;
    Tensor<1, dim> relative_displacement; ///< block relative to the plate under it
    unsigned int   n_contact;
    double         kinetic, external_work, friction, total;
    double         tangential_stiffness; ///< sum of k_t over the contact pairs
    double         mean_cof;             ///< sum f |F_n| / sum |F_n| over the contact nodes
    double         trailing_slip;        ///< mean micro-slip behind the patch centre
    Tensor<1, dim> trailing_slip_rate;   ///< mean relative velocity vector there
  };

  /** Records the samples of a run with contact. */
  class SampleRecorder : public SerializedPostprocessor<SampleRecorder>
  {
  public:
    explicit SampleRecorder(const SimulatorAccess &access);

    /** Every step: count the friction violations; at a statistics step
     *  also record a Sample. */
    void
    execute(const StepInfo &step) override;

    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar.vector(recorded);
      ar.pod(violations);
    }

    const std::vector<Sample> &
    samples() const
    {
      return recorded;
    }
    /** Steps x nodes with |F_t| > f |F_n| over the whole run. */
    unsigned long
    friction_violations() const
    {
      return violations;
    }

  private:
    void
    record(const Energies &e);

    const SimulatorAccess &access;
    std::vector<Sample>    recorded;
    unsigned long          violations = 0;
  };
} // namespace WheelRail

#endif
