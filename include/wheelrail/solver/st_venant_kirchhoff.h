/**
 * @file st_venant_kirchhoff.h
 * The St. Venant-Kirchhoff law of SPEC 2 on deal.II tensors: Green-Lagrange
 * strain E = (F^T F - I) / 2 and second Piola-Kirchhoff stress
 * S = lambda tr(E) I + 2 mu E. Used for the cell stresses of the output and
 * for the exact stress of the patch test. The element kernel
 * (element_kernel.h) and the strain energies evaluate the same law from
 * H = grad u in their own unrolled form, E = (H + H^T + H^T H) / 2, whose
 * rounding differs from this one.
 */
#ifndef wheelrail_solver_st_venant_kirchhoff_h
#define wheelrail_solver_st_venant_kirchhoff_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <wheelrail/parameters/parameters.h>

namespace WheelRail
{
  namespace StVenantKirchhoff
  {
    /** E = (F^T F - I) / 2 of the deformation gradient @p F. */
    inline __attribute__((always_inline)) Tensor<2, dim>
    green_lagrange_strain(const Tensor<2, dim> &F)
    {
      return 0.5 * (transpose(F) * F - unit_symmetric_tensor<dim>());
    }

    /** S = lambda tr(E) I + 2 mu E. */
    inline __attribute__((always_inline)) Tensor<2, dim>
    second_piola_kirchhoff_stress(const Tensor<2, dim> &E, const double lambda, const double mu)
    {
      return lambda * trace(E) * Tensor<2, dim>(unit_symmetric_tensor<dim>()) + 2. * mu * E;
    }
  } // namespace StVenantKirchhoff
} // namespace WheelRail

#endif
