/**
 * @file postprocess/patch_series.h
 * The contact patch as a time series: OUTDIR/patch_series.h5 and
 * OUTDIR/patch_series.xdmf (ParaView plays it as a movie).
 */
#ifndef wheelrail_postprocess_patch_series_h
#define wheelrail_postprocess_patch_series_h

#include <wheelrail/postprocess/postprocessor.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace WheelRail
{
  /**
   * Every Output/Patch series interval steps (with a wheelset and contact),
   * the contact fields on the rail-top surface of the solution zone (the
   * mesh of write_patch_surface()): /mesh/points (nodes x 3, m),
   * /mesh/quads (faces x 4, node indices), /mesh/area (the nodes'
   * tributary areas, m^2), /time (frames) and per frame /fields/NAME
   * (frames x nodes, or x 3 for vectors, single precision): pressure_Pa,
   * shear_Pa, slip_velocity_m_s, slip_rate_m_s, cof,
   * state_0free_1adhesion_2slip. The wheel tread's faces over the zone
   * (write_tread_surface()), whose set changes as the wheel rolls, go to
   * one group per frame, /tread/K: points (current positions), quads, area
   * and the same fields, listed by patch_series_tread.xdmf. Rank 0 writes (the contact state is
   * replicated); each frame is flushed, and patch_series.xdmf (rewritten
   * atomically at report steps, at the run's last frame and by
   * write_files()) lists the frames for ParaView.
   *
   * Frame k is step (k + 1) N - 1, so a resumed run knows how many frames
   * its checkpoint had: it reopens the file, cuts it to them and goes on.
   */
  class PatchSeries : public Postprocessor
  {
  public:
    explicit PatchSeries(const SimulatorAccess &access);
    ~PatchSeries() override;

    void
    execute(const StepInfo &step) override;

    /** The XDMF lists, if frames were written since they were. */
    void
    write_files() const override;

    /** No state of its own in the checkpoint: the frames follow from the
     *  step, and the file holds them. */
    void
    save(Checkpoint::Writer &) override
    {}
    void
    load(Checkpoint::Reader &) override
    {}

  private:
    /** Select the solution zone's nodes, then create the file with the
     *  mesh (frame 0) or reopen it and cut it to @p frames frames (a
     *  resumed run). */
    void
    open(const unsigned long frames);
    /** Fill zone_nodes with the indices of the rail-top @p nodes in the
     *  solution zone and set n_quads; returns the @p faces with all four
     *  nodes in the zone as quadrilaterals (four zone-node indices each,
     *  in the VTK / XDMF order round the cell). */
    std::vector<int>
    select_zone(const std::vector<NodalContact>                &nodes,
                const std::vector<std::array<unsigned int, 4>> &faces);
    /** Create the file at @p path: /mesh (the zone's points and areas from
     *  @p nodes, @p quads), an empty /time, an empty extendable dataset
     *  per field in /fields and an empty group /tread. */
    void
    create_file(const std::string               &path,
                const std::vector<NodalContact> &nodes,
                const std::vector<int>          &quads);
    /** Reopen the file at @p path (a resumed run), read the times of its
     *  first @p frames frames and cut /time and /fields to them. */
    void
    reopen_file(const std::string &path, const unsigned long frames);
    /** In the reopened file: the sizes of the tread frames before
     *  @p frames into tread_sizes (0 where a frame has none), and the
     *  groups /tread/K of later frames removed. */
    void
    cut_tread_frames(const unsigned long frames);
    /** The wheel tread's faces over the zone at frame @p frame: group
     *  /tread/FRAME with points (current positions), quads, area and the
     *  fields, none if no face is there. */
    void
    write_tread_frame(const unsigned long frame);
    /** patch_series.xdmf (rail top) and patch_series_tread.xdmf (tread). */
    void
    write_xdmf() const;

    const SimulatorAccess    &access;
    std::int64_t              file = -1;  ///< the HDF5 file (hid_t)
    std::vector<unsigned int> zone_nodes; ///< indices in master_node_results()
    unsigned int              n_quads = 0;
    std::vector<double>       times; ///< of the frames so far
    /** Nodes and quadrilaterals of each tread frame (0 = none written). */
    std::vector<std::array<unsigned long, 2>> tread_sizes;
    /** Frames written that the XDMF lists do not list yet. */
    mutable bool xdmf_pending = false;
  };
} // namespace WheelRail

#endif
