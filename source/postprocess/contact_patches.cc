#include <deal.II/base/exceptions.h>

#include <wheelrail/postprocess/contact_patches.h>

#include <algorithm>
#include <cmath>

namespace WheelRail
{
  namespace
  {
    /**
     * Call @p f(state, sign) for every slave state of @p contact in
     * contact, in pass and slave order: sign = +1 for the first pass's
     * slaves (on the wheel), -1 for the second's (on the rail), so that
     * sign F is the force on the wheel and sign normal the rail's outward
     * normal.
     */
    template <class Function>
    void
    for_each_contact_slave(const PenaltyContact &contact, const Function &f)
    {
      for (unsigned int p = 0; p < contact.n_passes(); ++p)
        for (const ContactNodeState &state : contact.slave_states(p))
          if (state.in_contact)
            f(state, p == 0 ? 1. : -1.);
    }
  } // namespace



  PatchFrame
  PatchFrame::at_contact_angle(const double delta)
  {
    PatchFrame frame;
    frame.x[0] = 1;
    frame.n[1] = std::sin(delta);
    frame.n[2] = std::cos(delta);
    frame.s    = cross_product_3d(frame.n, frame.x);
    return frame;
  }



  ContactPatches::ContactPatches(const std::vector<Geometry::RigidContact> &contacts)
    : points(contacts)
  {
    AssertThrow(!points.empty(), ExcMessage("A contact has at least one patch."));
    for (const Geometry::RigidContact &c : points)
      frames.push_back(PatchFrame::at_contact_angle(c.contact_angle));
  }



  unsigned int
  ContactPatches::patch_of(const double y) const
  {
    unsigned int best = 0;
    for (unsigned int k = 1; k < points.size(); ++k)
      if (std::abs(y - points[k].y) < std::abs(y - points[best].y))
        best = k;
    return best;
  }



  std::vector<PatchResult>
  ContactPatches::evaluate(const PenaltyContact &contact) const
  {
    std::vector<PatchResult> results(size());
    add_forces(contact, results);
    add_shape(contact, results);
    return results;
  }



  void
  ContactPatches::add_forces(const PenaltyContact &contact, std::vector<PatchResult> &results) const
  {
    // the forces, the centre of pressure and the mean rail normal
    std::vector<double>         fn(size(), 0.);
    std::vector<Tensor<1, dim>> weighted_x(size()), normal(size());
    for_each_contact_slave(contact, [&](const ContactNodeState &state, const double sign) {
      const unsigned int k = patch_of(state.x[1]);
      results[k].force += sign * (state.normal_force * state.normal + state.tangential_force);
      fn[k] += state.normal_force;
      weighted_x[k] += state.normal_force * state.x;
      normal[k] += (sign * state.normal_force) * state.normal;
    });
    for (unsigned int k = 0; k < size(); ++k)
      {
        PatchResult      &r = results[k];
        const PatchFrame &e = frames[k];
        r.F_x               = r.force * e.x;
        r.F_s               = r.force * e.s;
        r.F_n               = r.force * e.n;
        if (fn[k] > 0)
          {
            r.centre        = Point<dim>(weighted_x[k] / fn[k]);
            r.contact_angle = std::atan2(normal[k][1], normal[k][2]);
          }
      }
    // the moment about n through the centre of pressure
    for_each_contact_slave(contact, [&](const ContactNodeState &state, const double sign) {
      const unsigned int   k = patch_of(state.x[1]);
      const Tensor<1, dim> F = sign * (state.normal_force * state.normal + state.tangential_force);
      results[k].M_n += frames[k].n * cross_product_3d(state.x - results[k].centre, F);
    });
  }



  void
  ContactPatches::add_shape(const PenaltyContact &contact, std::vector<PatchResult> &results) const
  {
    const std::vector<NodalContact> nodes = contact.master_node_results();
    std::vector<unsigned int>       patch(nodes.size());
    std::vector<double>             x_lo(size(), 1e300), x_hi(size(), -1e300), s_lo(size(), 1e300),
      s_hi(size(), -1e300);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const NodalContact &m = nodes[i];
        patch[i]              = patch_of(m.X[1]);
        if (!m.in_contact() || m.area <= 0)
          continue;
        PatchResult &r = results[patch[i]];
        const double s = frames[patch[i]].s * m.X;
        ++r.n_nodes;
        r.area += m.area;
        r.p_max        = std::max(r.p_max, m.pressure());
        x_lo[patch[i]] = std::min(x_lo[patch[i]], m.X[0]);
        x_hi[patch[i]] = std::max(x_hi[patch[i]], m.X[0]);
        s_lo[patch[i]] = std::min(s_lo[patch[i]], s);
        s_hi[patch[i]] = std::max(s_hi[patch[i]], s);
      }
    for (unsigned int k = 0; k < size(); ++k)
      if (results[k].n_nodes > 0)
        {
          results[k].length = x_hi[k] - x_lo[k];
          results[k].width  = s_hi[k] - s_lo[k];
        }
    // a face in contact at all four nodes that spans two patches joins them
    for (const auto &face : contact.master_face_nodes())
      {
        bool         all_in = true;
        unsigned int lo = size(), hi = 0;
        for (const unsigned int v : face)
          {
            all_in = all_in && nodes[v].in_contact();
            lo     = std::min(lo, patch[v]);
            hi     = std::max(hi, patch[v]);
          }
        if (all_in && lo != hi)
          results[lo].joined = results[hi].joined = true;
      }
  }
} // namespace WheelRail
