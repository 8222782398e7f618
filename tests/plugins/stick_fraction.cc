/**
 * @file tests/plugins/stick_fraction.cc
 * The worked example of doc/developer.md, "a postprocessor with one
 * column": the fraction of the contact nodes that stick, averaged over the
 * steps since the previous statistics row (the per-step value chatters
 * where nodes switch between stick and slip). Selected by
 * Output/Postprocessors = stick fraction; its statistics column is "stick
 * fraction [-]". This one file is the whole postprocessor: the class, its
 * column, its checkpoint state and its registration.
 */

#include <wheelrail/postprocess/postprocessor.h>
#include <wheelrail/postprocess/registry.h>
#include <wheelrail/postprocess/statistics.h>

namespace
{
  using namespace WheelRail;

  class StickFraction : public SerializedPostprocessor<StickFraction>
  {
  public:
    explicit StickFraction(const SimulatorAccess &access)
      : access(access)
    {}

    /** After every step: add this step's fraction (0 without contact);
     *  at a statistics step, the mean since the previous one. */
    void
    execute(const StepInfo &step) override
    {
      const ContactSummary &summary = access.contact->summary();
      sum += summary.n_contact > 0 ?
               1. - static_cast<double>(summary.n_slip) / summary.n_contact :
               0.;
      ++steps;
      if (step.energies != nullptr)
        {
          mean  = sum / steps;
          sum   = 0;
          steps = 0;
        }
    }

    /** The column of the statistics row of this step. */
    void
    add_statistics(StatisticsTable &table) const override
    {
      table.add_number("stick fraction [-]", mean);
    }

    /** The checkpoint: the sum and count of the row in progress. */
    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar.pod(sum);
      ar.pod(steps);
    }

  private:
    const SimulatorAccess &access;
    double                 sum   = 0; ///< of the steps since the last row
    unsigned long          steps = 0;
    double                 mean  = 0; ///< of the last row's steps
  };



  const PostprocessorPlugin stick_fraction = {
    "stick fraction",
    "column 'stick fraction [-]', the fraction of the contact nodes that stick, averaged over the "
    "steps since the previous row",
    nullptr, // no parameters of its own
    [](const dealii::ParameterHandler &) -> PostprocessorFactory {
      return [](const SimulatorAccess &access) -> std::unique_ptr<Postprocessor> {
        AssertThrow(access.contact,
                    dealii::ExcMessage("Output/Postprocessors: 'stick fraction' needs contact "
                                       "(Contact/Enabled = true)."));
        return std::make_unique<StickFraction>(access);
      };
    }};
} // namespace

WHEELRAIL_REGISTER_POSTPROCESSOR(stick_fraction)
