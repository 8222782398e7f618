#include <deal.II/base/mpi.h>

#include <wheelrail/mesh/geometry.h>
#include <wheelrail/solver/wheelset_coupling.h>

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
  WheelsetCoupling::add_damping(const VectorType &u,
                                const VectorType &v,
                                VectorType       &f,
                                const double      h,
                                double           &work)
  {
    DampingSums sums;
    if (shape == RunupDampingShape::wheel_rigid_motion)
      damp_wheel_rigid_motion(u, v, f, sums);
    else
      damp_nodes(u, v, f, sums);
    work = h * sums.rigid_power;
    return sums.power;
  }



  namespace
  {
    /** The damping force alpha m w on a DoF of mass @p mass, velocity
     *  @p velocity and rigid velocity @p rigid_velocity, added to @p force,
     *  with its power on the motion relative to the rigid one and on the
     *  rigid motion added to @p power and @p rigid_power. */
    inline void
    damp(const double alpha,
         const double mass,
         const double velocity,
         const double rigid_velocity,
         const double damped_velocity,
         double      &force,
         double      &power,
         double      &rigid_power)
    {
      const double fd = alpha * mass * damped_velocity;
      force += fd;
      power += fd * (velocity - rigid_velocity);
      rigid_power -= fd * rigid_velocity;
    }
  } // namespace



  void
  WheelsetCoupling::damp_nodes(const VectorType &u,
                               const VectorType &v,
                               VectorType       &f,
                               DampingSums      &sums) const
  {
    const Point<dim>               axle  = wheelset.axle_position();
    const Tensor<1, dim>          &Va    = wheelset.axle_velocity();
    const double                   omega = wheelset.angular_velocity();
    const std::vector<Point<dim>> &nodes = fe->support_points();
    const double                  *U     = u.begin();
    const double                  *V     = v.begin();
    const double                  *M     = fe->lumped_mass().begin();
    double                        *F     = f.begin();
    const unsigned int             n     = u.locally_owned_size();

    // the node's rigid velocity V_a + omega e_y x r (r relative to the
    // axle; V_a with the lateral creepage's v_y) in the DoF's direction
    // (a node's x, y, z DoFs are contiguous); 0 on the rail
    const auto rigid_velocity = [&](const unsigned int k) {
      const unsigned int component = fe->dof_component(k);
      const unsigned int first     = k - component;
      const double       rx        = nodes[k][0] + U[first] - axle[0];
      const double       rz        = nodes[k][2] + U[first + 2] - axle[2];
      if (component == 0)
        return Va[0] + omega * rz;
      if (component == 2)
        return Va[2] - omega * rx;
      return Va[1]; // the lateral creepage's constant v_y (else 0)
    };
    // the sums in locals, as scalars: in the struct the compiler pairs
    // them into vector additions, without the multiply-adds of their bits
    double power = 0, rigid_power = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        const bool   wheel = fe->dof_material(k) == Geometry::MaterialIds::wheel;
        const double vr    = wheel ? rigid_velocity(k) : 0.;
        damp(runup_damping, M[k], V[k], vr, V[k] - vr, F[k], power, rigid_power);
      }
    sums.power       = power;
    sums.rigid_power = rigid_power;
  }



  WheelsetCoupling::RigidFit
  WheelsetCoupling::wheel_rigid_fit(const VectorType &u, const VectorType &v) const
  {
    const Point<dim> axle  = wheelset.axle_position();
    const double     omega = wheelset.angular_velocity();
    const double    *U     = u.begin();
    const double    *V     = v.begin();
    const double    *M     = fe->lumped_mass().begin();
    // the wheel's mass, centre of mass (relative to the axle), momentum,
    // angular momentum and polar moment in the rolling plane, summed
    // over the ranks. Over the wheel's nodes (the x DoF, z two further),
    // x then z, in DoF order as a loop over all DoFs would sum them:
    // mass (x DoFs), mass (z DoFs), sum m rz, sum m rx, sum m r^2,
    // P_x, P_z, L_y = sum m (rz v_x - rx v_z)
    std::array<double, 8> s = {{0, 0, 0, 0, 0, 0, 0, 0}};
    for (const WheelNode &node : wheel_nodes)
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
    RigidFit fit;
    if (g[0] > 0 && g[1] > 0)
      {
        fit.rcz = g[2] / g[0];
        fit.rcx = g[3] / g[1];
        fit.Vcx = g[5] / g[0];
        fit.Vcz = g[6] / g[1];
        // about the centre of mass
        const double J = g[4] - g[2] * fit.rcz - g[3] * fit.rcx;
        const double L = g[7] - (g[2] * fit.Vcx - g[3] * fit.Vcz);
        if (J > 0)
          fit.dOmega = L / J - omega;
      }
    return fit;
  }



  void
  WheelsetCoupling::damp_wheel_rigid_motion(const VectorType &u,
                                            const VectorType &v,
                                            VectorType       &f,
                                            DampingSums      &sums) const
  {
    const Point<dim>      axle  = wheelset.axle_position();
    const Tensor<1, dim> &Va    = wheelset.axle_velocity();
    const double          omega = wheelset.angular_velocity();
    const double         *U     = u.begin();
    const double         *V     = v.begin();
    const double         *M     = fe->lumped_mass().begin();
    double               *F     = f.begin();
    // the damped velocity is w = (V_c - V_a) + (Omega - omega) e_y x (r - r_c),
    // against the reference motion: the centre of mass with the axle,
    // rotation omega about it
    const RigidFit fit   = wheel_rigid_fit(u, v);
    double         power = 0, rigid_power = 0; // as in damp_nodes()
    for (const WheelNode &node : wheel_nodes)
      {
        const unsigned int kx = node.dof, kz = kx + 2;
        const double       rx = node.x + U[kx] - axle[0];
        const double       rz = node.z + U[kz] - axle[2];
        damp(runup_damping,
             M[kx],
             V[kx],
             Va[0] + omega * (rz - fit.rcz),
             fit.Vcx - Va[0] + fit.dOmega * (rz - fit.rcz),
             F[kx],
             power,
             rigid_power);
        damp(runup_damping,
             M[kz],
             V[kz],
             Va[2] - omega * (rx - fit.rcx),
             fit.Vcz - Va[2] - fit.dOmega * (rx - fit.rcx),
             F[kz],
             power,
             rigid_power);
      }
    sums.power       = power;
    sums.rigid_power = rigid_power;
  }
} // namespace WheelRail
