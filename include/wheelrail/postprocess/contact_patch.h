/**
 * @file postprocess/contact_patch.h
 * The contact patch: its centre, the micro-slip of its trailing part, the
 * per-node state (contact_nodes.csv), the snapshots of SPEC 5.5 and the
 * summary at the end of a rolling run.
 */
#ifndef wheelrail_postprocess_contact_patch_h
#define wheelrail_postprocess_contact_patch_h

#include <wheelrail/postprocess/contact_patches.h>
#include <wheelrail/postprocess/postprocessor.h>
#include <wheelrail/verification/hertz_patch.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace WheelRail
{
  /** Means over the contact nodes behind the patch centre. */
  struct TrailingSlip
  {
    double         magnitude = 0; ///< of the micro-slip s_n = |de| / dt [m/s]
    Tensor<1, dim> rate;          ///< of the relative velocity de / dt [m/s]
  };
  TrailingSlip
  trailing_micro_slip(const PenaltyContact &contact);

  /** Per-node contact state of the slave surface as CSV (SPEC 6 columns)
   *  in OUTDIR/@p name. */
  void
  write_contact_nodes(const SimulatorAccess &access, const std::string &name);

  /** Whether point @p p lies over the solution zones of @p g (|x| <=
   *  length / 2, y within the zones' lateral span: |y| <= half width on
   *  the paper's pair). */
  inline bool
  over_solution_zone(const GeometryParameters &g, const Point<3> &p)
  {
    return std::abs(p[0]) <= 0.5 * g.zone_length + 1e-9 && p[1] >= g.zone_y_lo - 1e-9 &&
           p[1] <= g.zone_y_hi + 1e-9;
  }

  /** Whether rail-top node @p m (of master_node_results()) lies in the
   *  solution zone with a tributary area: the nodes of the patch files. */
  inline bool
  in_solution_zone(const GeometryParameters &g, const NodalContact &m)
  {
    return over_solution_zone(g, m.X) && m.area > 0;
  }

  /** A contact field of the patch's surface files: its name and its
   *  components at [first, first + components) of patch_field_values(). */
  struct PatchField
  {
    std::string  name;
    unsigned int first;
    unsigned int components;
  };
  /** The nodal values of patch_field_values(). */
  constexpr unsigned int n_patch_values = 12;
  /** pressure_Pa, shear_Pa (3), slip_velocity_m_s, slip_rate_m_s (3), cof,
   *  state_0free_1adhesion_2slip, adhesion_share, slip_share. */
  const std::vector<PatchField> &
  patch_fields();
  /** The values of patch_fields() at rail-top node @p m. */
  std::array<float, n_patch_values>
  patch_field_values(const NodalContact &m);

  /**
   * The contact fields of @p nodes (master_node_results()) on the rail-top
   * faces of the solution zone as a surface mesh: OUTDIR/@p file_name, a
   * VTU of quadrilaterals with the point data pressure, shear (vector),
   * micro-slip s_n, slip rate de/dt (vector), COF, state (0 free,
   * 1 adhesion, 2 slip), adhesion and slip shares.
   */
  void
  write_patch_surface(const SimulatorAccess           &access,
                      const std::vector<NodalContact> &nodes,
                      const std::string               &file_name);

  /**
   * The same fields of @p nodes (slave_node_results()) on the wheel tread:
   * the first pass's slave faces whose nodes are contact candidates and lie
   * over the solution zone, at the nodes' current positions.
   */
  void
  write_tread_surface(const SimulatorAccess           &access,
                      const std::vector<NodalContact> &nodes,
                      const std::string               &file_name);
  /** The faces of write_tread_surface(): the contact's candidate slave faces
   *  whose four nodes (@p nodes = slave_node_results()) lie over the solution
   *  zone at their current positions. */
  std::vector<std::array<unsigned int, 4>>
  tread_faces_over_zone(const SimulatorAccess &access, const std::vector<NodalContact> &nodes);

  /**
   * Contact-patch snapshots at the instants of SPEC 5.5: when the patch
   * centre passes x = -V dt_s, 0, +V dt_s (dt_s = 5.7 us), the rail-top
   * nodes of the solution zone as patch_NAME.csv and, on the rail-top
   * faces, patch_NAME.vtu (write_patch_surface()), on the tread faces
   * over the zone patch_tread_NAME.vtu (write_tread_surface()); with
   * Output/Patch averaging window > 0, the time means over that window
   * centred on each instant as patch_NAME_mean.csv. Where the geometry
   * reports patches (a profile case), patch_NAME.csv has the column patch,
   * the node's patch (ContactPatches::patch_of(), from 1).
   * Active with a wheelset and contact.
   */
  class ContactPatch : public SerializedPostprocessor<ContactPatch>
  {
  public:
    explicit ContactPatch(const SimulatorAccess &access);

    void
    execute(const StepInfo &step) override;

    /** The short human summary of the contact at the end of a rolling run
     *  (not in the robust output of a round-off sensitive test). */
    void
    print_summary() const;

    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar.pod(previous_centre);
      ar.pod(next_snapshot);
      for (Window &w : windows)
        {
          ar.pod(w.steps);
          ar.pod(w.done);
          ar.vector(w.sums);
        }
    }

  private:
    /** The sums of a snapshot's averaging window: per rail-top node of
     *  PenaltyContact::master_node_results() (that order), the quantities
     *  of window_fields(). */
    struct Window
    {
      std::uint64_t       steps = 0;
      std::uint8_t        done  = 0;
      std::vector<double> sums;
    };
    static constexpr unsigned int n_window_fields = 8;
    /** Add this step to the windows that contain the patch centre @p centre,
     *  and write those that it has just left. */
    void
    average(const double centre);
    /** Write patch_NAME_mean.csv of snapshot @p k. */
    void
    write_mean(const unsigned int k) const;

    /** Write the snapshot @p name (t-5.7us, t, t+5.7us) at @p centre. */
    void
    write_snapshot(const std::string &name, const double centre) const;

    /** The patch at t against Hertz (the paper's pair), or where its
     *  reference is (profiles from files). */
    void
    judge_patch_at_t(const std::vector<Verification::PatchNode> &patch) const;

    const SimulatorAccess &access;
    /** The patches of a geometry that reports them. */
    std::optional<ContactPatches> patches;
    double                        previous_centre = -std::numeric_limits<double>::max();
    unsigned int                  next_snapshot   = 0;
    Window                        windows[3];
  };
} // namespace WheelRail

#endif
