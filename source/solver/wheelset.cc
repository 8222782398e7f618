#include <deal.II/base/exceptions.h>

#include <wheelrail/solver/wheelset.h>

#include <cmath>
#include <string>

namespace WheelRail
{
  Wheelset::Wheelset(const WheelsetParameters &parameters,
                     const SolverParameters   &solver,
                     const Point<dim>         &axle_centre)
    : prm(parameters)
    , g(solver.gravity.norm())
    , centre(axle_centre)
  {}



  void
  Wheelset::set_bore_inertia(const double mass,
                             const double polar_inertia,
                             const double fe_wheel_mass,
                             const double fe_wheel_inertia)
  {
    m_bore  = mass;
    i_bore  = polar_inertia;
    m_wheel = fe_wheel_mass;
    i_wheel = fe_wheel_inertia;
    m_axle  = prm.unsprung_mass - fe_wheel_mass;
    AssertThrow(m_axle > 0,
                ExcMessage("Wheelset/Unsprung mass (" + std::to_string(prm.unsprung_mass) +
                           " kg) must exceed the mass of the FE wheel (" +
                           std::to_string(fe_wheel_mass) + " kg)."));
  }



  double
  Wheelset::static_load() const
  {
    return (prm.sprung_mass + prm.unsprung_mass) * g;
  }



  double
  Wheelset::nominal_torque() const
  {
    return prm.traction_coefficient * radius * static_load();
  }



  double
  Wheelset::steady_traction_coefficient() const
  {
    const double M = prm.unsprung_mass + prm.sprung_mass; // axle + FE wheel + M_c
    const double I = prm.axle_inertia + i_wheel;
    return nominal_torque() / (radius * static_load()) / (1. + I / (M * radius * radius));
  }



  void
  Wheelset::start_rolling(const Point<dim> &static_axle, const double rolling_radius)
  {
    displacement  = static_axle - centre;
    d_axle_static = displacement[2];
    radius        = rolling_radius;
    // lateral creepage and yaw: the axle moves laterally at (eta - psi) V
    velocity =
      Tensor<1, dim>({prm.rolling_speed, prm.axle_lateral_creepage() * prm.rolling_speed, 0.});
    // rolling towards +x turns the wheel about +y: the contact point
    // (x - x_axle = -r e_z) then has omega e_y x (-r e_z) = -V e_x
    omega = prm.rolling_speed * (1. - prm.initial_creepage) / rolling_radius;
    theta = 0;
    d_c = v_c = 0;
    work = damper_loss = 0;
    active             = true;
  }



  double
  Wheelset::torque(const double t) const
  {
    // a driving torque turns the wheel forward: about +y, like omega
    const double ramp = prm.torque_ramp_time > 0 ? std::min(1., t / prm.torque_ramp_time) : 1.;
    return ramp * nominal_torque();
  }



  void
  Wheelset::advance(const Tensor<1, dim> &force,
                    const double          moment,
                    const double          h,
                    const double          dt,
                    const double          t)
  {
    if (!active)
      return;
    const double Mc  = prm.sprung_mass;
    const double d_a = displacement[2] - d_axle_static;
    const double Fs  = -Mc * g + prm.suspension_stiffness * (d_c - d_a) +
                      prm.suspension_damping * (v_c - velocity[2]);
    const double ax = force[0] / (m_axle + m_bore + Mc);
    const double az = (force[2] - m_axle * g + Fs) / (m_axle + m_bore);
    const double ac = (-Mc * g - Fs) / Mc;
    const double I  = prm.axle_inertia + i_bore;

    const double v_rel = v_c - velocity[2];
    damper_loss += prm.suspension_damping * v_rel * v_rel * h;
    const double omega_old = omega;
    velocity[0] += h * ax;
    velocity[2] += h * az;
    v_c += h * ac;
    // under creepage control the axle turns at v_x (1 - xi_0) / r: its
    // torque is what that angular acceleration takes against the FE moment
    double T;
    if (creepage_controlled(t))
      {
        omega = velocity[0] * (1. - prm.initial_creepage) / radius;
        T     = I * (omega - omega_old) / h - moment;
      }
    else
      {
        T = torque(t);
        omega += h * (moment + T) / I;
      }
    work += T * h * 0.5 * (omega_old + omega);
    if (velocity[1] != 0)
      {
        // the lateral guide holds v_y against the FE force on the bore:
        // its force -F_y does the work -F_y v_y h
        work -= force[1] * velocity[1] * h;
        displacement[1] += dt * velocity[1];
      }
    displacement[0] += dt * velocity[0];
    displacement[2] += dt * velocity[2];
    d_c += dt * v_c;
    theta += dt * omega;
  }



  double
  Wheelset::kinetic() const
  {
    const double Mc = prm.sprung_mass;
    double       e  = 0.5 * m_axle * (velocity[0] * velocity[0] + velocity[2] * velocity[2]) +
               0.5 * Mc * (velocity[0] * velocity[0] + v_c * v_c) +
               0.5 * prm.axle_inertia * omega * omega;
    // the lateral motion at constant v_y (lateral creepage, yaw)
    if (velocity[1] != 0)
      e += 0.5 * (m_axle + Mc) * velocity[1] * velocity[1];
    return e;
  }



  double
  Wheelset::spring_energy() const
  {
    const double d_a = displacement[2] - d_axle_static;
    const double e   = d_c - d_a;
    return -prm.sprung_mass * g * e + 0.5 * prm.suspension_stiffness * e * e;
  }



  double
  Wheelset::external_work() const
  {
    const double d_a = displacement[2] - d_axle_static;
    return -m_axle * g * d_a - prm.sprung_mass * g * d_c + work;
  }
} // namespace WheelRail
