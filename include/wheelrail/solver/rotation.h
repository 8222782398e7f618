/**
 * @file rotation.h
 * The rotation about the axle (y) of the wheel's rigid motions.
 */
#ifndef wheelrail_solver_rotation_h
#define wheelrail_solver_rotation_h

#include <deal.II/base/tensor.h>

#include <wheelrail/parameters/parameters.h>

namespace WheelRail
{
  /** @p r rotated about +y by the angle whose cosine and sine are @p c
   *  and @p s (computed once for many vectors). */
  inline Tensor<1, dim>
  rotate_about_y(const Tensor<1, dim> &r, const double c, const double s)
  {
    return Tensor<1, dim>({c * r[0] + s * r[2], r[1], -s * r[0] + c * r[2]});
  }
} // namespace WheelRail

#endif
