#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <wheelrail/contact.h>
#include <wheelrail/stopwatch.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace WheelRail
{
  std::unique_ptr<FrictionLaw>
  FrictionLaw::create(const std::string &name,
                      const double       static_coefficient,
                      const double       dynamic_coefficient,
                      const double       decay)
  {
    if (name == "constant")
      return std::make_unique<ConstantFriction>(static_coefficient);
    if (name == "exponential")
      return std::make_unique<ExponentialFriction>(static_coefficient, dynamic_coefficient, decay);
    AssertThrow(false, ExcMessage("Unknown friction law '" + name + "' (known: " + names() + ")."));
    return nullptr;
  }



  namespace
  {
    namespace bg     = boost::geometry;
    namespace bgi    = boost::geometry::index;
    using BoostPoint = bg::model::point<double, 3, bg::cs::cartesian>;
    using BoostBox   = bg::model::box<BoostPoint>;

    bool
    lexicographic_less(const Point<dim> &a, const Point<dim> &b)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    }

    /** Bilinear face x(xi, eta) on corners p[0..3] (lexicographic). */
    struct BilinearFace
    {
      const Point<dim> *p[4];

      void
      evaluate(const double    xi,
               const double    eta,
               Point<dim>     &x,
               Tensor<1, dim> &dxi,
               Tensor<1, dim> &deta,
               double          N[4]) const
      {
        shape(xi, eta, N);
        x = Point<dim>();
        for (unsigned int j = 0; j < 4; ++j)
          x += N[j] * (*p[j]);
        dxi  = 0.25 * ((1 - eta) * (*p[1] - *p[0]) + (1 + eta) * (*p[3] - *p[2]));
        deta = 0.25 * ((1 - xi) * (*p[2] - *p[0]) + (1 + xi) * (*p[3] - *p[1]));
      }

      /** The tangents x_xi, x_eta at corner v, as evaluate() gives them
       *  there (bit for bit: the other edge's weight is exactly 0). */
      void
      corner_tangents(const unsigned int v, Tensor<1, dim> &dxi, Tensor<1, dim> &deta) const
      {
        dxi  = (v & 2) ? 0.5 * (*p[3] - *p[2]) : 0.5 * (*p[1] - *p[0]);
        deta = (v & 1) ? 0.5 * (*p[3] - *p[1]) : 0.5 * (*p[2] - *p[0]);
      }

      /** Shape functions at (xi, eta), as evaluate() gives them. */
      static void
      shape(const double xi, const double eta, double N[4])
      {
        N[0] = 0.25 * (1 - xi) * (1 - eta);
        N[1] = 0.25 * (1 + xi) * (1 - eta);
        N[2] = 0.25 * (1 - xi) * (1 + eta);
        N[3] = 0.25 * (1 + xi) * (1 + eta);
      }

      /**
       * For a projection (xi, eta) outside the face: the closest point on
       * the face's boundary. The edges of a bilinear face are straight, so
       * this is the closest point on a segment; two faces sharing the edge
       * give the same point (clamping the coordinates does not, and the
       * difference showed up as micro-slip of 1-2 m/s at nodes rolling along
       * a mesh line).
       */
      void
      project_to_boundary(const Point<dim> &xs, double &xi, double &eta) const
      {
        // edges as (corner a, corner b, fixed coordinate, value)
        const unsigned int edges[4][2] = {{0, 2}, {1, 3}, {0, 1}, {2, 3}};
        double             best        = std::numeric_limits<double>::max();
        double             bx = 0, be = 0;
        for (unsigned int e = 0; e < 4; ++e)
          {
            const Point<dim>    &a = *p[edges[e][0]], &b = *p[edges[e][1]];
            const Tensor<1, dim> ab = b - a;
            const double         t  = std::clamp(((xs - a) * ab) / ab.norm_square(), 0., 1.);
            const double         d2 = (a + t * ab).distance_square(xs);
            if (d2 < best)
              {
                best = d2;
                // xi = -1 edge (0-2), xi = 1 edge (1-3): t runs along eta;
                // eta = -1 edge (0-1), eta = 1 edge (2-3): t runs along xi
                if (e < 2)
                  {
                    bx = (e == 0) ? -1. : 1.;
                    be = 2. * t - 1.;
                  }
                else
                  {
                    bx = 2. * t - 1.;
                    be = (e == 2) ? -1. : 1.;
                  }
              }
          }
        xi  = bx;
        eta = be;
      }

      /** Closest point by Newton (Gauss-Newton) in the face coordinates. */
      void
      project(const Point<dim> &xs, double &xi, double &eta) const
      {
        xi = eta = 0;
        Point<dim>     x;
        Tensor<1, dim> dxi, deta;
        double         N[4];
        bool           was_clamped = false;
        for (unsigned int it = 0; it < 20; ++it)
          {
            evaluate(xi, eta, x, dxi, deta, N);
            const Tensor<1, dim> r   = x - xs;
            const double         a11 = dxi * dxi, a12 = dxi * deta, a22 = deta * deta;
            const double         b1 = dxi * r, b2 = deta * r;
            const double         det = a11 * a22 - a12 * a12;
            if (!(det > 0))
              break;
            const double dx      = -(a22 * b1 - a12 * b2) / det;
            const double de      = -(a11 * b2 - a12 * b1) / det;
            const bool   clamped = std::abs(xi + dx) > 3. || std::abs(eta + de) > 3.;
            xi                   = std::clamp(xi + dx, -3., 3.);
            eta                  = std::clamp(eta + de, -3., 3.);
            if (std::abs(dx) + std::abs(de) < 1e-13)
              break;
            // the closest point lies far outside the face (beyond the
            // clamp twice in a row): the callers only use projections
            // within 1.1, and iterating on (the clamp stops Newton from
            // converging) would take all 20 iterations
            if (clamped && was_clamped)
              break;
            was_clamped = clamped;
          }
      }
    };
  } // namespace



  PenaltyContact::PenaltyContact(const ContactParameters  &contact,
                                 const MaterialParameters &material,
                                 MPI_Comm                  comm)
    : prm(contact)
    , mpi_communicator(comm)
    , bulk_modulus(material.lambda() + 2. / 3. * material.mu())
  {
    if (prm.friction_law != "none")
      law = FrictionLaw::create(prm.friction_law,
                                prm.static_coefficient,
                                prm.dynamic_coefficient,
                                prm.decay);
  }



  unsigned int
  PenaltyContact::node_index(const types::global_dof_index dof, const Point<dim> &X)
  {
    const auto it =
      std::lower_bound(dof_to_node.begin(),
                       dof_to_node.end(),
                       std::make_pair(dof, 0u),
                       [](const auto &a, const auto &b) { return a.first < b.first; });
    if (it != dof_to_node.end() && it->first == dof)
      return it->second;
    const unsigned int index = node_dof.size();
    node_dof.push_back(dof);
    node_X.push_back(X);
    dof_to_node.insert(it, std::make_pair(dof, index));
    return index;
  }



  void
  PenaltyContact::collect_pass(const DoFHandler<dim>   &dof_handler,
                               const types::boundary_id slave_id,
                               const types::boundary_id master_id,
                               Pass                    &pass)
  {
    // local contributions, packed as doubles for one all_gather each:
    // slaves (dof, X, partial area), faces (4 dofs, 4 X, k, sign)
    std::vector<double> slaves, faces;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto   face = cell->face(f);
              const double area = 0.5 * cross_product_3d(face->vertex(3) - face->vertex(0),
                                                         face->vertex(2) - face->vertex(1))
                                          .norm();
              if (face->boundary_id() == slave_id)
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    slaves.push_back(face->vertex_dof_index(v, 0));
                    for (unsigned int d = 0; d < dim; ++d)
                      slaves.push_back(face->vertex(v)[d]);
                    slaves.push_back(0.25 * area);
                  }
              if (face->boundary_id() == master_id)
                {
                  for (unsigned int v = 0; v < 4; ++v)
                    {
                      faces.push_back(face->vertex_dof_index(v, 0));
                      for (unsigned int d = 0; d < dim; ++d)
                        faces.push_back(face->vertex(v)[d]);
                    }
                  const Tensor<1, dim> n = cross_product_3d(face->vertex(1) - face->vertex(0),
                                                            face->vertex(2) - face->vertex(0));
                  faces.push_back(area);
                  faces.push_back(cell->measure());
                  faces.push_back(n * (face->center() - cell->center()) > 0 ? 1. : -1.);
                }
            }

    // slaves: sum the partial areas of shared nodes, order by position
    std::map<types::global_dof_index, std::pair<Point<dim>, double>> slave_map;
    for (const auto &part : Utilities::MPI::all_gather(mpi_communicator, slaves))
      for (unsigned int i = 0; i < part.size(); i += 5)
        {
          auto &entry = slave_map[static_cast<types::global_dof_index>(part[i])];
          entry.first = Point<dim>(part[i + 1], part[i + 2], part[i + 3]);
          entry.second += part[i + 4];
        }
    std::vector<std::tuple<Point<dim>, types::global_dof_index, double>> sorted_slaves;
    for (const auto &s : slave_map)
      sorted_slaves.emplace_back(s.second.first, s.first, s.second.second);
    std::sort(sorted_slaves.begin(), sorted_slaves.end(), [](const auto &a, const auto &b) {
      return lexicographic_less(std::get<0>(a), std::get<0>(b));
    });
    for (const auto &s : sorted_slaves)
      {
        ContactNodeState state;
        state.X    = std::get<0>(s);
        state.x    = state.X;
        state.area = std::get<2>(s);
        pass.slave_node.push_back(node_index(std::get<1>(s), state.X));
        pass.slaves.push_back(state);
      }

    // faces, ordered by centroid
    std::vector<std::pair<Point<dim>, std::vector<double>>> sorted_faces;
    double thinnest = std::numeric_limits<double>::max(); // smallest V / A
    for (const auto &part : Utilities::MPI::all_gather(mpi_communicator, faces))
      for (unsigned int i = 0; i < part.size(); i += 19)
        {
          Point<dim> c;
          for (unsigned int v = 0; v < 4; ++v)
            c += 0.25 * Point<dim>(part[i + 4 * v + 1], part[i + 4 * v + 2], part[i + 4 * v + 3]);
          sorted_faces.emplace_back(c,
                                    std::vector<double>(part.begin() + i, part.begin() + i + 19));
          thinnest = std::min(thinnest, part[i + 17] / part[i + 16]);
        }
    // penalty stiffness per face (SPEC 4; Contact/Penalty stiffness)
    if (prm.penalty_stiffness == "area" && &pass == &passes.front())
      reference_length = prm.penalty_reference_length > 0 ? prm.penalty_reference_length : thinnest;
    const auto stiffness = [&](const double area, const double volume) {
      return prm.penalty_stiffness == "area" ?
               prm.penalty_scale * bulk_modulus * area / reference_length :
               prm.penalty_scale * bulk_modulus * area * area / volume;
    };
    std::sort(sorted_faces.begin(), sorted_faces.end(), [](const auto &a, const auto &b) {
      return lexicographic_less(a.first, b.first);
    });
    for (const auto &f : sorted_faces)
      {
        MasterFace face;
        for (unsigned int v = 0; v < 4; ++v)
          face.node[v] =
            node_index(static_cast<types::global_dof_index>(f.second[4 * v]),
                       Point<dim>(f.second[4 * v + 1], f.second[4 * v + 2], f.second[4 * v + 3]));
        face.stiffness = stiffness(f.second[16], f.second[17]);
        face.sign      = f.second[18];
        pass.faces.push_back(face);
        if (&pass == &passes.front())
          {
            node_area.resize(node_dof.size(), 0.);
            const Point<dim> &p0 = node_X[face.node[0]], &p1 = node_X[face.node[1]],
                             &p2 = node_X[face.node[2]], &p3 = node_X[face.node[3]];
            const double area = 0.5 * cross_product_3d(p3 - p0, p2 - p1).norm();
            for (unsigned int v = 0; v < 4; ++v)
              node_area[face.node[v]] += 0.25 * area;
          }
      }
  }



  void
  PenaltyContact::setup(
    const DoFHandler<dim>                                    &dof_handler,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &vector_partitioner,
    const LinearAlgebra::distributed::Vector<double>         &lumped_mass)
  {
    partitioner = vector_partitioner;
    node_dof.clear();
    node_X.clear();
    dof_to_node.clear();
    passes.clear();
    passes.resize(prm.two_pass ? 2 : 1);
    collect_pass(dof_handler, prm.slave_boundary, prm.master_boundary, passes[0]);
    if (prm.two_pass)
      collect_pass(dof_handler, prm.master_boundary, prm.slave_boundary, passes[1]);
    AssertThrow(!passes[0].slaves.empty(),
                ExcMessage("Contact/Slave boundary " + std::to_string(prm.slave_boundary) +
                           " has no faces in this geometry."));
    AssertThrow(!passes[0].faces.empty(),
                ExcMessage("Contact/Master boundary " + std::to_string(prm.master_boundary) +
                           " has no faces in this geometry."));
    // nodal masses of the slaves (for contact damping), replicated
    std::vector<double> owned_mass(node_dof.size(), 0.), mass(node_dof.size(), 0.);
    for (unsigned int n = 0; n < node_dof.size(); ++n)
      if (partitioner->in_local_range(node_dof[n]))
        owned_mass[n] = lumped_mass.local_element(partitioner->global_to_local(node_dof[n]));
    Utilities::MPI::sum(owned_mass, mpi_communicator, mass);
    for (Pass &pass : passes)
      for (unsigned int s = 0; s < pass.slaves.size(); ++s)
        {
          pass.slaves[s].mass       = mass[pass.slave_node[s]];
          pass.slaves[s].x_previous = pass.slaves[s].X;
        }
    node_area.resize(node_dof.size(), 0.);
    for (Pass &pass : passes)
      pass.bounds.assign(pass.faces.size(), FaceBound());
    node_normal.assign(node_dof.size(), Tensor<1, dim>());
    normal_evaluation.assign(node_dof.size(), 0);
    normal_offsets.assign(node_dof.size() + 1, 0);
    normal_entries.clear();
    evaluation    = 0;
    node_x        = node_X;
    node_x_search = node_X;
    std::vector<unsigned int> all(node_dof.size());
    for (unsigned int n = 0; n < all.size(); ++n)
      all[n] = n;
    plan_gather(all, all_gather);
    active_nodes.clear();
    plan_gather(active_nodes, active_gather);
    need_search  = true;
    dissipation  = 0;
    damping_loss = 0;
    searches     = 0;
    search_time  = 0;
    trigger_nodes.clear();
    step_motion_known = false;
    overlap_checked   = false;
    approach_searches = 0;
    new_contact_depth = 0;
  }



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

    const double      margin = prm.search_margin;
    std::vector<bool> active(node_dof.size(), false);
    for (Pass &pass : passes)
      {
        // rtree of the master faces' boxes grown by the margin
        std::vector<std::pair<BoostBox, unsigned int>> boxes;
        for (unsigned int f = 0; f < pass.faces.size(); ++f)
          {
            const auto [lo, hi] = face_box(pass.faces[f], node_x);
            boxes.emplace_back(BoostBox(BoostPoint(lo[0] - margin, lo[1] - margin, lo[2] - margin),
                                        BoostPoint(hi[0] + margin, hi[1] + margin, hi[2] + margin)),
                               f);
          }
        const bgi::rtree<std::pair<BoostBox, unsigned int>, bgi::quadratic<16>> tree(boxes);

        std::vector<bool> was_candidate(pass.slaves.size(), false);
        for (const unsigned int s : pass.candidate_slaves)
          was_candidate[s] = true;
        pass.candidate_slaves.clear();
        pass.face_offsets.assign(1, 0);
        pass.face_lists.clear();
        std::vector<bool> face_used(pass.faces.size(), false);

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

        std::size_t next = 0; // the next packed slave in found
        for (unsigned int s = 0; s < pass.slaves.size(); ++s)
          {
            const Point<dim> &x = node_x[pass.slave_node[s]];
            if (next >= found.size() || found[next] != s)
              {
                // out of reach: no contact and no friction memory
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



  const PenaltyContact::FaceBound &
  PenaltyContact::face_bound(Pass &pass, const unsigned int f)
  {
    FaceBound &bound = pass.bounds[f];
    if (bound.evaluation == evaluation)
      return bound;
    bound.evaluation = evaluation;
    // compute_slaves() uses a face's projection only if it lies within
    // |xi|, |eta| <= 1.1. A converged projection x_k of x_s is a point of
    // the face extended to 1.1, so |x_k - c| <= R (the extended face lies
    // in the convex hull of its corners x(+-1.1, +-1.1)), and x_s - x_k is
    // normal to the face there: x_s = x_k + t n, |t| <= |x_s - c| + R. The
    // normal x_xi x x_eta is affine in (xi, eta), a combination with
    // non-negative weights of its values at the extended corners, so it
    // lies within their largest angle a from the centre normal n_c. The
    // distance of x_s from the axis (c, n_c) is then at most
    // R + (|x_s - c| + R) sin a; a slave farther out cannot project within
    // 1.1. Faces that are not nearly flat (sin a > 0.1) are not bounded:
    // their projection is always computed. In closed form,
    // x = c + xi g1 + eta g2 + xi eta w and x_xi x x_eta = n0 + xi (g1 x w)
    // + eta (w x g2).
    constexpr double  e    = 1.1; // the extension
    const MasterFace &face = pass.faces[f];
    const Point<dim> &p0 = node_x[face.node[0]], &p1 = node_x[face.node[1]],
                     &p2 = node_x[face.node[2]], &p3 = node_x[face.node[3]];
    const Tensor<1, dim> g1     = 0.25 * ((p1 - p0) + (p3 - p2));
    const Tensor<1, dim> g2     = 0.25 * ((p2 - p0) + (p3 - p1));
    const Tensor<1, dim> w      = 0.25 * ((p0 - p1) + (p3 - p2));
    bound.centre                = Point<dim>(0.25 * (p0 + p1 + p2 + p3));
    const Tensor<1, dim> n0     = cross_product_3d(g1, g2);
    const double         length = n0.norm();
    bound.usable                = length > 0;
    if (!bound.usable)
      return bound;
    bound.normal = n0 / length;
    // the normal's change across the face, and its part across n0
    const Tensor<1, dim> a = cross_product_3d(g1, w), b = cross_product_3d(w, g2);
    const Tensor<1, dim> at = cross_product_3d(a, bound.normal),
                         bt = cross_product_3d(b, bound.normal);
    const double an = a * bound.normal, bn = b * bound.normal;
    bound.radius    = 0;
    bound.sin_angle = 0;
    for (unsigned int v = 0; v < 4; ++v)
      {
        const double xi = (v & 1) ? e : -e, eta = (v & 2) ? e : -e;
        bound.radius       = std::max(bound.radius, (xi * g1 + eta * g2 + xi * eta * w).norm());
        const double along = length + xi * an + eta * bn; // m . n0 / |n0|
        if (!(along > 0))
          {
            bound.usable = false;
            return bound;
          }
        const double across = (xi * at + eta * bt).norm(); // |m x n0| / |n0|
        bound.sin_angle =
          std::max(bound.sin_angle, across / std::sqrt(along * along + across * across));
      }
    bound.usable = bound.sin_angle <= 0.1;
    return bound;
  }



  const Tensor<1, dim> &
  PenaltyContact::averaged_normal(const unsigned int n)
  {
    // Averaged nodal normals of the candidate master faces: the normal is
    // interpolated from them over a face, so that it, and the contact force,
    // are continuous when a slave passes from one face to its neighbour
    // (with face normals the force direction jumps at every edge). Summed
    // over the faces in ascending order, as one loop over all candidate
    // faces would: the same bits on every rank, whichever node it needs.
    Tensor<1, dim> &normal = node_normal[n];
    if (normal_evaluation[n] == evaluation)
      return normal;
    normal_evaluation[n] = evaluation;
    normal               = Tensor<1, dim>();
    for (unsigned int e = normal_offsets[n]; e < normal_offsets[n + 1]; ++e)
      {
        const NormalEntry &entry = normal_entries[e];
        const MasterFace  &face  = passes[entry.pass].faces[entry.face];
        BilinearFace       bf{{&node_x[face.node[0]],
                               &node_x[face.node[1]],
                               &node_x[face.node[2]],
                               &node_x[face.node[3]]}};
        Tensor<1, dim>     dxi, deta;
        bf.corner_tangents(entry.corner, dxi, deta);
        normal += face.sign * cross_product_3d(dxi, deta);
      }
    if (normal.norm() > 0)
      normal /= normal.norm();
    return normal;
  }



  void
  PenaltyContact::build_normal_adjacency()
  {
    normal_offsets.assign(node_dof.size() + 1, 0);
    for (const Pass &pass : passes)
      for (const unsigned int f : pass.candidate_faces)
        for (unsigned int v = 0; v < 4; ++v)
          ++normal_offsets[pass.faces[f].node[v] + 1];
    for (unsigned int n = 0; n < node_dof.size(); ++n)
      normal_offsets[n + 1] += normal_offsets[n];
    normal_entries.resize(normal_offsets.back());
    std::vector<unsigned int> next(normal_offsets.begin(), normal_offsets.end() - 1);
    for (unsigned int p = 0; p < passes.size(); ++p)
      for (const unsigned int f : passes[p].candidate_faces)
        for (unsigned int v = 0; v < 4; ++v)
          normal_entries[next[passes[p].faces[f].node[v]]++] = NormalEntry{p, f, v};
  }



  std::pair<unsigned int, unsigned int>
  PenaltyContact::candidate_block(const unsigned int n, const unsigned int rank) const
  {
    const unsigned long n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    return {static_cast<unsigned int>(n * static_cast<unsigned long>(rank) / n_ranks),
            static_cast<unsigned int>(n * (rank + 1ul) / n_ranks)};
  }



  std::pair<unsigned int, unsigned int>
  PenaltyContact::own_candidates(const unsigned int n) const
  {
    return candidate_block(n, Utilities::MPI::this_mpi_process(mpi_communicator));
  }



  std::vector<MasterNodeState>
  PenaltyContact::master_states() const
  {
    const Pass                  &pass = passes.front();
    std::vector<MasterNodeState> states(node_dof.size());
    std::vector<double>          weight(node_dof.size(), 0.);
    std::vector<bool>            is_master(node_dof.size(), false);
    for (const auto &face : pass.faces)
      for (unsigned int v = 0; v < 4; ++v)
        is_master[face.node[v]] = true;
    for (const unsigned int s : pass.candidate_slaves)
      {
        const ContactNodeState &state = pass.slaves[s];
        if (!state.in_contact)
          continue;
        const MasterFace &face = pass.faces[state.face];
        const double      N[4] = {0.25 * (1 - state.xi) * (1 - state.eta),
                                  0.25 * (1 + state.xi) * (1 - state.eta),
                                  0.25 * (1 - state.xi) * (1 + state.eta),
                                  0.25 * (1 + state.xi) * (1 + state.eta)};
        for (unsigned int v = 0; v < 4; ++v)
          {
            MasterNodeState &m = states[face.node[v]];
            m.normal_force += N[v] * state.normal_force;
            m.tangential_force += N[v] * state.tangential_force;
            m.slip_velocity += N[v] * state.slip_velocity;
            m.cof += N[v] * state.cof;
            weight[face.node[v]] += N[v];
          }
      }
    std::vector<MasterNodeState> result;
    for (unsigned int n = 0; n < node_dof.size(); ++n)
      if (is_master[n])
        {
          MasterNodeState m = states[n];
          m.X               = node_X[n];
          m.area            = node_area[n];
          if (weight[n] > 0)
            {
              m.slip_velocity /= weight[n];
              m.cof /= weight[n];
            }
          result.push_back(m);
        }
    std::sort(result.begin(), result.end(), [](const auto &a, const auto &b) {
      return lexicographic_less(a.X, b.X);
    });
    return result;
  }



  void
  PenaltyContact::add_forces(const LinearAlgebra::distributed::Vector<double> &u,
                             const double                                      dt,
                             const bool                                        advance,
                             LinearAlgebra::distributed::Vector<double>       &f)
  {
    Clock::time_point clock = Clock::now();
    // the ranks meet here first after their element loops, in the reduction
    // of the approach bound: what one waits for the other (imbalance, and
    // the noise of single steps) is timed on its own
    const bool approach = approach_bound_exceeded(u, advance, clock);
    if (need_search || steps_since_search >= prm.search_interval || approach)
      {
        if (!need_search && steps_since_search < prm.search_interval)
          ++approach_searches;
        search(u);
        timing.search += lap(clock);
      }
    else
      {
        gather_positions(u, active_gather);
        timing.positions += lap(clock);
      }

    // rebuild at the next step when a candidate moved too far
    const double limit = prm.rebuild_fraction * prm.search_margin;
    for (const unsigned int n : active_nodes)
      if (node_x[n].distance_square(node_x_search[n]) > limit * limit)
        {
          need_search = true;
          break;
        }

    // the averaged nodal normals and the face bounds of this evaluation are
    // computed where compute_slaves() first needs them
    ++evaluation;

    // each rank a block of the candidates (ordered by position: a rank's
    // slaves share faces and nodal normals), then all states everywhere
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    for (Pass &pass : passes)
      {
        compute_slaves(pass, dt, advance);
        timing.slaves += lap(clock);
        if (n_ranks > 1)
          {
            exchange_states(pass, advance);
            timing.exchange += lap(clock);
          }
      }
    pairs.clear();
    totals = ContactSummary();
    for (const Pass &pass : passes)
      accumulate(pass, advance);
    if (totals.n_contact > 0)
      totals.relative_displacement /= totals.n_contact;
    if (!overlap_checked)
      {
        overlap_checked = true;
        check_initial_overlap();
      }

    // forces on the owned DoFs, with the sign of internal forces
    for (const Pass &pass : passes)
      for (const unsigned int s : pass.candidate_slaves)
        {
          const ContactNodeState &state = pass.slaves[s];
          if (!state.in_contact)
            continue;
          const Tensor<1, dim> F   = state.normal_force * state.normal + state.tangential_force;
          const auto           add = [&](const types::global_dof_index dof, const double weight) {
            if (partitioner->in_local_range(dof))
              {
                const unsigned int i = partitioner->global_to_local(dof);
                for (unsigned int d = 0; d < dim; ++d)
                  f.local_element(i + d) -= weight * F[d];
              }
          };
          add(node_dof[pass.slave_node[s]], 1.);
          const MasterFace &face = pass.faces[state.face];
          double            N[4];
          BilinearFace::shape(state.xi, state.eta, N);
          for (unsigned int v = 0; v < 4; ++v)
            add(node_dof[face.node[v]], -N[v]);
        }
    if (advance)
      ++steps_since_search;
    timing.forces += lap(clock);
  }



  void
  PenaltyContact::compute_slaves(Pass &pass, const double dt, const bool advance)
  {
    const double margin = prm.search_margin;
    const auto   own    = own_candidates(pass.candidate_slaves.size());
    for (unsigned int c = own.first; c < own.second; ++c)
      {
        const unsigned int s     = pass.candidate_slaves[c];
        ContactNodeState  &state = pass.slaves[s];
        const Point<dim>  &xs    = node_x[pass.slave_node[s]];
        state.x                  = xs;
        const Point<dim> x_prev  = state.x_previous;
        state.friction_loss      = 0;
        state.damping_work       = 0;
        if (advance)
          state.x_previous = xs;

        // closest point over the candidate faces; a projection inside a
        // face wins, otherwise the nearest face edge takes over
        int            best_face = -1;
        double         best_xi = 0, best_eta = 0, best_gap = 0, best_out = 1e300;
        Tensor<1, dim> best_n;
        for (unsigned int k = pass.face_offsets[c]; k < pass.face_offsets[c + 1]; ++k)
          {
            const FaceBound &bound = face_bound(pass, pass.face_lists[k]);
            if (bound.usable)
              {
                // the projection cannot lie within 1.1 of this face (see
                // face_bound()): project() would give out > 0.1,
                // skipped below; most candidates are neighbours of the
                // face under the slave and end here
                const Tensor<1, dim> d  = xs - bound.centre;
                const double         dd = d.norm_square();
                const double         dn = d * bound.normal;
                const double         reach =
                  1.01 * (bound.radius + (std::sqrt(dd) + bound.radius) * bound.sin_angle);
                if (dd - dn * dn > reach * reach)
                  continue;
              }
            const MasterFace &face = pass.faces[pass.face_lists[k]];
            BilinearFace      bf{{&node_x[face.node[0]],
                                  &node_x[face.node[1]],
                                  &node_x[face.node[2]],
                                  &node_x[face.node[3]]}};
            double            xi, eta;
            bf.project(xs, xi, eta);
            const double out = std::max(std::abs(xi), std::abs(eta)) - 1.;
            if (out > 0.1)
              continue;
            if (out > 0)
              bf.project_to_boundary(xs, xi, eta);
            Point<dim>     x;
            Tensor<1, dim> dxi, deta;
            double         N[4];
            bf.evaluate(xi, eta, x, dxi, deta, N);
            Tensor<1, dim> n;
            for (unsigned int j = 0; j < 4; ++j)
              n += N[j] * averaged_normal(face.node[j]);
            n /= n.norm();
            const double gap = n * (xs - x);
            if (gap < -margin)
              continue;
            const double o      = std::max(out, 0.);
            const bool   better = (o < best_out - 1e-12) ||
                                (o <= best_out + 1e-12 && std::abs(gap) < std::abs(best_gap));
            if (best_face < 0 || better)
              {
                best_face = pass.face_lists[k];
                best_xi   = xi;
                best_eta  = eta;
                best_gap  = gap;
                best_out  = o;
                best_n    = n;
              }
          }

        state.gap = best_face >= 0 ? best_gap : 0.;
        if (best_face < 0 || best_gap >= 0)
          {
            separate(state, xs, state.gap, advance);
            continue;
          }

        const MasterFace &face = pass.faces[best_face];
        const double      k    = face.stiffness;
        if (advance && state.face < 0)
          new_contact_depth = std::max(new_contact_depth, -best_gap);
        state.in_contact   = true;
        state.normal       = best_n;
        state.normal_force = -k * best_gap;
        if (advance && prm.damping_ratio > 0 && state.face >= 0)
          {
            // viscous normal force on the closing rate of the gap; the
            // total stays compressive
            const double c    = 2. * prm.damping_ratio * std::sqrt(k * state.mass);
            const double rate = (best_gap - state.gap_previous) / dt;
            const double fd   = std::max(-c * rate, -state.normal_force);
            state.normal_force += fd;
            state.damping_work = -fd * rate * dt;
          }

        if (law && advance)
          {
            const double kt = prm.tangential_factor * k;
            // slip increment: the contact point now minus the old contact
            // point on the current master geometry
            Tensor<1, dim> de;
            Tensor<1, dim> Ft_old;
            if (state.face < 0)
              {
                // a new contact: the slip of this step is the motion of the
                // slave relative to the face, from its previous position
                // projected onto the same face
                BilinearFace bn{{&node_x[face.node[0]],
                                 &node_x[face.node[1]],
                                 &node_x[face.node[2]],
                                 &node_x[face.node[3]]}};
                double       xi_p, eta_p;
                bn.project(x_prev, xi_p, eta_p);
                Point<dim>     x_old, x_new;
                Tensor<1, dim> dxi, deta;
                double         N[4];
                bn.evaluate(xi_p, eta_p, x_old, dxi, deta, N);
                bn.evaluate(best_xi, best_eta, x_new, dxi, deta, N);
                de = x_new - x_old;
              }
            else
              {
                const MasterFace &old = pass.faces[state.face];
                BilinearFace      bf{{&node_x[old.node[0]],
                                      &node_x[old.node[1]],
                                      &node_x[old.node[2]],
                                      &node_x[old.node[3]]}};
                Point<dim>        x_old, x_new;
                Tensor<1, dim>    dxi, deta;
                double            N[4];
                bf.evaluate(state.xi, state.eta, x_old, dxi, deta, N);
                BilinearFace bn{{&node_x[face.node[0]],
                                 &node_x[face.node[1]],
                                 &node_x[face.node[2]],
                                 &node_x[face.node[3]]}};
                bn.evaluate(best_xi, best_eta, x_new, dxi, deta, N);
                de     = x_new - x_old;
                Ft_old = state.tangential_force;
              }
            Tensor<1, dim> trial = Ft_old - kt * de;
            trial -= (trial * best_n) * best_n;
            state.slip_rate        = de / dt;
            state.slip_velocity    = de.norm() / dt;
            state.cof              = law->coefficient(state.slip_velocity);
            state.tangential_force = return_map(
              trial, state.cof * state.normal_force, kt, state.slipping, state.friction_loss);
          }
        else
          {
            // frictionless, or a static evaluation (no time step to slip in)
            state.tangential_force = Tensor<1, dim>();
            state.slip_velocity    = 0;
            state.slip_rate        = Tensor<1, dim>();
            state.cof              = law ? law->coefficient(0.) : 0.;
            state.slipping         = false;
          }
        state.face         = best_face;
        state.xi           = best_xi;
        state.eta          = best_eta;
        state.gap_previous = best_gap;
      }
  }



  void
  PenaltyContact::separate(ContactNodeState &state,
                           const Point<dim> &xs,
                           const double      gap,
                           const bool        advance)
  {
    state.x             = xs;
    state.friction_loss = 0;
    state.damping_work  = 0;
    if (advance)
      state.x_previous = xs;
    state.gap              = gap;
    state.in_contact       = false;
    state.normal_force     = 0;
    state.tangential_force = Tensor<1, dim>();
    state.slip_velocity    = 0;
    state.slip_rate        = Tensor<1, dim>();
    state.slipping         = false;
    if (advance)
      state.face = -1;
  }



  void
  PenaltyContact::exchange_states(Pass &pass, const bool advance)
  {
    // Rank r computed the block own_candidates() gives it. Most candidates
    // are not in contact, and their state follows from the gap alone
    // (separate(), with the position every rank has): only the states in
    // contact travel whole. First the (contact, gap) pairs of all blocks,
    // then the contact states, whose number per rank the pairs tell.
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    const unsigned int n       = pass.candidate_slaves.size();
    const auto         own     = own_candidates(n);
    std::vector<int>  &counts = exchange_counts, &displs = exchange_displs;
    counts.resize(n_ranks);
    displs.resize(n_ranks);
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        const auto block = candidate_block(n, r);
        counts[r]        = 2 * (block.second - block.first);
        displs[r]        = 2 * block.first;
      }
    exchange_gaps.resize(2 * n);
    exchange_buffer.clear();
    for (unsigned int c = own.first; c < own.second; ++c)
      {
        const ContactNodeState &state = pass.slaves[pass.candidate_slaves[c]];
        exchange_gaps[2 * c]          = state.in_contact ? 1. : 0.;
        exchange_gaps[2 * c + 1]      = state.gap;
      }
    int ierr = MPI_Allgatherv(MPI_IN_PLACE,
                              0,
                              MPI_DATATYPE_NULL,
                              exchange_gaps.data(),
                              counts.data(),
                              displs.data(),
                              MPI_DOUBLE,
                              mpi_communicator);
    AssertThrowMPI(ierr);

    // the contact states, in candidate order
    const int    size  = sizeof(ContactNodeState);
    unsigned int total = 0;
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        const unsigned int first = displs[r] / 2, last = first + counts[r] / 2;
        unsigned int       count = 0;
        for (unsigned int c = first; c < last; ++c)
          count += exchange_gaps[2 * c] > 0;
        counts[r] = count * size;
        displs[r] = total * size;
        total += count;
      }
    exchange_buffer.resize(total);
    for (unsigned int c = own.first,
                      i = displs[Utilities::MPI::this_mpi_process(mpi_communicator)] / size;
         c < own.second;
         ++c)
      if (exchange_gaps[2 * c] > 0)
        exchange_buffer[i++] = pass.slaves[pass.candidate_slaves[c]];
    ierr = MPI_Allgatherv(MPI_IN_PLACE,
                          0,
                          MPI_DATATYPE_NULL,
                          exchange_buffer.data(),
                          counts.data(),
                          displs.data(),
                          MPI_BYTE,
                          mpi_communicator);
    AssertThrowMPI(ierr);
    for (unsigned int c = 0, i = 0; c < n; ++c)
      {
        const bool in_contact = exchange_gaps[2 * c] > 0;
        if (c < own.first || c >= own.second)
          {
            const unsigned int s = pass.candidate_slaves[c];
            if (in_contact)
              pass.slaves[s] = exchange_buffer[i];
            else
              separate(pass.slaves[s],
                       node_x[pass.slave_node[s]],
                       exchange_gaps[2 * c + 1],
                       advance);
          }
        i += in_contact;
      }
  }



  void
  PenaltyContact::accumulate(const Pass &pass, const bool advance)
  {
    for (const unsigned int s : pass.candidate_slaves)
      {
        const ContactNodeState &state = pass.slaves[s];
        damping_loss += state.damping_work;
        dissipation += state.friction_loss;
        if (!state.in_contact)
          continue;
        const MasterFace &face = pass.faces[state.face];
        const double      k    = face.stiffness;
        totals.max_penetration = std::max(totals.max_penetration, -state.gap);
        totals.elastic_energy += 0.5 * k * state.gap * state.gap;
        if (law && advance)
          totals.elastic_energy +=
            0.5 * state.tangential_force.norm_square() / (prm.tangential_factor * k);

        const Tensor<1, dim> F = state.normal_force * state.normal + state.tangential_force;
        // the force on the first pass's slave body: in the second pass the
        // slaves belong to the other body
        totals.force += (&pass == &passes.front()) ? F : -F;
        ++totals.n_contact;
        double N[4];
        BilinearFace::shape(state.xi, state.eta, N);
        {
          Point<dim> X_c, x_c;
          for (unsigned int j = 0; j < 4; ++j)
            {
              X_c += N[j] * node_X[face.node[j]];
              x_c += N[j] * node_x[face.node[j]];
            }
          totals.relative_displacement += (state.x - state.X) - (x_c - X_c);
        }
        if (state.slipping)
          ++totals.n_slip;
        if (law &&
            state.tangential_force.norm() > state.cof * state.normal_force * (1 + 1e-12) + 1e-300)
          ++totals.n_violation;

        ContactPair pair;
        pair.slave = node_dof[pass.slave_node[s]];
        for (unsigned int v = 0; v < 4; ++v)
          {
            pair.master[v] = node_dof[face.node[v]];
            pair.shape[v]  = N[v];
          }
        pair.normal    = state.normal;
        pair.stiffness = k;
        pairs.push_back(pair);
      }
  }



  void
  PenaltyContact::save(Checkpoint::Writer &out) const
  {
    out.vector(node_x);
    out.vector(node_x_search);
    out.vector(active_nodes);
    out.pod<std::uint64_t>(passes.size());
    for (const Pass &pass : passes)
      {
        out.vector(pass.slaves);
        out.vector(pass.candidate_slaves);
        out.vector(pass.candidate_faces);
        out.vector(pass.face_offsets);
        out.vector(pass.face_lists);
      }
    out.pod(totals);
    out.pod(dissipation);
    out.pod(damping_loss);
    out.pod(steps_since_search);
    out.pod(need_search);
    out.pod(searches);
  }



  void
  PenaltyContact::load(Checkpoint::Reader &in)
  {
    in.vector(node_x);
    in.vector(node_x_search);
    in.vector(active_nodes);
    std::uint64_t n_passes = 0;
    in.pod(n_passes);
    AssertThrow(n_passes == passes.size(),
                ExcMessage("The checkpoint does not fit this run (contact passes differ)."));
    for (Pass &pass : passes)
      {
        const std::size_t n_slaves = pass.slaves.size();
        in.vector(pass.slaves);
        AssertThrow(pass.slaves.size() == n_slaves,
                    ExcMessage("The checkpoint does not fit this run (slave nodes differ)."));
        in.vector(pass.candidate_slaves);
        in.vector(pass.candidate_faces);
        in.vector(pass.face_offsets);
        in.vector(pass.face_lists);
      }
    in.pod(totals);
    in.pod(dissipation);
    in.pod(damping_loss);
    in.pod(steps_since_search);
    in.pod(need_search);
    in.pod(searches);
    build_normal_adjacency();
    plan_gather(active_nodes, active_gather);
    plan_approach_trigger();
    // the motion of the last step before the checkpoint is not known here
    step_motion_known = false;
    overlap_checked   = true;
  }
} // namespace WheelRail
