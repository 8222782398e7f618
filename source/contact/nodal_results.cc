#include <wheelrail/contact/bilinear_face.h>
#include <wheelrail/contact/penalty_contact.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace WheelRail
{
  namespace
  {
    /** Add the state of a slave in contact to @p node with weight @p w; the
     *  force is added by the caller (its sign depends on the pass). */
    void
    add_state(const ContactNodeState &slave,
              const double            w,
              const double            eps_t,
              const double            rate_sign,
              NodalContact           &node)
    {
      node.weight += w;
      node.slip_velocity += w * slave.slip_velocity;
      node.slip_rate += (w * rate_sign) * slave.slip_rate;
      node.cof += w * slave.cof;
      if (slave.cof * slave.normal_force - slave.tangential_force.norm() > eps_t)
        node.adhesion_share += w;
      if (slave.slip_velocity > NodalContact::slip_velocity_threshold)
        node.slip_share += w;
    }

    void
    normalise(NodalContact &node)
    {
      if (node.weight > 0)
        {
          node.slip_velocity /= node.weight;
          node.slip_rate /= node.weight;
          node.cof /= node.weight;
          node.adhesion_share /= node.weight;
          node.slip_share /= node.weight;
        }
    }

    /** N_j of the contact point of @p state (lexicographic corners). */
    void
    contact_shape(const ContactNodeState &state, double N[4])
    {
      N[0] = 0.25 * (1 - state.xi) * (1 - state.eta);
      N[1] = 0.25 * (1 + state.xi) * (1 - state.eta);
      N[2] = 0.25 * (1 - state.xi) * (1 + state.eta);
      N[3] = 0.25 * (1 + state.xi) * (1 + state.eta);
    }
  } // namespace



  double
  PenaltyContact::adhesion_tolerance(const unsigned int p) const
  {
    double max_ft = 0;
    for (const auto &s : passes[p].slaves)
      max_ft = std::max(max_ft, s.tangential_force.norm());
    return NodalContact::adhesion_tolerance_fraction * max_ft;
  }



  double
  PenaltyContact::patch_centre() const
  {
    // the candidates (in ascending slave order): a slave that is not one
    // is not in contact (search())
    double fn = 0, fx = 0;
    for (unsigned int p = 0; p < passes.size(); ++p)
      for (const unsigned int c : passes[p].candidate_slaves)
        {
          const ContactNodeState &s = passes[p].slaves[c];
          if (s.in_contact)
            {
              fn += s.normal_force;
              fx += s.normal_force * s.x[0];
            }
        }
    return fn > 0 ? fx / fn : std::numeric_limits<double>::quiet_NaN();
  }



  std::vector<NodalContact>
  PenaltyContact::slave_node_results() const
  {
    const Pass               &first = passes.front();
    std::vector<NodalContact> result(first.slaves.size());
    const double              eps_t = adhesion_tolerance(0);
    for (unsigned int s = 0; s < first.slaves.size(); ++s)
      {
        const ContactNodeState &state = first.slaves[s];
        NodalContact           &node  = result[s];
        node.X                        = state.X;
        node.x                        = state.x;
        node.area                     = state.area;
        if (state.in_contact)
          {
            node.normal_force     = state.normal_force;
            node.tangential_force = state.tangential_force;
            add_state(state, 1., eps_t, 1., node);
          }
      }
    if (passes.size() > 1)
      {
        // the second pass's slaves (rail nodes) push on the faces of the
        // first pass's slave body: their reactions, shared with N_j
        std::vector<int> slave_of_node(node_dof.size(), -1);
        for (unsigned int s = 0; s < first.slave_node.size(); ++s)
          slave_of_node[first.slave_node[s]] = s;
        const Pass  &second = passes[1];
        const double eps_2  = adhesion_tolerance(1);
        for (const unsigned int c : second.candidate_slaves)
          {
            const ContactNodeState &state = second.slaves[c];
            if (!state.in_contact)
              continue;
            double N[4];
            contact_shape(state, N);
            for (unsigned int v = 0; v < 4; ++v)
              {
                const int s = slave_of_node[second.faces[state.face].node[v]];
                if (s < 0)
                  continue;
                NodalContact &node = result[s];
                node.normal_force += N[v] * state.normal_force;
                node.tangential_force -= N[v] * state.tangential_force;
                add_state(state, N[v], eps_2, -1., node);
              }
          }
      }
    for (NodalContact &node : result)
      normalise(node);
    return result;
  }



  std::vector<NodalContact>
  PenaltyContact::master_node_results() const
  {
    const Pass               &first = passes.front();
    std::vector<NodalContact> nodes(node_dof.size());
    const double              eps_t = adhesion_tolerance(0);
    for (const unsigned int s : first.candidate_slaves)
      {
        const ContactNodeState &state = first.slaves[s];
        if (!state.in_contact)
          continue;
        double N[4];
        contact_shape(state, N);
        for (unsigned int v = 0; v < 4; ++v)
          {
            NodalContact &node = nodes[first.faces[state.face].node[v]];
            node.normal_force += N[v] * state.normal_force;
            node.tangential_force += N[v] * state.tangential_force;
            add_state(state, N[v], eps_t, 1., node);
          }
      }
    if (passes.size() > 1)
      {
        // the master nodes are the second pass's slaves: their own forces
        // (on the rail; reversed onto the wheel) and states
        const Pass  &second = passes[1];
        const double eps_2  = adhesion_tolerance(1);
        for (const unsigned int c : second.candidate_slaves)
          {
            const ContactNodeState &state = second.slaves[c];
            if (!state.in_contact)
              continue;
            NodalContact &node = nodes[second.slave_node[c]];
            node.normal_force += state.normal_force;
            node.tangential_force -= state.tangential_force;
            add_state(state, 1., eps_2, -1., node);
          }
      }
    std::vector<NodalContact> result;
    for (const unsigned int n : master_order())
      {
        NodalContact node = nodes[n];
        node.X            = node_X[n];
        node.x            = node_X[n];
        node.area         = node_area[n];
        normalise(node);
        result.push_back(node);
      }
    return result;
  }



  std::vector<unsigned int>
  PenaltyContact::master_order() const
  {
    std::vector<bool> is_master(node_dof.size(), false);
    for (const auto &face : passes.front().faces)
      for (unsigned int v = 0; v < 4; ++v)
        is_master[face.node[v]] = true;
    std::vector<unsigned int> order;
    for (unsigned int n = 0; n < node_dof.size(); ++n)
      if (is_master[n])
        order.push_back(n);
    std::sort(order.begin(), order.end(), [this](const unsigned int a, const unsigned int b) {
      return ContactGeometry::lexicographic_less(node_X[a], node_X[b]);
    });
    return order;
  }



  std::vector<std::array<unsigned int, 4>>
  PenaltyContact::master_face_nodes() const
  {
    const std::vector<unsigned int> order = master_order();
    std::vector<unsigned int>       position(node_dof.size(), numbers::invalid_unsigned_int);
    for (unsigned int i = 0; i < order.size(); ++i)
      position[order[i]] = i;
    std::vector<std::array<unsigned int, 4>> faces;
    for (const auto &face : passes.front().faces)
      faces.push_back({{position[face.node[0]],
                        position[face.node[1]],
                        position[face.node[2]],
                        position[face.node[3]]}});
    return faces;
  }



  std::vector<std::array<unsigned int, 4>>
  PenaltyContact::candidate_slave_faces() const
  {
    const Pass       &first = passes.front();
    std::vector<bool> candidate(first.slaves.size(), false);
    for (const unsigned int c : first.candidate_slaves)
      candidate[c] = true;
    std::vector<std::array<unsigned int, 4>> faces;
    for (const auto &face : first.slave_faces)
      if (candidate[face[0]] && candidate[face[1]] && candidate[face[2]] && candidate[face[3]])
        faces.push_back(face);
    return faces;
  }
} // namespace WheelRail
