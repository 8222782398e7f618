/**
 * @file contact/friction_model.h
 * One step of the friction at a contact point: the slip rate the law is
 * given, an optional friction state that relaxes towards the law, optional
 * tangential damping, and the return to the cone. The penalty contact
 * calls it at every slave node; the 1D slider of the verification calls the
 * same code.
 */
#ifndef wheelrail_contact_friction_model_h
#define wheelrail_contact_friction_model_h

#include <deal.II/base/tensor.h>

#include <wheelrail/contact/friction_law.h>

namespace WheelRail
{
  /**
   * The friction of one contact point over one time step.
   *
   * With the default options it is the paper's scheme (SPEC 4): the law is
   * evaluated at s = |de| / dt, the motion of the point relative to the
   * master material in the step (the elastic rate of the tangential spring
   * included), and the trial force F_e - k_t de is returned to the cone
   * f(s) |F_n|. The options, each off by default:
   *
   * - Irreversible slip rate: s is the slip increment minus the elastic
   *   increment of the tangential spring: in slip the spring's trial
   *   beyond the cone, (|F_e - k_t de| - f |F_n|) / (k_t dt) (the damper's
   *   force is not slip), in stick 0. Without relaxation f(s) and s are
   *   solved together (a scalar root, unique for a convex decreasing law
   *   such as eq. 1). In adhesion the spring's own oscillation no longer
   *   reads as slip.
   * - Relaxation: the coefficient is a state theta that follows the law
   *   with d theta / dt = -(s / L + 1 / tau) (theta - f(s)), integrated
   *   exactly over the step with s of the step; the cone is theta |F_n|.
   *   L is a slip distance, tau a time (rate-and-state style, cf.
   *   Prakash & Clifton, CONTACT's friction memory). A node that comes
   *   into contact starts at theta = f(0). s is then computed with the
   *   state at the start of the step.
   * - Tangential damping: a viscous force -c_t de / dt, c_t = 2 zeta
   *   sqrt(k_t m), in parallel with the spring while it sticks (it damps the
   *   slave node's mode on its tangential spring); the sum is capped by the
   *   cone. Whether the point slips is the spring's decision alone, and the
   *   spring's memory keeps the elastic part only. The damper's work on the
   *   relative motion is its dissipation.
   */
  class FrictionModel
  {
  public:
    struct Options
    {
      bool   irreversible_slip_rate = false; ///< s without the spring's elastic rate
      double relaxation_length      = 0;     ///< L [m], 0: no relaxation by slip
      double relaxation_time        = 0;     ///< tau [s], 0: no relaxation in time
      double damping_ratio          = 0;     ///< zeta of the tangential damping [-]

      /** Whether the coefficient is a relaxing state. */
      bool
      relaxes() const
      {
        return relaxation_length > 0 || relaxation_time > 0;
      }
    };

    /** The memory of a contact point between steps. */
    struct Memory
    {
      dealii::Tensor<1, 3> elastic_force; ///< force in the tangential spring [N]
      double               state = 0;     ///< theta, the relaxing coefficient [-]
    };

    /** What one step gives. */
    struct Result
    {
      dealii::Tensor<1, 3> force;             ///< F_t on the slave [N]
      dealii::Tensor<1, 3> slip_rate;         ///< the slip rate vector the law sees [m/s]
      double               slip          = 0; ///< its magnitude s [m/s]
      double               cof           = 0; ///< the coefficient of the cone [-]
      bool                 slipping      = false;
      double               friction_loss = 0; ///< energy lost in the slip [J]
      double               damping_work  = 0; ///< energy lost in the damper [J]
    };

    FrictionModel(const FrictionLaw &law, const Options &options);

    /** The memory of a point that comes into contact. */
    Memory
    new_contact() const;

    /**
     * One step: @p de the motion of the slave relative to the master
     * material in the step [m], @p normal the contact normal, @p normal_force
     * |F_n| [N], @p k_t the tangential spring [N/m], @p mass the slave's
     * lumped mass [kg] (tangential damping), @p dt the step [s]. Updates
     * @p memory.
     */
    Result
    step(const dealii::Tensor<1, 3> &de,
         const dealii::Tensor<1, 3> &normal,
         const double                normal_force,
         const double                k_t,
         const double                mass,
         const double                dt,
         Memory                     &memory) const;

    /** The coefficient law(s). */
    const FrictionLaw &
    law() const
    {
      return friction_law;
    }

    const Options &
    options() const
    {
      return opts;
    }

  private:
    /** The irreversible slip rate s > 0 of a slipping point with
     *  k_t dt s + F_n f(s) = |F_e - k_t de| = @p elastic_norm. */
    double
    irreversible_rate(const double elastic_norm,
                      const double normal_force,
                      const double k_t_dt) const;

    const FrictionLaw &friction_law;
    const Options      opts;
  };
} // namespace WheelRail

#endif
