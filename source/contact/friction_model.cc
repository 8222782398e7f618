/**
 * @file contact/friction_model.cc
 * FrictionModel: the slip rate given to the law, the relaxing friction
 * state, tangential damping and the return to the cone at one contact point.
 */

#include <wheelrail/contact/friction_model.h>

#include <cmath>

namespace WheelRail
{
  FrictionModel::FrictionModel(const FrictionLaw &law, const Options &options)
    : friction_law(law)
    , opts(options)
  {}



  FrictionModel::Memory
  FrictionModel::new_contact() const
  {
    Memory memory;
    memory.state = friction_law.coefficient(0.);
    return memory;
  }



  double
  FrictionModel::irreversible_rate(const double elastic_norm,
                                   const double normal_force,
                                   const double k_t_dt) const
  {
    // g(s) = k_t dt s + F_n f(s) - |F_e - k_t de| is negative at s = 0 (the
    // point slips) and not negative at s = |F_e - k_t de| / (k_t dt); for a
    // convex decreasing f it has one root between. Bisection to round-off.
    double lo = 0, hi = elastic_norm / k_t_dt;
    for (unsigned int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i)
      {
        const double s = 0.5 * (lo + hi);
        if (k_t_dt * s + normal_force * friction_law.coefficient(s) < elastic_norm)
          lo = s;
        else
          hi = s;
      }
    return 0.5 * (lo + hi);
  }



  FrictionModel::Result
  FrictionModel::step(const dealii::Tensor<1, 3> &de,
                      const dealii::Tensor<1, 3> &normal,
                      const double                normal_force,
                      const double                k_t,
                      const double                mass,
                      const double                dt,
                      Memory                     &memory) const
  {
    Result result;

    // the spring's elastic trial, in the tangent plane; beyond the cone it
    // is the irreversible slip
    dealii::Tensor<1, 3> elastic = memory.elastic_force - k_t * de;
    elastic -= (elastic * normal) * normal;
    const double elastic_norm = elastic.norm();

    // the slip rate the law sees and the coefficient of the cone
    double slip = 0, cof = 0;
    if (opts.relaxes())
      {
        const double theta = memory.state;
        if (opts.irreversible_slip_rate)
          slip = std::max(elastic_norm - theta * normal_force, 0.) / (k_t * dt);
        else
          slip = de.norm() / dt;
        const double f_s  = friction_law.coefficient(slip);
        const double rate = (opts.relaxation_length > 0 ? slip / opts.relaxation_length : 0.) +
                            (opts.relaxation_time > 0 ? 1. / opts.relaxation_time : 0.);
        cof          = f_s + (theta - f_s) * std::exp(-rate * dt);
        memory.state = cof;
      }
    else if (opts.irreversible_slip_rate)
      {
        const double f_0 = friction_law.coefficient(0.);
        slip             = elastic_norm <= f_0 * normal_force ?
                             0. :
                             irreversible_rate(elastic_norm, normal_force, k_t * dt);
        cof              = friction_law.coefficient(slip);
      }
    else
      {
        slip = de.norm() / dt;
        cof  = friction_law.coefficient(slip);
      }

    result.force =
      return_map(elastic, cof * normal_force, k_t, result.slipping, result.friction_loss);
    memory.elastic_force = result.force;
    if (!result.slipping && opts.damping_ratio > 0)
      {
        // the damper in parallel with the sticking spring, the sum capped by
        // the cone; it dissipates the work of its share on the relative
        // motion -de
        const double         c_t     = 2. * opts.damping_ratio * std::sqrt(k_t * mass);
        dealii::Tensor<1, 3> viscous = (-c_t / dt) * de;
        viscous -= (viscous * normal) * normal;
        dealii::Tensor<1, 3> total = elastic + viscous;
        const double         limit = cof * normal_force;
        if (total.norm() > limit)
          total *= limit / total.norm();
        result.damping_work = -((total - elastic) * de);
        result.force        = total;
      }

    result.cof  = cof;
    result.slip = slip;
    if (opts.irreversible_slip_rate)
      result.slip_rate = slip > 0 ? (-slip / elastic_norm) * elastic : dealii::Tensor<1, 3>();
    else
      result.slip_rate = de / dt;
    return result;
  }
} // namespace WheelRail
