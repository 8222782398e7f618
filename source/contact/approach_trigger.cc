/**
 * @file contact/approach_trigger.cc
 * The parts of PenaltyContact that guard the candidate lists: the approach
 * bound, which calls for a search before a slave and a master face that are
 * not candidates can meet, and the check of the initial overlap.
 *
 * The approach bound. A search lists the pair (s, f) of a slave node s and
 * a master face f when x_s lies in the bounding box of f grown by the
 * search margin m on every side. A pair that is not listed therefore had,
 * at the search, a distance D0 = dist(x_s, f) > m (a bilinear face lies in
 * the convex hull of its corners, hence in its box). At the search every
 * slave s gets the clearance c_s = distance from x_s to the nearest box of
 * a master face of its pass, and every master face the clearance c_f =
 * distance from its box to the nearest slave of the pass; both bound D0
 * from below. So D0 >= max(m, c_s, c_f) >= e_s + e_f with the allowances
 * e_s = max(m, c_s) / 2 and e_f = max(m, c_f) / 2. A master node j gets the
 * smallest e_f of its faces, e_j.
 *
 * Since the search the slave moved by dx_s and the point of the face with
 * the same face coordinates by at most max_j |dx_j| over its corners (the
 * bilinear shape functions are non-negative and sum to one). The distance
 * of the pair now is therefore at least
 *   D0 - |dx_s| - max_j |dx_j| >= -[(|dx_s| - e_s) + max_j (|dx_j| - e_j)]
 *                             >= -(A + B),
 * A = max over all slaves of (|dx_s| - e_s), B = max over all master nodes
 * of (|dx_j| - e_j). While A + B < -(1 - Rebuild fraction) m every pair
 * that is not listed stays farther apart than (1 - Rebuild fraction) m > 0.
 * A and B are evaluated at every evaluation, each rank over the contact
 * nodes whose DoFs it owns, and reduced with one allreduce; when the bound
 * fails a search runs at once, before the forces of this evaluation.
 *
 * Between two evaluations a pair that is not listed could still cross if
 * the surfaces moved by more than the distance it kept, (1 - Rebuild
 * fraction) m, in one step. The largest motion in one step of a slave and
 * of a master node is reduced with A and B; if their sum reaches that
 * distance the run stops (the margin is too small for the motion per step).
 * With both, no slave meets a face it is not listed with.
 *
 * The bound is kept per pass (two-pass contact: a node has an allowance as
 * slave and one as master-face corner in each pass). It costs one loop over
 * this rank's contact nodes per evaluation, and at each search two nearest-
 * neighbour queries per owned node. The candidate trigger of add_forces()
 * (a candidate moved more than Rebuild fraction x m) and Search interval
 * are kept.
 */

#include <deal.II/base/mpi.h>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <wheelrail/contact/penalty_contact.h>
#include <wheelrail/mesh/geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace WheelRail
{
  namespace
  {
    namespace bg     = boost::geometry;
    namespace bgi    = boost::geometry::index;
    using BoostPoint = bg::model::point<double, 3, bg::cs::cartesian>;
    using BoostBox   = bg::model::box<BoostPoint>;

    constexpr double no_role = std::numeric_limits<double>::max();

    /** The body a contact boundary belongs to, and the parameters that place it. */
    std::pair<std::string, std::string>
    body_of(const types::boundary_id id)
    {
      namespace B = Geometry::BoundaryIds;
      if (id == B::wheel_tread || id == B::wheel_bore || id == B::wheel_side)
        return {"wheel", "Geometry/Wheel/Initial gap and Centre x"};
      if (id >= B::rail_top && id <= B::rail_side)
        return {"rail", "Geometry/Rail"};
      if (id >= B::block_bottom && id <= B::block_side)
        return {"block", "Geometry/Block on plate/Block gap and Block x"};
      if (id >= B::plate_top && id <= B::plate_side)
        return {"plate", "Geometry/Block on plate/Plate size"};
      return {"body of boundary " + std::to_string(id), "Geometry"};
    }

    std::string
    millimetres(const Point<dim> &p)
    {
      std::ostringstream s;
      s << "(" << p[0] * 1e3 << ", " << p[1] * 1e3 << ", " << p[2] * 1e3 << ") mm";
      return s.str();
    }
  } // namespace



  void
  PenaltyContact::plan_approach_trigger()
  {
    const double margin = prm.search_margin;
    // this rank's contact nodes, in the order of their DoFs
    std::vector<int> entry(node_dof.size(), -1);
    trigger_nodes.clear();
    for (unsigned int n = 0; n < node_dof.size(); ++n)
      if (partitioner->in_local_range(node_dof[n]))
        {
          entry[n] = trigger_nodes.size();
          TriggerNode t;
          t.local_dof = partitioner->global_to_local(node_dof[n]);
          t.u_search  = node_x_search[n] - node_X[n];
          std::fill(std::begin(t.e), std::end(t.e), no_role);
          trigger_nodes.push_back(t);
        }

    for (unsigned int p = 0; p < passes.size(); ++p)
      {
        const Pass &pass = passes[p];
        // the master faces' boxes and the slaves at the search
        std::vector<std::pair<BoostBox, unsigned int>> boxes(pass.faces.size());
        for (unsigned int f = 0; f < pass.faces.size(); ++f)
          {
            const auto [lo, hi] = face_box(pass.faces[f], node_x_search);
            boxes[f] = {BoostBox(BoostPoint(lo[0], lo[1], lo[2]), BoostPoint(hi[0], hi[1], hi[2])),
                        f};
          }
        std::vector<std::pair<BoostPoint, unsigned int>> points(pass.slaves.size());
        for (unsigned int s = 0; s < pass.slaves.size(); ++s)
          {
            const Point<dim> &x = node_x_search[pass.slave_node[s]];
            points[s]           = {BoostPoint(x[0], x[1], x[2]), s};
          }
        const bgi::rtree<std::pair<BoostBox, unsigned int>, bgi::quadratic<16>>   face_tree(boxes);
        const bgi::rtree<std::pair<BoostPoint, unsigned int>, bgi::quadratic<16>> slave_tree(
          points);

        std::vector<std::pair<BoostBox, unsigned int>>   nearest_face;
        std::vector<std::pair<BoostPoint, unsigned int>> nearest_slave;
        for (unsigned int s = 0; s < pass.slaves.size(); ++s)
          if (entry[pass.slave_node[s]] >= 0)
            {
              nearest_face.clear();
              face_tree.query(bgi::nearest(points[s].first, 1), std::back_inserter(nearest_face));
              const double c = bg::distance(points[s].first, nearest_face.front().first);
              double      &e = trigger_nodes[entry[pass.slave_node[s]]].e[2 * p];
              e              = std::min(e, 0.5 * std::max(margin, c));
            }
        for (unsigned int f = 0; f < pass.faces.size(); ++f)
          {
            const unsigned int *node = pass.faces[f].node;
            if (entry[node[0]] < 0 && entry[node[1]] < 0 && entry[node[2]] < 0 &&
                entry[node[3]] < 0)
              continue;
            nearest_slave.clear();
            slave_tree.query(bgi::nearest(boxes[f].first, 1), std::back_inserter(nearest_slave));
            const double c = bg::distance(boxes[f].first, nearest_slave.front().first);
            for (unsigned int v = 0; v < 4; ++v)
              if (entry[node[v]] >= 0)
                {
                  double &e = trigger_nodes[entry[node[v]]].e[2 * p + 1];
                  e         = std::min(e, 0.5 * std::max(margin, c));
                }
          }
      }
    std::sort(trigger_nodes.begin(),
              trigger_nodes.end(),
              [](const TriggerNode &a, const TriggerNode &b) { return a.local_dof < b.local_dof; });
    // at a search the positions are those of this evaluation: dx = 0
    step_motion_known = true;
  }



  bool
  PenaltyContact::approach_bound_exceeded(const LinearAlgebra::distributed::Vector<double> &u,
                                          const bool                                        advance,
                                          Clock::time_point                                &clock)
  {
    // per pass: A (slaves), B (master nodes); then the largest motion in
    // this step of a slave and of a master node
    constexpr unsigned int ahead    = 16;
    const unsigned int     n_values = 2 * passes.size();
    double                 value[6];
    std::fill(value, value + 6, -no_role);
    double *const      step = value + n_values;
    const double      *U    = u.begin();
    const unsigned int n    = trigger_nodes.size();
    for (unsigned int k = 0; k < n; ++k)
      {
        TriggerNode &t = trigger_nodes[k];
        if (k + ahead < n)
          __builtin_prefetch(U + trigger_nodes[k + ahead].local_dof, 0, 0);
        Tensor<1, dim> dx;
        for (unsigned int d = 0; d < dim; ++d)
          dx[d] = U[t.local_dof + d] - t.u_search[d];
        const double moved         = dx.norm();
        const double moved_in_step = (dx - t.dx).norm();
        t.dx                       = dx;
        for (unsigned int r = 0; r < n_values; ++r)
          {
            value[r] = std::max(value[r], moved - t.e[r]);
            if (t.e[r] != no_role)
              step[r % 2] = std::max(step[r % 2], moved_in_step);
          }
      }
    timing.positions += lap(clock);
    if (Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
      {
        const int ierr =
          MPI_Allreduce(MPI_IN_PLACE, value, n_values + 2, MPI_DOUBLE, MPI_MAX, mpi_communicator);
        AssertThrowMPI(ierr);
        timing.wait += lap(clock);
      }

    const double keep = kept_distance();
    if (advance && step_motion_known && !(step[0] + step[1] < keep))
      {
        std::ostringstream message;
        message << "Contact nodes moved " << step[0] * 1e3 << " mm (slave) and " << step[1] * 1e3
                << " mm (master) in one step, together more than (1 - Contact/Rebuild fraction) "
                   "x Contact/Search margin = "
                << keep * 1e3
                << " mm: a slave could cross a master face between two searches unseen. "
                   "Increase Contact/Search margin (or lower Contact/Rebuild fraction, or the "
                   "time step).";
        AssertThrow(false, ExcMessage(message.str()));
      }
    step_motion_known = true;
    for (unsigned int p = 0; p < passes.size(); ++p)
      if (!(value[2 * p] + value[2 * p + 1] < -keep))
        return true;
    return false;
  }



  double
  PenaltyContact::deepest_new_contact() const
  {
    return Utilities::MPI::max(new_contact_depth, mpi_communicator);
  }



  void
  PenaltyContact::check_initial_overlap() const
  {
    // The faces of a curved surface are chords of it: a node of one body
    // on the true surface of the other lies up to h^2 / (8 R) behind its
    // faces (h the face size, R the radius of curvature), which is below
    // 0.05 h wherever h <= 0.4 R (the wheel and rail meshes have h below
    // 0.05 R). A deeper penetration at the start is an overlap of the
    // bodies as placed; its penalty force would act at once in full.
    // The states are the same on every rank: so is the decision.
    double       depth = 0, tolerance = 0;
    Point<dim>   where;
    unsigned int pass_of = 0;
    for (unsigned int p = 0; p < passes.size(); ++p)
      for (const unsigned int s : passes[p].candidate_slaves)
        {
          const ContactNodeState &state = passes[p].slaves[s];
          if (!state.in_contact)
            continue;
          const MasterFace  &face        = passes[p].faces[state.face];
          double             h           = 0;
          const unsigned int edges[4][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}};
          for (const auto &e : edges)
            h = std::max(h, node_X[face.node[e[0]]].distance(node_X[face.node[e[1]]]));
          const double allowed = std::max(0.05 * h, prm.initial_overlap_tolerance);
          if (-state.gap / allowed > (depth > 0 ? depth / tolerance : 1.))
            {
              depth     = -state.gap;
              tolerance = allowed;
              where     = state.X;
              pass_of   = p;
            }
        }
    if (depth == 0)
      return;
    const bool         first_pass = pass_of == 0;
    const auto         slave      = body_of(first_pass ? prm.slave_boundary : prm.master_boundary);
    const auto         master     = body_of(first_pass ? prm.master_boundary : prm.slave_boundary);
    std::ostringstream message;
    message << "The bodies overlap at the start: a node of the " << slave.first
            << " at X = " << millimetres(where) << " lies " << depth * 1e3 << " mm deep in the "
            << master.first << ", more than the tolerance " << tolerance * 1e3
            << " mm (0.05 x the longest edge of the master face, the faceting of a curved "
               "surface, or Contact/Initial overlap tolerance). Its penalty force would act in "
               "full at the first step. Check the parameters that place the bodies: "
            << slave.second << "; " << master.second << ".";
    AssertThrow(false, ExcMessage(message.str()));
  }
} // namespace WheelRail
