/**
 * @file static_tangent.h
 * The Newton tangent of the static contact solve (static_solver.h): the
 * bodies' stiffness matrix and the penalty tangent of the active contact
 * pairs applied beside it.
 */
#ifndef wheelrail_solver_static_tangent_h
#define wheelrail_solver_static_tangent_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <wheelrail/contact/penalty_contact.h>

#include <vector>

namespace WheelRail
{
  /**
   * The Newton tangent K + sum_p k_p g_p g_p^T: the stiffness matrix K of the
   * bodies (constant: the one-point element's small-strain stiffness in the
   * reference configuration) and the rank-one penalty tangent of each active
   * contact pair, g_p being the pair's gap functional (slave minus the
   * interpolated master point, along the normal). The contact part is applied
   * outside the matrix, so K and its AMG preconditioner are built once for
   * the whole static solve; CG deals with the contact directions the
   * preconditioner does not see.
   */
  class StaticTangent
  {
  public:
    StaticTangent(const TrilinosWrappers::SparseMatrix &K, MPI_Comm comm);

    /** The gap functionals of @p pairs on the free DoFs: hanging DoFs are
     *  expanded into their masters, fixed DoFs dropped; each rank keeps the
     *  entries on its owned DoFs. */
    void
    set_contact_pairs(const std::vector<ContactPair>  &pairs,
                      const AffineConstraints<double> &constraints,
                      const IndexSet                  &owned);

    void
    vmult(TrilinosWrappers::MPI::Vector &dst, const TrilinosWrappers::MPI::Vector &src) const;

  private:
    const TrilinosWrappers::SparseMatrix &K;
    MPI_Comm                              comm;
    std::vector<double>                   stiffness; ///< k_p [N/m]
    std::vector<unsigned int>             offsets;   ///< pair p: entries [offsets[p], offsets[p+1])
    std::vector<unsigned int>             local_index; ///< owned DoF, local numbering
    std::vector<double>                   coefficient; ///< d g_p / d u_dof
    mutable std::vector<double>           gaps;
  };
} // namespace WheelRail

#endif
