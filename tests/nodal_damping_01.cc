// Unit test of the stiffness damping from one nodal field (Damping form =
// nodal field, nodal_damping.h): the element forces at w = u + beta_n v.
//  - beta_n is the smallest beta_e of the node's cells: on a bar of 10 mm
//    cubes with one cell refined (stiffness damping, beta_e = COEF L_e / c)
//    the nodes of the refined cell's children have the children's beta_e,
//    half the coarse one, and every other node the coarse beta_e;
//  - on the linear element with an affine velocity v = L X (strain rate
//    D = sym L, no hourglass mode) and u = 0, the damping power
//    v . (f_int(beta v) - f_int(0)) is the viscous stress's
//    beta V (lambda tr(D)^2 + 2 mu D : D) to first order: with v scaled by
//    1, 1/2, 1/4 the relative difference halves (it is O(beta |L|));
//  - the nodal forces f_int(u + beta v) - f_int(u) against the strain-rate
//    form's beta_e C : dE/dt forces: the same halving at u = 0; at a
//    homogeneous u = H0 X they differ by the geometric stiffness term,
//    O(|H0|) of the force, which the strain-rate form leaves out.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/elastic_operator.h>
#include <wheelrail/solver/nodal_damping.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

using namespace WheelRail;

namespace
{
  void
  parse(Parameters &parameters, const std::string &damping)
  {
    {
      std::ofstream prm_file("nodal_damping_01_case.prm");
      prm_file << "subsection Problem\n  set Geometry = bar\n  set Test mode = true\nend\n"
                  "subsection Geometry\n  subsection Bar\n    set Length = 0.04\n"
                  "    set Width = 0.02\n    set Height = 0.02\n    set Cells = 4, 2, 2\n"
                  "    set Distortion = 0\n  end\nend\n"
                  "subsection Time integration\n"
               << damping << "  set Damping form = nodal field\nend\n";
    }
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    parameters.parse(prm, "nodal_damping_01_case.prm");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = true;

  // beta_n on a mesh with one refined cell
  {
    Parameters parameters;
    parse(parameters, "  set Damping model = stiffness\n");
    parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
    Geometry::build(*parameters.geometry_model, triangulation);
    const auto refined = std::next(triangulation.begin_active(), 5);
    refined->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();
    ElasticOperator op(parameters, triangulation);
    op.setup();
    VectorType beta;
    op.smallest_cell_beta(beta);
    const double c      = parameters.material.wave_speed();
    const double coarse = parameters.solver.stiffness_damping_coefficient * 0.01 / c;
    // the nodes of the refined cells: their x-DoFs
    std::vector<bool>                    fine(beta.locally_owned_size(), false);
    std::vector<types::global_dof_index> dofs(24);
    for (const auto &cell : op.get_dof_handler().active_cell_iterators())
      if (cell->level() == 1)
        {
          cell->get_dof_indices(dofs);
          for (const auto d : dofs)
            fine[beta.get_partitioner()->global_to_local(d)] = true;
        }
    unsigned int n_fine = 0, n_coarse = 0;
    double       error = 0;
    for (unsigned int i = 0; i < beta.locally_owned_size(); ++i)
      {
        const double expected = fine[i] ? 0.5 * coarse : coarse;
        (fine[i] ? n_fine : n_coarse) += 1;
        error = std::max(error, std::abs(beta.local_element(i) - expected) / expected);
      }
    std::printf("beta_n, one cell of 10 mm refined: %u DoFs at the children's beta_e "
                "(half the coarse one), %u at the coarse one, within 1e-12: %s\n",
                n_fine,
                n_coarse,
                error < 1e-12 ? "yes" : "NO");
    ok &= error < 1e-12 && n_fine == 3 * 27;
  }

  // first order on the linear element
  Parameters parameters;
  parse(parameters, "  set Damping model = Rayleigh\n  set Rayleigh beta = 1e-6\n");
  parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
  Geometry::build(*parameters.geometry_model, triangulation);
  ElasticOperator op(parameters, triangulation);
  op.setup();
  NodalDamping nodal;
  nodal.setup(op);
  const double beta = parameters.solver.rayleigh_beta;
  const double la = parameters.material.lambda(), mu = parameters.material.mu();
  const double volume = 0.04 * 0.02 * 0.02;

  // a velocity gradient of about 200 1/s: beta |L| about 2e-4
  const Tensor<2, dim> L({{120., -40., 75.}, {-90., 60., 30.}, {20., 110., -150.}});
  const Tensor<2, dim> H0({{2e-4, 1e-4, -3e-4}, {0., -1e-4, 2e-4}, {1e-4, 3e-4, 1e-4}});

  const auto field = [&](const Tensor<2, dim> &G, const double s) {
    VectorType x(op.partitioner());
    op.interpolate([&](const Point<dim> &X) { return s * (G * X); },
                   numbers::invalid_material_id,
                   x);
    return x;
  };

  for (const bool strained : {false, true})
    {
      const VectorType u = strained ? field(H0, 1.) : VectorType(op.partitioner());
      VectorType       f_u(op.partitioner());
      op.element_forces(u, nullptr, f_u, false);
      std::printf("%s\n", strained ? "u = H0 X, |H0| = 5.4e-4:" : "u = 0:");
      double last_power = 0, last_force = 0;
      for (const double s : {1., 0.5, 0.25})
        {
          const VectorType v = field(L, s);
          VectorType       w(op.partitioner()), f_w(op.partitioner()), f_rate(op.partitioner());
          nodal.damped_displacement(u, v, w);
          op.element_forces(w, nullptr, f_w, false);
          op.element_forces(u, &v, f_rate, false);
          const double power = NodalDamping::power(v, f_w, f_u);
          // the viscous stress beta C : D of the constant strain rate
          const Tensor<2, dim> D  = 0.5 * (s * L + transpose(s * L));
          const double         tr = trace(D);
          const double         exact = beta * volume * (la * tr * tr + 2. * mu * scalar_product(D, D));
          VectorType           nodal_force = f_w, rate_force = f_rate;
          nodal_force -= f_u;
          rate_force -= f_u;
          VectorType difference = nodal_force;
          difference -= rate_force;
          const double power_error = std::abs(power - exact) / exact;
          const double force_error = difference.l2_norm() / rate_force.l2_norm();
          if (!strained)
            {
              char ratios[2][32] = {"", ""};
              if (last_power > 0)
                {
                  std::snprintf(ratios[0], 32, " (ratio %.2f)", last_power / power_error);
                  std::snprintf(ratios[1], 32, " (ratio %.2f)", last_force / force_error);
                }
              std::printf("  v = %.2f L X: damping power %.4g W (beta V (lambda tr(D)^2 + 2 mu D:D) "
                          "%.4g W), relative difference %.1e%s; forces against beta C : dE/dt: "
                          "%.1e%s\n",
                          s,
                          power,
                          exact,
                          power_error,
                          ratios[0],
                          force_error,
                          ratios[1]);
              ok &= power_error < 1e-3 && force_error < 1e-3;
              if (last_power > 0)
                ok &= std::abs(last_power / power_error - 2.) < 0.05 &&
                      std::abs(last_force / force_error - 2.) < 0.05;
            }
          else
            {
              std::printf("  v = %.2f L X: forces against beta C : dE/dt: %.1e of the force, "
                          "%.2f |H0|\n",
                          s,
                          force_error,
                          force_error / 5.4e-4);
              ok &= force_error < 5. * 5.4e-4;
            }
          last_power = power_error;
          last_force = force_error;
        }
    }
  return ok ? 0 : 1;
}
