/**
 * @file postprocess/contact_patches.h
 * The contact split into patches, one per rigid contact point of the
 * profiles (SPEC 10), and each patch's results in its own frame.
 *
 * Assignment: a contact node belongs to the patch of the rigid contact
 * point nearest to it laterally (its y; the boundaries are the midpoints
 * between neighbouring rigid points). The patches are thereby fixed for
 * the whole run (the statistics have one set of columns per rigid point),
 * independent of the rank count, and a patch whose rigid point is not in
 * contact reports zeros. When two patches grow into one connected contact
 * region, the region stays split at the midpoint: each part is reported
 * with its rigid point's frame, the parts' forces still sum to the total,
 * and the patches are marked joined (a rail-top face with its four nodes
 * in contact spans both).
 *
 * Frame of patch k, from its rigid point's contact angle delta (the rail
 * top's normal, from z in the y-z plane, > 0 leaning towards +y): n = (0, sin delta, cos delta),
 * x = (1, 0, 0) rolling, s = n x x = (0, cos delta, -sin delta) lateral in
 * the tangent plane; (x, s, n) is right-handed.
 *
 * Forces: those summary() of the contact sums into F_N, F_L, F_lateral,
 * on the wheel: per slave state in contact F = f_n normal + F_t, + F for
 * the first pass's slaves (wheel nodes), - F for the second pass's (rail
 * nodes), each in the patch of its current y. The shape of the patch
 * (area, length, width, p_max) is that of the rail-top nodes in contact
 * (master_node_results(), the nodes of the patch snapshots), each in the
 * patch of its reference y.
 */
#ifndef wheelrail_postprocess_contact_patches_h
#define wheelrail_postprocess_contact_patches_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <wheelrail/contact/penalty_contact.h>
#include <wheelrail/geometry/rigid_contact.h>

#include <vector>

namespace WheelRail
{
  /** The frame of a patch: x rolling, s lateral, n normal (SPEC 10). */
  struct PatchFrame
  {
    Tensor<1, dim> x, s, n;

    /** The frame of the rail top at contact angle @p delta [rad]. */
    static PatchFrame
    at_contact_angle(const double delta);
  };

  /** The results of one patch; forces on the wheel, SI units. */
  struct PatchResult
  {
    /** The patch's contact force in the global frame [N]. */
    Tensor<1, dim> force;
    /** The same in the patch frame: F_x (rolling), F_s (lateral), F_n
     *  (normal, > 0 in compression) [N]. */
    double F_x = 0, F_s = 0, F_n = 0;
    /** Moment about n through the centre of pressure of the slaves'
     *  forces, n . sum (x_i - c) x F_i [N m]. */
    double M_n = 0;
    /** Centre of pressure: the slaves' current positions weighted by
     *  their normal forces [m] (0 without contact). */
    Point<dim> centre;
    /** The contact angle there: of the normal-force weighted mean of the
     *  rail's outward normals at the slaves' contact points [rad]. */
    double contact_angle = 0;
    /** Rail-top nodes in contact: their number, tributary area [m^2],
     *  extents along x (length) and along s (width) of their positions
     *  [m] and the largest pressure [Pa]. */
    unsigned int n_nodes = 0;
    double       area = 0, length = 0, width = 0, p_max = 0;
    /** Whether a rail-top face in contact joins it to another patch. */
    bool joined = false;
  };

  /**
   * The patches of a contact: one per rigid contact point, their frames,
   * the assignment of contact nodes to them and their results.
   */
  class ContactPatches
  {
  public:
    /** One patch per point of @p contacts (at least one). */
    explicit ContactPatches(const std::vector<Geometry::RigidContact> &contacts);

    /** Number of patches. */
    unsigned int
    size() const
    {
      return points.size();
    }

    /** The rigid contact point of patch @p k. */
    const Geometry::RigidContact &
    point(const unsigned int k) const
    {
      return points[k];
    }

    /** The frame of patch @p k. */
    const PatchFrame &
    frame(const unsigned int k) const
    {
      return frames[k];
    }

    /** The patch of a node at lateral position @p y [m]: that of the
     *  nearest rigid contact point (the lower index on a tie). */
    unsigned int
    patch_of(const double y) const;

    /** The results of every patch for the contact's last evaluation (the
     *  same on every rank). */
    std::vector<PatchResult>
    evaluate(const PenaltyContact &contact) const;

  private:
    std::vector<Geometry::RigidContact> points;
    std::vector<PatchFrame>             frames;

    /** Forces, moment, centre of pressure and its contact angle. */
    void
    add_forces(const PenaltyContact &contact, std::vector<PatchResult> &results) const;
    /** Shape of the rail-top nodes in contact, and the joined flags. */
    void
    add_shape(const PenaltyContact &contact, std::vector<PatchResult> &results) const;
  };
} // namespace WheelRail

#endif
