/**
 * @file contact/face_normals.cc
 * What PenaltyContact knows of the master faces near a slave at the current
 * positions, computed at first use in each evaluation: the cheap bound of
 * a face's projections (FaceBound) and the averaged nodal normals.
 */

#include <deal.II/base/mpi.h>

#include <wheelrail/base/stopwatch.h>
#include <wheelrail/contact/bilinear_face.h>
#include <wheelrail/contact/penalty_contact.h>

#include <algorithm>
#include <cmath>

namespace WheelRail
{
  using namespace ContactGeometry;



  void
  PenaltyContact::compute_face_bound(Pass &pass, const unsigned int f)
  {
    FaceBound &bound         = pass.bounds[f];
    pass.bound_evaluation[f] = evaluation;
    // compute_slaves() uses a face's projection only if it lies within
    // |xi|, |eta| <= 1.1. A converged projection x_k of x_s is a point of
    // the face extended to 1.1, so |x_k - c| <= R (the extended face lies
    // in the convex hull of its corners x(+-1.1, +-1.1)), and x_s - x_k is
    // normal to the face there: x_s = x_k + t n, |t| <= |x_s - c| + R. The
    // normal x_xi x x_eta is affine in (xi, eta), a combination with
    // non-negative weights of its values at the extended corners, so it
    // lies within their largest angle a from the centre normal n_c. The
    // distance of x_s from the axis (c, n_c) is then at most
    // R + (|x_s - c| + R) sin a; a slave farther out cannot project within
    // 1.1. Faces that are not nearly flat (sin a > 0.1) are not bounded:
    // their projection is always computed. In closed form,
    // x = c + xi g1 + eta g2 + xi eta w and x_xi x x_eta = n0 + xi (g1 x w)
    // + eta (w x g2).
    constexpr double  e      = 1.1; // the extension
    const MasterFace &face   = pass.faces[f];
    FaceFrame        &frame  = pass.frames[f];
    frame                    = FaceFrame(node_x[face.node[0]],
                      node_x[face.node[1]],
                      node_x[face.node[2]],
                      node_x[face.node[3]]);
    bound.centre             = frame.centre;
    bound.sin_angle          = std::numeric_limits<double>::infinity();
    const Tensor<1, dim> &g1 = frame.g1, &g2 = frame.g2, &w = frame.w;
    const Tensor<1, dim>  n0     = cross_product_3d(g1, g2);
    const double          length = n0.norm();
    if (!(length > 0))
      return;
    bound.normal = n0 / length;
    // the normal's change across the face, and its part across n0
    const Tensor<1, dim> a = cross_product_3d(g1, w), b = cross_product_3d(w, g2);
    const Tensor<1, dim> at = cross_product_3d(a, bound.normal),
                         bt = cross_product_3d(b, bound.normal);
    const double an = a * bound.normal, bn = b * bound.normal;
    bound.radius     = 0;
    double sin_angle = 0;
    for (unsigned int v = 0; v < 4; ++v)
      {
        const double xi = (v & 1) ? e : -e, eta = (v & 2) ? e : -e;
        bound.radius       = std::max(bound.radius, (xi * g1 + eta * g2 + xi * eta * w).norm());
        const double along = length + xi * an + eta * bn; // m . n0 / |n0|
        if (!(along > 0))
          return;
        const double across = (xi * at + eta * bt).norm(); // |m x n0| / |n0|
        sin_angle = std::max(sin_angle, across / std::sqrt(along * along + across * across));
      }
    if (sin_angle <= 0.1)
      bound.sin_angle = sin_angle;
  }



  void
  PenaltyContact::compute_averaged_normal(const unsigned int n)
  {
    // Averaged nodal normals of the candidate master faces: the normal is
    // interpolated from them over a face, so that it, and the contact force,
    // are continuous when a slave passes from one face to its neighbour
    // (with face normals the force direction jumps at every edge). Summed
    // over the faces in ascending order, as one loop over all candidate
    // faces would: the same bits on every rank, whichever node it needs.
    Tensor<1, dim> &normal = node_normal[n];
    normal_evaluation[n]   = evaluation;
    normal                 = Tensor<1, dim>();
    for (unsigned int e = normal_offsets[n]; e < normal_offsets[n + 1]; ++e)
      {
        const NormalEntry &entry = normal_entries[e];
        const MasterFace  &face  = passes[entry.pass].faces[entry.face];
        BilinearFace       bf{{&node_x[face.node[0]],
                               &node_x[face.node[1]],
                               &node_x[face.node[2]],
                               &node_x[face.node[3]]}};
        Tensor<1, dim>     dxi, deta;
        bf.corner_tangents(entry.corner, dxi, deta);
        normal += face.sign * cross_product_3d(dxi, deta);
      }
    if (normal.norm() > 0)
      normal /= normal.norm();
  }



  void
  PenaltyContact::build_normal_adjacency()
  {
    normal_offsets.assign(node_dof.size() + 1, 0);
    for (const Pass &pass : passes)
      for (const unsigned int f : pass.candidate_faces)
        for (unsigned int v = 0; v < 4; ++v)
          ++normal_offsets[pass.faces[f].node[v] + 1];
    for (unsigned int n = 0; n < node_dof.size(); ++n)
      normal_offsets[n + 1] += normal_offsets[n];
    normal_entries.resize(normal_offsets.back());
    std::vector<unsigned int> next(normal_offsets.begin(), normal_offsets.end() - 1);
    for (unsigned int p = 0; p < passes.size(); ++p)
      for (const unsigned int f : passes[p].candidate_faces)
        for (unsigned int v = 0; v < 4; ++v)
          normal_entries[next[passes[p].faces[f].node[v]]++] = NormalEntry{p, f, v};
  }
} // namespace WheelRail
