#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/simulator/format.h>
#include <wheelrail/simulator/simulator.h>
#include <wheelrail/solver/st_venant_kirchhoff.h>
#include <wheelrail/solver/static_solver.h>
#include <wheelrail/verification/hertz_patch.h>
#include <wheelrail/verification/verdict.h>

#include <cmath>

namespace WheelRail
{
  using Report::fmt;

  namespace
  {
    /** Rotation matrix for angle @p angle about the unit vector @p axis. */
    Tensor<2, dim>
    rotation_matrix(const Tensor<1, dim> &axis, const double angle)
    {
      const double   c = std::cos(angle), s = std::sin(angle);
      Tensor<2, dim> R;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          R[i][j] = (i == j ? c : 0.) + (1 - c) * axis[i] * axis[j];
      R[0][1] -= s * axis[2];
      R[0][2] += s * axis[1];
      R[1][0] += s * axis[2];
      R[1][2] -= s * axis[0];
      R[2][0] -= s * axis[1];
      R[2][1] += s * axis[0];
      return R;
    }

    /** Tolerance of the static checks' relative stresses and forces:
     *  round-off of double arithmetic, or with single-precision element
     *  geometry the floats' 2^-24 = 6e-8 relative rounding of b and c
     *  summed over the 64 vertex terms at a node (measured: 2e-6 for the
     *  wheel rotated by 30 degrees, 5e-8 in the patch test). */
    double
    static_check_tolerance(const Parameters &parameters)
    {
      return parameters.solver.single_precision_geometry ? 5e-6 : 1e-10;
    }

    /** The patch test's report: the exact stress @p Sx, the largest cell
     *  stress error @p stress_error relative to it, the largest interior
     *  nodal force relative to the largest boundary one @p force_ratio,
     *  and the verdict of both against @p tol. */
    void
    report_patch_test(const ConditionalOStream &pcout,
                      const Tensor<2, dim>     &Sx,
                      const double              stress_error,
                      const double              force_ratio,
                      const double              tol)
    {
      pcout << "Patch test: u = G X on every node" << std::endl
            << "  exact 2nd Piola-Kirchhoff stress |S| : " << fmt(Sx.norm() * 1e-6) << " MPa"
            << std::endl
            << "  S_xx, S_yy, S_zz, S_xy, S_yz, S_xz   : " << fmt(Sx[0][0] * 1e-6) << " "
            << fmt(Sx[1][1] * 1e-6) << " " << fmt(Sx[2][2] * 1e-6) << " " << fmt(Sx[0][1] * 1e-6)
            << " " << fmt(Sx[1][2] * 1e-6) << " " << fmt(Sx[0][2] * 1e-6) << " MPa" << std::endl
            << "  largest cell stress error / |S|      : " << fmt(stress_error, 1) << std::endl
            << "  largest interior nodal force / largest boundary nodal force : "
            << fmt(force_ratio, 1) << std::endl
            << "  both within " << fmt(tol) << "                : "
            << Verification::verdict(stress_error < tol && force_ratio < tol) << std::endl;
    }



    /** The lines of the rolling start that say what holds the wheelset:
     *  the held creepage, the lateral creepage or yaw, the run-up damping
     *  of shape @p shape. */
    void
    report_rolling_controls(const ConditionalOStream &pcout,
                            const Parameters         &parameters,
                            const Wheelset           &wheelset,
                            const RunupDampingShape   shape)
    {
      const WheelsetParameters &wp = parameters.wheelset;
      if (wp.creepage_control_time > 0)
        {
          pcout << "  creepage held at " << fmt(wp.initial_creepage)
                << " (omega = v_x (1 - xi_0) / r) ";
          if (wp.creepage_control_time < parameters.solver.end_time)
            pcout << "until t = " << fmt(wp.creepage_control_time * 1e3) << " ms, the torque after";
          else
            pcout << "for the whole run";
          pcout << std::endl;
        }
      if (wp.axle_lateral_creepage() != 0)
        pcout << "  lateral creepage eta = " << fmt(wp.axle_lateral_creepage())
              << (wp.yaw_angle != 0 ?
                    " (yaw angle psi = " + fmt(wp.yaw_angle) + " rad, eta = -psi)" :
                    std::string())
              << ": the axle moves laterally at v_y = eta V = " << fmt(wheelset.axle_velocity()[1])
              << " m/s" << std::endl;
      if (wp.runup_damping > 0 && wp.runup_time > 0)
        {
          pcout << "  run-up damping alpha = " << fmt(wp.runup_damping) << " 1/s of "
                << (shape == RunupDampingShape::nodes ?
                      "the velocity relative to the wheelset's rigid motion" :
                      "the wheel's rigid motion relative to the axle's");
          if (wp.runup_time < parameters.solver.end_time)
            pcout << " until t = " << fmt(wp.runup_time * 1e3) << " ms";
          else
            pcout << " for the whole run";
          pcout << std::endl;
        }
    }
  } // namespace



  void
  Simulator::run_patch_test()
  {
    const VerificationParameters &vp = parameters.verification;
    VectorType                    force;
    const Tensor<2, dim>          G = vp.displacement_gradient;
    solver->set_displacement([&](const Point<dim> &X) { return G * X; });
    solver->compute_internal_force(force);
    const Tensor<2, dim> Sx =
      StVenantKirchhoff::second_piola_kirchhoff_stress(StVenantKirchhoff::green_lagrange_strain(
                                                         unit_symmetric_tensor<dim>() + G),
                                                       parameters.material.lambda(),
                                                       parameters.material.mu());
    double     max_stress_error = 0;
    const auto stresses         = solver->cell_stresses();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &s = stresses[cell->active_cell_index()];
          max_stress_error =
            std::max(max_stress_error, (s.second_piola_kirchhoff - Sx).norm() / Sx.norm());
        }
    max_stress_error    = Utilities::MPI::max(max_stress_error, mpi_communicator);
    double max_interior = 0, max_boundary = 0;
    for (unsigned int i = 0; i < force.locally_owned_size(); ++i)
      (solver->boundary_dof_mask()[i] ? max_boundary : max_interior) =
        std::max(solver->boundary_dof_mask()[i] ? max_boundary : max_interior,
                 std::abs(force.local_element(i)));
    max_interior = Utilities::MPI::max(max_interior, mpi_communicator);
    max_boundary = Utilities::MPI::max(max_boundary, mpi_communicator);
    report_patch_test(
      pcout, Sx, max_stress_error, max_interior / max_boundary, static_check_tolerance(parameters));
  }



  void
  Simulator::run_static_check()
  {
    const VerificationParameters &vp = parameters.verification;
    const double                  E  = parameters.material.youngs_modulus;
    VectorType                    force;

    if (parameters.problem.mode == RunMode::patch_test)
      {
        run_patch_test();
        return;
      }

    // rigid rotation of the wheel (or the bar) about its centre
    const std::pair<types::material_id, Point<dim>> rotating =
      parameters.geometry_model->rotating_body();
    const Point<dim>     centre = rotating.second;
    const Tensor<2, dim> R      = rotation_matrix(vp.rotation_axis, vp.rotation_angle);
    solver->set_displacement(
      [&](const Point<dim> &X) {
        const Tensor<1, dim> r = X - centre;
        return R * r - r;
      },
      rotating.first);
    solver->compute_internal_force(force);
    double     max_vm   = 0;
    const auto stresses = solver->cell_stresses();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        max_vm = std::max(max_vm, stresses[cell->active_cell_index()].von_mises);
    max_vm                 = Utilities::MPI::max(max_vm, mpi_communicator);
    const double max_force = Utilities::MPI::max(force.linfty_norm(), mpi_communicator);
    const double h         = solver->mesh_quality().min_longest_edge;
    // force scale: E h^2 times the size of the displacement gradient
    const double scale = E * h * h * (R - unit_symmetric_tensor<dim>()).norm();
    const double tol   = static_check_tolerance(parameters);
    pcout << "Rigid rotation by " << fmt(vp.rotation_angle * 180 / M_PI) << " degrees about ("
          << fmt(vp.rotation_axis[0], 4) << ", " << fmt(vp.rotation_axis[1], 4) << ", "
          << fmt(vp.rotation_axis[2], 4) << ")" << std::endl
          << "  largest von Mises stress / E                : " << fmt(max_vm / E, 1) << std::endl
          << "  largest nodal force / (E h_min^2 |R - I|)   : " << fmt(max_force / scale, 1)
          << std::endl
          << "  both within " << fmt(tol) << "                      : "
          << Verification::verdict(max_vm / E < tol && max_force / scale < tol) << std::endl;
  }



  void
  Simulator::run_static_contact()
  {
    AssertThrow(parameters.geometry_model->has_wheel() && contact,
                ExcMessage("Problem/Mode = static contact needs Problem/Geometry = wheel and "
                           "rail and Contact/Enabled = true."));
    Timer               timer;
    StaticContactSolver statics(parameters, *solver, *contact, mpi_communicator);
    const StaticResult  r = statics.solve(parameters.statics.axle_load, solver_log());
    // The digits printed here are those that the solve determines: the state
    // is known to the Newton tolerance (1e-5 of the load by default) and the
    // force to the load tolerance (1e-4). With Inexact Newton each CPU's
    // round-off takes CG to other iterates and the solve by another path
    // within them (forces to about 1e-5 of the load, nodal values to about
    // 1e-4): in a test its force has 4 digits and its iteration counts are
    // left out. The patch's discretisation error against Hertz is percents.
    const bool inexact_test = parameters.problem.test_mode && parameters.statics.inexact_newton;
    pcout << "Static solution: axle displacement " << fmt(r.axle_displacement * 1e6, 4) << " um, "
          << "contact force " << fmt(r.contact_force * 1e-3, inexact_test ? 4 : 5) << " kN";
    if (!inexact_test)
      pcout << " after " << r.load_iterations << " load iterations, " << r.newton_iterations
            << " Newton iterations";
    if (!parameters.problem.test_mode)
      pcout << ", " << r.linear_iterations << " CG iterations, " << fmt(timer.wall_time(), 3)
            << " s";
    pcout << std::endl;

    Verification::compare_patch_with_hertz(*access, r.contact_force);
    write_contact_nodes(*access, "contact_nodes.csv");
    if (!parameters.problem.test_mode)
      {
        VtuOutput(*access).write();
        pcout << "  results in " << output_directory << "/ (contact_nodes.csv, solution.pvd)"
              << std::endl;
      }
  }



  void
  Simulator::start_wheelset()
  {
    const Point<dim> centre = parameters.geometry_model->wheel_centre();
    Point<dim>       axle   = centre;
    double radius = parameters.geometry_model->rolling_radius() + parameters.geometry.initial_gap;
    if (parameters.wheelset.static_start)
      {
        AssertThrow(contact, ExcMessage("Wheelset/Static start needs Contact/Enabled = true."));
        Timer        timer;
        StaticResult r;
        const bool   read = read_static_start(r);
        if (!read)
          {
            // the wheel of the rolling run spins: include its centrifugal load
            const double omega =
              parameters.wheelset.rolling_speed / parameters.geometry_model->rolling_radius();
            solver->add_centrifugal_load(centre, omega);
            StaticContactSolver statics(parameters, *solver, *contact, mpi_communicator);
            r = statics.solve(wheelset->static_load(), solver_log());
            solver->remove_centrifugal_load();
            write_static_start(r);
          }
        axle[2] -= r.axle_displacement;
        // rolling radius: axle height above the contact points
        double fz = 0, z = 0;
        for (const auto &s : contact->slave_states())
          if (s.in_contact)
            {
              fz += s.normal_force;
              z += s.normal_force * s.x[2];
            }
        if (fz > 0)
          radius = axle[2] - z / fz;
        pcout << "Static start at A: wheel load " << fmt(r.contact_force * 1e-3) << " kN (target "
              << fmt(wheelset->static_load() * 1e-3) << " kN), axle lowered by "
              << fmt(r.axle_displacement * 1e6, 5) << " um, " << contact->summary().n_contact
              << " contact nodes, penetration " << fmt(contact->summary().max_penetration * 1e6, 4)
              << " um";
        if (!parameters.problem.test_mode && !read)
          pcout << " (" << r.newton_iterations << " Newton, " << r.linear_iterations
                << " CG iterations, " << fmt(timer.wall_time(), 3) << " s)";
        pcout << std::endl;
        if (!parameters.wheelset.static_start_state.empty())
          pcout << "  static start " << (read ? "read from " : "written to ")
                << parameters.wheelset.static_start_state << "/" << std::endl;
      }
    wheelset->start_rolling(axle, radius);
    pcout << "Rolling: V = " << fmt(parameters.wheelset.rolling_speed) << " m/s, rolling radius "
          << fmt(radius * 1e3, 7) << " mm, omega = " << fmt(wheelset->angular_velocity(), 6)
          << " rad/s, driving torque " << fmt(wheelset->torque(1e30) * 1e-3, 5)
          << " kN m (mu_n = " << fmt(parameters.wheelset.traction_coefficient) << ")" << std::endl;
    report_rolling_controls(pcout, parameters, *wheelset, wheelset_coupling->damping_shape());
  }



  void
  Simulator::apply_initial_conditions()
  {
    const InitialParameters &ip     = parameters.initial;
    const auto               extra  = make_vector_function(ip.velocity_expression,
                                            ip.velocity_constants,
                                            "x,y,z",
                                            "Initial conditions/Velocity function");
    const Point<dim>         centre = parameters.geometry_model->wheel_centre();
    solver->set_velocity([&](const Point<dim> &X, const types::material_id material) {
      Tensor<1, dim> v;
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = extra->value(X, d);
      if (material == Geometry::MaterialIds::wheel && wheelset)
        {
          // the wheel rolls with its axle: V e_x + omega e_y x (x - x_axle)
          const Tensor<1, dim> r = X - centre;
          v += wheelset->axle_velocity() +
               wheelset->angular_velocity() * Tensor<1, dim>({r[2], 0., -r[0]});
        }
      else if (material == Geometry::MaterialIds::wheel)
        {
          const Tensor<1, dim> r = X - centre;
          // omega e_y x r
          v += ip.wheel_velocity + ip.wheel_angular_velocity * Tensor<1, dim>({r[2], 0., -r[0]});
        }
      return v;
    });
  }
} // namespace WheelRail
