/**
 * @file wheelset.h
 * The rigid axle that carries the wheel's bore, the sprung mass on the
 * primary suspension, and the driving torque (SPEC 3).
 */
#ifndef wheelrail_solver_wheelset_h
#define wheelrail_solver_wheelset_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <wheelrail/base/checkpoint.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/rotation.h>

#include <cmath>

namespace WheelRail
{
  /**
   * Rigid-body state of the axle (translation in x and z, rotation about y;
   * in y a constant velocity (eta - psi) V, 0 unless Wheelset/Lateral
   * creepage or Yaw angle is given, held by a lateral guide whose work
   * enters external_work()) and of the sprung mass (vertical; horizontally
   * it moves with the axle). The bore nodes of the wheel belong to the
   * rigid body: their lumped masses and inertia are added to the axle's,
   * and the FE forces on them drive it. Central differences as for the FE
   * nodes.
   *
   * The suspension force on the axle is
   *   F_s = -M_c g + K (d_c - d_a) + C (v_c - v_a),
   * d_a, d_c the vertical displacements of axle and sprung mass from the
   * static state (where the spring carries M_c g).
   */
  class Wheelset
  {
  public:
    Wheelset(const WheelsetParameters &parameters,
             const SolverParameters   &solver,
             const Point<dim>         &axle_centre);

    /** Lumped mass and polar inertia of the bore nodes and of the whole FE
     *  wheel (all ranks). */
    void
    set_bore_inertia(const double mass,
                     const double polar_inertia,
                     const double fe_wheel_mass,
                     const double fe_wheel_inertia);

    /**
     * Traction coefficient of steady rolling under the torque: the traction
     * force accelerates the vehicle (horizontal mass M) and, with it, the
     * wheel's rotation (polar inertia I), so F_L = T / (r (1 + I / (M r^2))).
     */
    double
    steady_traction_coefficient() const;

    /** Start the rolling run: axle at @p static_axle (after the static
     *  solve), velocity V along x and (eta - psi) V along y (lateral
     *  creepage, yaw), angular velocity +V (1 - xi_0) / r_eff about y
     *  (xi_0 the initial creepage)
     *  (SPEC 5.3 writes -V/r_eff, which with its own v = V e_x + omega x
     *  (x - x_axle) would make the contact point move at 2V). */
    void
    start_rolling(const Point<dim> &static_axle, const double rolling_radius);

    /** The axle and suspension state, in the order of the checkpoint file,
     *  for Checkpoint::Writer and Reader. */
    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar.pod(active);
      ar.pod(displacement);
      ar.pod(velocity);
      for (double *x : {&theta, &omega, &d_axle_static, &d_c, &v_c, &work, &damper_loss, &radius})
        ar.pod(*x);
    }

    /** Whether at time t the angular velocity is held at the initial
     *  creepage (Wheelset/Creepage control time) rather than driven by the
     *  torque. */
    bool
    creepage_controlled(const double t) const
    {
      return t < prm.creepage_control_time;
    }

    /** Torque about +y at time t under torque control [N m] (positive drives
     *  towards +x). */
    double
    torque(const double t) const;

    /**
     * Advance by one step: @p force and @p moment are the FE forces on the
     * bore nodes (summed over all ranks, gravity of the bore nodes included)
     * and their moment about the axle (y component). Under creepage control
     * the angular velocity follows the new v_x; otherwise the torque and the
     * moment accelerate the rotation.
     */
    void
    advance(const Tensor<1, dim> &force,
            const double          moment,
            const double          h,
            const double          dt,
            const double          t);

    /** The rigid motion of the bore in the current state, evaluated per
     *  node without the trigonometry of the angle. */
    struct BoreMotion
    {
      Point<dim>     centre;       ///< reference axle centre
      Tensor<1, dim> displacement; ///< of the axle
      double         c, s;         ///< cos and sin of the angle
      /** Displacement of the bore node with reference position @p X. */
      Tensor<1, dim>
      operator()(const Point<dim> &X) const
      {
        const Tensor<1, dim> r = X - centre;
        return displacement + rotate_about_y(r, c, s) - r;
      }
    };
    BoreMotion
    bore_motion() const
    {
      return {centre, displacement, std::cos(theta), std::sin(theta)};
    }

    Point<dim>
    axle_position() const
    {
      return centre + displacement;
    }
    const Tensor<1, dim> &
    axle_velocity() const
    {
      return velocity;
    }
    double
    angular_velocity() const
    {
      return omega;
    }
    double
    angle() const
    {
      return theta;
    }
    /** Rolling radius r_eff of the static state (axle height above the
     *  contact points) [m]. */
    double
    rolling_radius() const
    {
      return radius;
    }
    /** Rigid longitudinal creepage (v_x - omega r_eff) / v_x [-] (0 before
     *  rolling starts). */
    double
    creepage() const
    {
      return velocity[0] != 0 ? (velocity[0] - omega * radius) / velocity[0] : 0.;
    }
    /** Static wheel load (M_c + unsprung mass) g [N]. */
    double
    static_load() const;
    /** Torque for the nominal traction coefficient: mu_n R_w F_N,static. */
    double
    nominal_torque() const;

    /** Energies of the rigid parts [J]. */
    double
    kinetic() const; ///< axle (without bore nodes), sprung mass
    double
    spring_energy() const; ///< suspension spring beyond the static preload
    double
    external_work() const; ///< gravity on axle and sprung mass, torque, lateral guide
    double
    damper_dissipation() const
    {
      return damper_loss;
    }

  private:
    const WheelsetParameters &prm;
    const double              g;      ///< |gravity|
    const Point<dim>          centre; ///< reference axle centre
    double                    m_axle = 0, m_bore = 0, i_bore = 0, m_wheel = 0, i_wheel = 0;
    bool                      active = false;
    Tensor<1, dim>            displacement, velocity; ///< axle (v_y constant)
    double                    theta = 0, omega = 0;
    double                    d_axle_static = 0; ///< axle z displacement at the static state
    double                    d_c = 0, v_c = 0;  ///< sprung mass, from the static state
    double                    work        = 0;   ///< of the torque and the lateral guide [J]
    double                    damper_loss = 0, radius = 0;
  };
} // namespace WheelRail

#endif
