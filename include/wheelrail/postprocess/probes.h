/**
 * @file postprocess/probes.h
 * Nodes whose displacement and velocity are recorded every step: the node
 * nearest to Output/Probe point (probe.csv) and, with a wheelset, the
 * wheel-tread node that passes O (wheel_probe.csv).
 */
#ifndef wheelrail_postprocess_probes_h
#define wheelrail_postprocess_probes_h

#include <wheelrail/postprocess/postprocessor.h>

#include <string>
#include <vector>

namespace WheelRail
{
  /** A node whose displacement and velocity are recorded every step. */
  struct Probe
  {
    std::string         file;   ///< output file name
    Point<dim>          target; ///< the node nearest to it is recorded
    types::material_id  material = numbers::invalid_material_id; ///< search only this body
    unsigned int        owner    = 0;                            ///< rank owning the node
    unsigned int        dof      = 0; ///< local index of its x-DoF on the owner
    Point<dim>          location;     ///< reference position of the node
    std::vector<double> history;      ///< t, u_x,u_y,u_z, v_x,v_y,v_z per step
  };

  class Probes : public SerializedPostprocessor<Probes>
  {
  public:
    /** Find the probe nodes; a probe point outside the mesh stops the
     *  run. */
    explicit Probes(const SimulatorAccess &access);

    /** Record the current state (also before the first step). */
    void
    record();

    void
    execute(const StepInfo &step) override;

    /** Each probe's CSV, written by the rank that owns its node. */
    void
    write_files() const override;

    template <class Archive>
    void
    serialize(Archive &ar)
    {
      std::uint64_t n = probes.size();
      ar.pod(n);
      AssertThrow(n == probes.size(), ExcMessage("The checkpoint's probes differ."));
      for (Probe &probe : probes)
        ar.vector(probe.history);
    }

    /** nodes()[0]: Output/Probe point; with a wheelset also the wheel
     *  probe. */
    const std::vector<Probe> &
    nodes() const
    {
      return probes;
    }

  private:
    void
    check_inside_mesh() const;

    const SimulatorAccess &access;
    std::vector<Probe>     probes;
  };
} // namespace WheelRail

#endif
