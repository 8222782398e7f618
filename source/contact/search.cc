/**
 * @file contact/search.cc
 * The candidate search of PenaltyContact: which slave nodes and master faces
 * can meet before the next search (face bounding boxes grown by the search
 * margin, an R-tree of the boxes), and the gathers of the contact nodes'
 * positions that the search and every step need.
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <wheelrail/base/stopwatch.h>
#include <wheelrail/contact/penalty_contact.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace WheelRail
{
  namespace
  {
    namespace bg     = boost::geometry;
    namespace bgi    = boost::geometry::index;
    using BoostPoint = bg::model::point<double, 3, bg::cs::cartesian>;
    using BoostBox   = bg::model::box<BoostPoint>;
  } // namespace



  void
  PenaltyContact::plan_gather(const std::vector<unsigned int> &nodes, GatherPlan &plan)
  {
    // this rank's nodes in the order of their DoFs: the reads of u in
    // gather_positions() go forward through memory
    std::vector<std::pair<unsigned int, unsigned int>> owned; // (local DoF, node)
    for (const unsigned int n : nodes)
      if (partitioner->in_local_range(node_dof[n]))
        owned.emplace_back(partitioner->global_to_local(node_dof[n]), n);
    std::sort(owned.begin(), owned.end());
    plan.local_dof.resize(owned.size());
    plan.X.resize(owned.size());
    std::vector<unsigned int> own_nodes(owned.size());
    for (unsigned int k = 0; k < owned.size(); ++k)
      {
        plan.local_dof[k] = owned[k].first;
        plan.X[k]         = node_X[owned[k].second];
        own_nodes[k]      = owned[k].second;
      }
    // the nodes in the order the positions arrive: all ranks' lists
    // concatenated (what every rank sends is fixed until the next plan)
    all_gather_concatenated(own_nodes, MPI_UNSIGNED, plan.nodes);
    const int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    plan.counts.resize(n_ranks);
    plan.displs.resize(n_ranks);
    for (int r = 0; r < n_ranks; ++r)
      {
        plan.counts[r] = dim * exchange_counts[r];
        plan.displs[r] = dim * exchange_displs[r];
      }
  }



  void
  PenaltyContact::gather_positions(const LinearAlgebra::distributed::Vector<double> &u,
                                   const GatherPlan                                 &plan)
  {
    // x = X + u of the owned nodes; u is read at scattered places (the
    // contact nodes among all the mesh's), each read a likely cache miss:
    // requested a few nodes ahead, the misses overlap
    constexpr unsigned int ahead = 16;
    const unsigned int     n_own = plan.local_dof.size();
    const double          *U     = u.begin();
    std::vector<double>   &send  = gather_send;
    send.resize(dim * n_own);
    for (unsigned int k = 0; k < n_own; ++k)
      {
        if (k + ahead < n_own)
          __builtin_prefetch(U + plan.local_dof[k + ahead], 0, 0);
        for (unsigned int d = 0; d < dim; ++d)
          send[dim * k + d] = plan.X[k][d] + U[plan.local_dof[k] + d];
      }
    const double *x = send.data();
    if (Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
      {
        gather_recv.resize(dim * plan.nodes.size());
        const int ierr = MPI_Allgatherv(send.data(),
                                        send.size(),
                                        MPI_DOUBLE,
                                        gather_recv.data(),
                                        plan.counts.data(),
                                        plan.displs.data(),
                                        MPI_DOUBLE,
                                        mpi_communicator);
        AssertThrowMPI(ierr);
        x = gather_recv.data();
      }
    for (unsigned int k = 0; k < plan.nodes.size(); ++k)
      node_x[plan.nodes[k]] = Point<dim>(x[dim * k], x[dim * k + 1], x[dim * k + 2]);
  }



  template <typename T>
  void
  PenaltyContact::all_gather_concatenated(const std::vector<T> &send,
                                          const MPI_Datatype    type,
                                          std::vector<T>       &recv)
  {
    const int         n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    int               count   = send.size();
    std::vector<int> &counts = exchange_counts, &displs = exchange_displs;
    counts.resize(n_ranks);
    displs.assign(n_ranks, 0);
    int ierr = MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, mpi_communicator);
    AssertThrowMPI(ierr);
    for (int r = 1; r < n_ranks; ++r)
      displs[r] = displs[r - 1] + counts[r - 1];
    recv.resize(displs.back() + counts.back());
    ierr = MPI_Allgatherv(
      send.data(), count, type, recv.data(), counts.data(), displs.data(), type, mpi_communicator);
    AssertThrowMPI(ierr);
  }



  std::pair<Point<dim>, Point<dim>>
  PenaltyContact::face_box(const MasterFace &face, const std::vector<Point<dim>> &x)
  {
    Point<dim> lo = x[face.node[0]], hi = lo;
    for (unsigned int v = 1; v < 4; ++v)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lo[d] = std::min(lo[d], x[face.node[v]][d]);
          hi[d] = std::max(hi[d], x[face.node[v]][d]);
        }
    return {lo, hi};
  }



  void
  PenaltyContact::search(const LinearAlgebra::distributed::Vector<double> &u)
  {
    Timer timer;
    gather_positions(u, all_gather);
    node_x_search = node_x;

    std::vector<bool> active(node_dof.size(), false);
    for (Pass &pass : passes)
      {
        std::vector<bool> was_candidate(pass.slaves.size(), false);
        for (const unsigned int s : pass.candidate_slaves)
          was_candidate[s] = true;
        const std::vector<unsigned int> found = query_candidates(pass);
        assign_candidates(found, was_candidate, pass, active);
      }
    active_nodes.clear();
    for (unsigned int n = 0; n < active.size(); ++n)
      if (active[n])
        active_nodes.push_back(n);
    plan_gather(active_nodes, active_gather);
    build_normal_adjacency();
    plan_approach_trigger();
    need_search        = false;
    steps_since_search = 0;
    ++searches;
    search_time += timer.wall_time();
  }



  std::pair<unsigned int, unsigned int>
  PenaltyContact::n_candidates() const
  {
    std::pair<unsigned int, unsigned int> n(0, 0);
    for (const Pass &pass : passes)
      {
        n.first += pass.candidate_slaves.size();
        n.second += pass.face_lists.size();
      }
    return n;
  }



  std::vector<unsigned int>
  PenaltyContact::query_candidates(const Pass &pass)
  {
    // rtree of the master faces' boxes grown by the margin
    const double                                   margin = prm.search_margin;
    std::vector<std::pair<BoostBox, unsigned int>> boxes;
    for (unsigned int f = 0; f < pass.faces.size(); ++f)
      {
        const auto [lo, hi] = face_box(pass.faces[f], node_x);
        boxes.emplace_back(BoostBox(BoostPoint(lo[0] - margin, lo[1] - margin, lo[2] - margin),
                                    BoostPoint(hi[0] + margin, hi[1] + margin, hi[2] + margin)),
                           f);
      }
    const bgi::rtree<std::pair<BoostBox, unsigned int>, bgi::quadratic<16>> tree(boxes);

    // the queries of this rank's block of the slaves, packed as
    // (slave, number of faces, faces in ascending order), then all
    // ranks' blocks in slave order on every rank
    const auto                                     own = own_candidates(pass.slaves.size());
    std::vector<unsigned int>                      found;
    std::vector<std::pair<BoostBox, unsigned int>> hits;
    for (unsigned int s = own.first; s < own.second; ++s)
      {
        const Point<dim> &x = node_x[pass.slave_node[s]];
        hits.clear();
        tree.query(bgi::intersects(BoostPoint(x[0], x[1], x[2])), std::back_inserter(hits));
        if (hits.empty())
          continue;
        found.push_back(s);
        found.push_back(hits.size());
        const std::size_t first = found.size();
        for (const auto &h : hits)
          found.push_back(h.second);
        std::sort(found.begin() + first, found.end());
      }
    if (Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
      {
        std::vector<unsigned int> merged;
        all_gather_concatenated(found, MPI_UNSIGNED, merged);
        found.swap(merged);
      }
    return found;
  }



  void
  PenaltyContact::assign_candidates(const std::vector<unsigned int> &found,
                                    const std::vector<bool>         &was_candidate,
                                    Pass                            &pass,
                                    std::vector<bool>               &active)
  {
    pass.candidate_slaves.clear();
    pass.face_offsets.assign(1, 0);
    pass.face_lists.clear();
    std::vector<bool> face_used(pass.faces.size(), false);
    std::size_t       next = 0; // the next packed slave in found
    for (unsigned int s = 0; s < pass.slaves.size(); ++s)
      {
        const Point<dim> &x = node_x[pass.slave_node[s]];
        if (next >= found.size() || found[next] != s)
          {
            // out of reach: no contact, no friction memory, no gap
            // (farther than the margin)
            pass.slaves[s].gap              = std::numeric_limits<double>::infinity();
            pass.slaves[s].in_contact       = false;
            pass.slaves[s].normal_force     = 0;
            pass.slaves[s].tangential_force = Tensor<1, dim>();
            pass.slaves[s].face             = -1;
            continue;
          }
        const unsigned int  n_faces = found[next + 1];
        const unsigned int *list    = &found[next + 2];
        next += 2 + n_faces;
        pass.candidate_slaves.push_back(s);
        active[pass.slave_node[s]] = true;
        if (!was_candidate[s])
          pass.slaves[s].x_previous = x;
        for (const unsigned int f : ArrayView<const unsigned int>(list, n_faces))
          {
            pass.face_lists.push_back(f);
            if (!face_used[f])
              {
                face_used[f] = true;
                for (unsigned int v = 0; v < 4; ++v)
                  active[pass.faces[f].node[v]] = true;
              }
          }
        pass.face_offsets.push_back(pass.face_lists.size());
      }
    pass.candidate_faces.clear();
    for (unsigned int f = 0; f < pass.faces.size(); ++f)
      if (face_used[f])
        pass.candidate_faces.push_back(f);
    // friction memory on a face that left the candidates is lost
    for (auto &s : pass.slaves)
      if (s.face >= 0 && !face_used[s.face])
        {
          s.face             = -1;
          s.tangential_force = Tensor<1, dim>();
        }
  }
} // namespace WheelRail
