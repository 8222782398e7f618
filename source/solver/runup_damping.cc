#include <deal.II/base/mpi.h>

#include <wheelrail/mesh/geometry.h>
#include <wheelrail/solver/explicit_solver.h>

#include <array>

namespace WheelRail
{
  // Wheelset/Run-up damping: a mass-proportional damping of the wheel's
  // velocity relative to the rigid motion of the wheelset, in one of two
  // shapes (Run-up damping shape):
  //
  // - nodes: every node's own relative velocity, f_i = alpha m_i (v_i - v_rigid,i)
  //   (rail nodes: relative to rest). It damps every vibration, but also the
  //   rolling deformation convected through the patch.
  // - wheel rigid motion: only the part of the wheel's relative velocity
  //   that is a rigid motion in the rolling plane (x and z translation,
  //   rotation about y) measured against the steady motion: with V_c the
  //   velocity of the wheel's centre of mass r_c and Omega = L_c / J_c its
  //   mean angular velocity about it (the mass-weighted rigid fit),
  //   w = (V_c - V_a) + (Omega - omega) e_y x (r - r_c) and
  //   f_i = alpha m_i w(r_i). This is the wheel's motion on its web
  //   relative to the axle (the torsional mode that the onset of traction
  //   excites, and the rim's swaying in x and z). A steadily rolling wheel
  //   has V_c = V_a, and Omega = omega up to terms of the order of the
  //   deformation squared (the convected deformation's angular momentum
  //   cancels to first order over the circumference), so the damping may
  //   act while the patch is sampled. (A fit about the axle would not
  //   vanish: the loaded wheel's centre of mass is off the axle by r_c,
  //   and its rigid velocity there is V_a - omega e_y x r_c.)
  //
  // f has the sign of internal forces. The damping's work on the rigid
  // motion, -sum f . v_rigid, is exchanged with the frame that moves with
  // the wheelset (external work), the rest, sum f . (v - v_rigid), is
  // dissipated.
  double
  ExplicitSolver::add_runup_damping(const double h, double &work)
  {
    const double          alpha = prm.wheelset.runup_damping;
    const Point<dim>      axle  = wheelset->axle_position();
    const Tensor<1, dim> &Va    = wheelset->axle_velocity();
    const double          omega = wheelset->angular_velocity();
    const double         *U     = u.begin();
    const double         *V     = v.begin();
    const double         *M     = mass.begin();
    double               *F     = f.begin();
    const unsigned int    n     = u.locally_owned_size();
    const bool            rigid = prm.wheelset.runup_damping_shape == "wheel rigid motion";

    // the node's position relative to the axle (x, z) and its rigid velocity
    // V_a + omega e_y x r in the DoF's direction (a node's x, y, z DoFs are
    // contiguous); 0 on the rail
    const auto rigid_velocity = [&](const unsigned int k, double &rx, double &rz) {
      const unsigned int first = k - node_component[k];
      rx                       = node_points[k][0] + U[first] - axle[0];
      rz                       = node_points[k][2] + U[first + 2] - axle[2];
      if (node_component[k] == 0)
        return Va[0] + omega * rz;
      if (node_component[k] == 2)
        return Va[2] - omega * rx;
      return 0.;
    };

    // the damping force on DoF k, alpha m (damped velocity w), with its
    // power on the motion relative to the rigid one (velocity vr) and on
    // the rigid motion
    double     power = 0, rigid_power = 0;
    const auto damp = [&](const unsigned int k, const double vr, const double w) {
      const double fd = alpha * M[k] * w;
      F[k] += fd;
      power += fd * (V[k] - vr);
      rigid_power -= fd * vr;
    };
    if (rigid)
      {
        // the wheel's mass, centre of mass (relative to the axle), momentum,
        // angular momentum and polar moment in the rolling plane, summed
        // over the ranks; the damped velocity is
        // w = (V_c - V_a) + (Omega - omega) e_y x (r - r_c). Over the wheel's
        // nodes (runup_nodes: the x DoF, z two further), x then z, in DoF
        // order as a loop over all DoFs would sum them.
        // mass (x DoFs), mass (z DoFs), sum m rz, sum m rx, sum m r^2,
        // P_x, P_z, L_y = sum m (rz v_x - rx v_z)
        std::array<double, 8> s = {{0, 0, 0, 0, 0, 0, 0, 0}};
        for (const RunupNode &node : runup_nodes)
          {
            const unsigned int kx = node.dof, kz = kx + 2;
            const double       rx = node.x + U[kx] - axle[0];
            const double       rz = node.z + U[kz] - axle[2];
            s[0] += M[kx];
            s[2] += M[kx] * rz;
            s[4] += M[kx] * rz * rz;
            s[5] += M[kx] * V[kx];
            s[7] += M[kx] * rz * V[kx];
            s[1] += M[kz];
            s[3] += M[kz] * rx;
            s[4] += M[kz] * rx * rx;
            s[6] += M[kz] * V[kz];
            s[7] -= M[kz] * rx * V[kz];
          }
        std::array<double, 8> g;
        Utilities::MPI::sum(ArrayView<const double>(s.data(), 8),
                            mpi_communicator,
                            ArrayView<double>(g.data(), 8));
        double Vcx = 0, Vcz = 0, rcx = 0, rcz = 0, dOmega = 0;
        if (g[0] > 0 && g[1] > 0)
          {
            rcz = g[2] / g[0];
            rcx = g[3] / g[1];
            Vcx = g[5] / g[0];
            Vcz = g[6] / g[1];
            // about the centre of mass
            const double J = g[4] - g[2] * rcz - g[3] * rcx;
            const double L = g[7] - (g[2] * Vcx - g[3] * Vcz);
            if (J > 0)
              dOmega = L / J - omega;
          }
        // the reference motion: the centre of mass with the axle, rotation
        // omega about it
        for (const RunupNode &node : runup_nodes)
          {
            const unsigned int kx = node.dof, kz = kx + 2;
            const double       rx = node.x + U[kx] - axle[0];
            const double       rz = node.z + U[kz] - axle[2];
            damp(kx, Va[0] + omega * (rz - rcz), Vcx - Va[0] + dOmega * (rz - rcz));
            damp(kz, Va[2] - omega * (rx - rcx), Vcz - Va[2] - dOmega * (rx - rcx));
          }
        work = h * rigid_power;
        return power;
      }

    for (unsigned int k = 0; k < n; ++k)
      {
        const bool   wheel = node_material[k] == Geometry::MaterialIds::wheel;
        double       rx, rz;
        const double vr = wheel ? rigid_velocity(k, rx, rz) : 0.;
        damp(k, vr, V[k] - vr);
      }
    work = h * rigid_power;
    return power;
  }
} // namespace WheelRail
