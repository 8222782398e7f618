// Unit test of ElasticOperator::point_mass(), the mass that the contact's
// damping gives a slave node: on a bar with two cells refined (one
// of them twice) the hanging vertices have no lumped mass of their own, and
// a force f applied at one of them acts on its masters j as w_j f, so that
// the hanging vertex accelerates by sum_j w_j^2 f / m_j.
//  - unconstrained DoFs keep their lumped mass;
//  - a hanging DoF's point mass m_p satisfies m_p sum_j w_j^2 / m_j = 1 with
//    the weights taken from the hanging-node constraints themselves;
//  - an edge midpoint (two masters of weight 1/2) with equal masters has
//    m_p = 2 m, a face centre (four of weight 1/4) m_p = 4 m: the ratio of
//    the point mass to the masters' harmonic mean is 2 or 4.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/elastic_operator.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

using namespace WheelRail;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  {
    std::ofstream prm_file("point_mass_01_case.prm");
    prm_file << "subsection Problem\n  set Geometry = bar\n  set Test mode = true\nend\n"
                "subsection Geometry\n  subsection Bar\n    set Length = 0.04\n"
                "    set Width = 0.02\n    set Height = 0.02\n    set Cells = 4, 2, 2\n"
                "    set Distortion = 0\n  end\nend\n";
  }
  ParameterHandler prm;
  Parameters       parameters;
  Parameters::declare_parameters(prm);
  parameters.parse(prm, "point_mass_01_case.prm");

  parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
  Geometry::build(*parameters.geometry_model, triangulation);
  triangulation.begin_active()->set_refine_flag();
  std::next(triangulation.begin_active(), 5)->set_refine_flag();
  triangulation.execute_coarsening_and_refinement();
  triangulation.begin_active()->set_refine_flag(); // a child of the first: 2:1 kept
  triangulation.execute_coarsening_and_refinement();

  ElasticOperator op(parameters, triangulation);
  op.setup();
  const VectorType                 point = op.point_mass();
  const VectorType                &mass  = op.lumped_mass();
  VectorType                       ghosted(op.partitioner());
  const AffineConstraints<double> &hanging = op.get_hanging_constraints();
  ghosted                                  = mass;
  ghosted.update_ghost_values();

  unsigned int n_free = 0, n_hanging = 0, n_edge = 0, n_face = 0, n_other = 0, n_equal = 0;
  double       free_error = 0, identity_error = 0, ratio_error = 0;
  for (const auto i : mass.locally_owned_elements())
    {
      const auto *entries = hanging.get_constraint_entries(i);
      if (entries == nullptr)
        {
          ++n_free;
          free_error = std::max(free_error, std::abs(point(i) - mass(i)) / mass(i));
          continue;
        }
      ++n_hanging;
      double mobility = 0, harmonic = 0;
      for (const auto &[j, w] : *entries)
        {
          mobility += w * w / ghosted(j);
          harmonic += 1. / ghosted(j) / entries->size();
        }
      identity_error        = std::max(identity_error, std::abs(point(i) * mobility - 1.));
      const double ratio    = point(i) * harmonic;
      const double expected = entries->size();
      bool         equal    = true; // masters of equal mass (to 1e-12)
      for (const auto &[j, w] : *entries)
        equal &= std::abs(ghosted(j) - ghosted(entries->front().first)) <= 1e-12 * ghosted(j);
      if (entries->size() == 2)
        ++n_edge;
      else if (entries->size() == 4)
        ++n_face;
      else
        ++n_other;
      n_equal += equal;
      if (equal)
        ratio_error = std::max(ratio_error, std::abs(ratio - expected) / expected);
    }
  std::printf("DoFs: %u free, %u hanging (%u on edges, %u on faces, %u other)\n",
              n_free,
              n_hanging,
              n_edge,
              n_face,
              n_other);
  std::printf("free DoFs: point mass = lumped mass: %s\n", free_error == 0 ? "yes" : "NO");
  std::printf("hanging DoFs: m_p sum w^2 / m_j = 1 within 1e-14: %s\n",
              identity_error < 1e-14 ? "yes" : "NO");
  std::printf("%u hanging DoFs with masters of equal mass: m_p = (2 or 4) x their mass within "
              "1e-12: %s\n",
              n_equal,
              ratio_error < 1e-12 ? "yes" : "NO");
  return (free_error == 0 && identity_error < 1e-14 && ratio_error < 1e-12 && n_equal > 0) ? 0 : 1;
}
