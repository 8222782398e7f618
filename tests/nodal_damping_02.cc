// Unit test of the damped field w = u + beta_n v formed inside the explicit
// step (Damping form = nodal field): NodalUpdate::apply() with w forms it on
// the owned DoFs in the update pass, ElasticOperator::distribute() on the
// hanging DoFs and NodalDamping::fix_up() on the prescribed DoFs and ghosts.
//  - after every step, w equals u + beta_n v on every owned and ghost entry,
//    to the bit, on a bar with one refined cell (hanging nodes), one end
//    fixed and the other moved by a prescribed velocity;
//  - the run that forms w inside the step gives the same u, v, to the bit,
//    as the run that forms it in a pass of its own before the force loop
//    (the steps with energies take that path and the per-DoF update).
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/explicit_solver.h>

#include <cstdio>
#include <fstream>
#include <iterator>

using namespace WheelRail;

namespace
{
  void
  parse(Parameters &parameters)
  {
    {
      std::ofstream prm_file("nodal_damping_02_case.prm");
      prm_file << "subsection Problem\n  set Geometry = bar\n  set Test mode = true\nend\n"
                  "subsection Geometry\n  subsection Bar\n    set Length = 0.04\n"
                  "    set Width = 0.02\n    set Height = 0.02\n    set Cells = 4, 2, 2\n"
                  "    set Distortion = 0\n  end\nend\n"
                  "subsection Time integration\n  set Damping model = stiffness\n"
                  "  set Stiffness damping coefficient = 0.05\n"
                  "  set Damping form = nodal field\nend\n"
                  "subsection Boundary conditions\n  set Fixed boundaries = 22: xyz\n"
                  "  set Prescribed velocity boundaries = 21\n"
                  "  set Prescribed velocity = 0.5*sin(2e4*t); 0; 0.2\n"
                  "  set Wheel bore = free\nend\n";
    }
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    parameters.parse(prm, "nodal_damping_02_case.prm");
  }


  /** Entries (owned and ghost) where w is not u + beta_n v to the bit. */
  unsigned int
  damped_field_mismatches(const ExplicitSolver &solver)
  {
    const VectorType &u = solver.displacement(), &v = solver.velocity();
    const std::size_t n = u.locally_owned_size() + u.get_partitioner()->n_ghost_indices();
    const double *U = u.begin(), *V = v.begin(), *B = solver.nodal_beta().begin(),
                 *W = solver.damped_field().begin();
    unsigned int bad = 0;
    for (std::size_t i = 0; i < n; ++i)
      bad += W[i] != U[i] + B[i] * V[i];
    return bad;
  }


  void
  set_up(ExplicitSolver &solver)
  {
    solver.setup();
    solver.set_time_step(2e-7);
    solver.set_velocity([](const Point<dim> &X, const types::material_id) {
      return Tensor<1, dim>({2. * X[2], -1. * X[0], 3. * X[0] * X[1] / 0.02});
    });
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  Parameters                       parameters;
  parse(parameters);

  const unsigned int                        n_steps = 300;
  parallel::distributed::Triangulation<dim> tria_a(comm), tria_b(comm);
  for (auto *tria : {&tria_a, &tria_b})
    {
      Geometry::build(*parameters.geometry_model, *tria);
      std::next(tria->begin_active(), 5)->set_refine_flag();
      tria->execute_coarsening_and_refinement();
    }
  ExplicitSolver fused(parameters, tria_a), separate(parameters, tria_b);
  set_up(fused);
  set_up(separate);

  unsigned int steps_current = 0, mismatches = 0;
  for (unsigned int s = 0; s < n_steps; ++s)
    {
      fused.step();
      steps_current += fused.damped_field_current();
      mismatches += damped_field_mismatches(fused);
      Energies energies;
      separate.step(&energies);
    }
  steps_current = Utilities::MPI::min(steps_current, comm);
  mismatches    = Utilities::MPI::sum(mismatches, comm);

  unsigned int differ = 0;
  double       largest = 0;
  for (const auto *pair : {&fused.displacement(), &fused.velocity()})
    {
      const VectorType &a = *pair;
      const VectorType &b = pair == &fused.displacement() ? separate.displacement() :
                                                             separate.velocity();
      for (unsigned int i = 0; i < a.locally_owned_size(); ++i)
        {
          differ += a.local_element(i) != b.local_element(i);
          largest = std::max(largest, std::abs(a.local_element(i)));
        }
    }
  differ  = Utilities::MPI::sum(differ, comm);
  largest = Utilities::MPI::max(largest, comm);

  const bool ok = steps_current == n_steps && mismatches == 0 && differ == 0 && largest > 0;
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::printf("w formed in the step: %u of %u steps\n", steps_current, n_steps);
      std::printf("entries (owned and ghost, all steps) where w differs from u + beta_n v: %u\n",
                  mismatches);
      std::printf("u and v after %u steps, w in the step against w in a pass of its own: "
                  "%u entries differ\n",
                  n_steps,
                  differ);
      std::printf("%s\n", ok ? "OK" : "FAILED");
    }
  return ok ? 0 : 1;
}
