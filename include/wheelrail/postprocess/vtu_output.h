/**
 * @file postprocess/vtu_output.h
 * The solution for ParaView: solution_NNNNN.pvtu (displacement, velocity,
 * von Mises stress, material id, MPI rank) and solution.pvd, the record
 * of all of them with their times. Not written in test mode.
 */
#ifndef wheelrail_postprocess_vtu_output_h
#define wheelrail_postprocess_vtu_output_h

#include <deal.II/base/data_out_base.h>

#include <wheelrail/postprocess/postprocessor.h>

#include <string>
#include <utility>
#include <vector>

namespace WheelRail
{
  /** zlib level of Output/VTU compression ('fast', 'best', 'none'). */
  DataOutBase::VtkFlags::ZlibCompressionLevel
  vtu_compression_level(const VtuCompression setting);

  class VtuOutput : public SerializedPostprocessor<VtuOutput>
  {
  public:
    explicit VtuOutput(const SimulatorAccess &access);

    /** Write the current solution and update solution.pvd. */
    void
    write();

    /** Every Output/VTU interval steps, except after the last step (the
     *  run's end writes that one). */
    void
    execute(const StepInfo &step) override;

    template <class Archive>
    void
    serialize(Archive &ar)
    {
      std::uint64_t n = records.size();
      ar.pod(n);
      records.resize(n);
      for (auto &r : records)
        {
          ar.pod(r.first);
          ar.string(r.second);
        }
      ar.pod(counter);
    }

  private:
    const SimulatorAccess                      &access;
    std::vector<std::pair<double, std::string>> records; ///< time, file of each
    unsigned int                                counter = 0;
  };
} // namespace WheelRail

#endif
