/**
 * @file contact/bilinear_face.h
 * The geometry of a master face of the contact (SPEC 4): the bilinear
 * surface x(xi, eta) through its four corners, its shape functions, tangents
 * and the closest-point projection of a slave node onto it.
 */
#ifndef wheelrail_contact_bilinear_face_h
#define wheelrail_contact_bilinear_face_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <wheelrail/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace WheelRail
{
  namespace ContactGeometry
  {
    /** Order of points by x, then y, then z. */
    inline bool
    lexicographic_less(const Point<dim> &a, const Point<dim> &b)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    }

    /** Bilinear face x(xi, eta) on corners p[0..3] (lexicographic). */
    struct BilinearFace
    {
      const Point<dim> *p[4];

      void
      evaluate(const double    xi,
               const double    eta,
               Point<dim>     &x,
               Tensor<1, dim> &dxi,
               Tensor<1, dim> &deta,
               double          N[4]) const
      {
        shape(xi, eta, N);
        x = Point<dim>();
        for (unsigned int j = 0; j < 4; ++j)
          x += N[j] * (*p[j]);
        dxi  = 0.25 * ((1 - eta) * (*p[1] - *p[0]) + (1 + eta) * (*p[3] - *p[2]));
        deta = 0.25 * ((1 - xi) * (*p[2] - *p[0]) + (1 + xi) * (*p[3] - *p[1]));
      }

      /** The tangents x_xi, x_eta at corner v, as evaluate() gives them
       *  there (bit for bit: the other edge's weight is exactly 0). */
      void
      corner_tangents(const unsigned int v, Tensor<1, dim> &dxi, Tensor<1, dim> &deta) const
      {
        dxi  = (v & 2) ? 0.5 * (*p[3] - *p[2]) : 0.5 * (*p[1] - *p[0]);
        deta = (v & 1) ? 0.5 * (*p[3] - *p[1]) : 0.5 * (*p[2] - *p[0]);
      }

      /** Shape functions at (xi, eta), as evaluate() gives them. */
      static void
      shape(const double xi, const double eta, double N[4])
      {
        N[0] = 0.25 * (1 - xi) * (1 - eta);
        N[1] = 0.25 * (1 + xi) * (1 - eta);
        N[2] = 0.25 * (1 - xi) * (1 + eta);
        N[3] = 0.25 * (1 + xi) * (1 + eta);
      }

      /**
       * For a projection (xi, eta) outside the face: the closest point on
       * the face's boundary. The edges of a bilinear face are straight, so
       * this is the closest point on a segment; two faces sharing the edge
       * give the same point (clamping the coordinates does not, and the
       * difference showed up as micro-slip of 1-2 m/s at nodes rolling along
       * a mesh line).
       */
      void
      project_to_boundary(const Point<dim> &xs, double &xi, double &eta) const
      {
        // edges as (corner a, corner b, fixed coordinate, value)
        const unsigned int edges[4][2] = {{0, 2}, {1, 3}, {0, 1}, {2, 3}};
        double             best        = std::numeric_limits<double>::max();
        double             bx = 0, be = 0;
        for (unsigned int e = 0; e < 4; ++e)
          {
            const Point<dim>    &a = *p[edges[e][0]], &b = *p[edges[e][1]];
            const Tensor<1, dim> ab = b - a;
            const double         t  = std::clamp(((xs - a) * ab) / ab.norm_square(), 0., 1.);
            const double         d2 = (a + t * ab).distance_square(xs);
            if (d2 < best)
              {
                best = d2;
                // xi = -1 edge (0-2), xi = 1 edge (1-3): t runs along eta;
                // eta = -1 edge (0-1), eta = 1 edge (2-3): t runs along xi
                if (e < 2)
                  {
                    bx = (e == 0) ? -1. : 1.;
                    be = 2. * t - 1.;
                  }
                else
                  {
                    bx = 2. * t - 1.;
                    be = (e == 2) ? -1. : 1.;
                  }
              }
          }
        xi  = bx;
        eta = be;
      }

      /** Closest point by Newton (Gauss-Newton) in the face coordinates
       *  (FaceFrame::project()). */
      void
      project(const Point<dim> &xs, double &xi, double &eta) const;
    };



    /**
     * A bilinear face in closed form, x(xi, eta) = c + xi g1 + eta g2 +
     * xi eta w (the same surface as BilinearFace's sum of shape functions),
     * for the closest-point projection: its Newton iterations need no
     * corner lookups.
     */
    struct FaceFrame
    {
      Point<dim>     centre;
      Tensor<1, dim> g1, g2, w;

      FaceFrame() = default;

      FaceFrame(const Point<dim> &p0,
                const Point<dim> &p1,
                const Point<dim> &p2,
                const Point<dim> &p3)
        : centre(0.25 * (p0 + p1 + p2 + p3))
        , g1(0.25 * ((p1 - p0) + (p3 - p2)))
        , g2(0.25 * ((p2 - p0) + (p3 - p1)))
        , w(0.25 * ((p0 - p1) + (p3 - p2)))
      {}

      explicit FaceFrame(const BilinearFace &f)
        : FaceFrame(*f.p[0], *f.p[1], *f.p[2], *f.p[3])
      {}

      /**
       * Closest point of @p xs by Gauss-Newton from the face centre, to a
       * step below 1e-13 in (xi, eta). The callers use a projection only
       * within max(|xi|, |eta|) <= 1 + @p wanted_out; with a finite @p
       * wanted_out the iteration stops early once the iterate lies beyond
       * it by more than twice its last step (from the second step on).
       * Gauss-Newton contracts the error by |r| |w| / |g|^2 per step, small
       * on the nearly flat faces this is used for (FaceBound::usable()), so
       * the converged point lies beyond as well and the caller's decision
       * is the same.
       */
      void
      project(const Point<dim> &xs,
              double           &xi,
              double           &eta,
              const double      wanted_out = std::numeric_limits<double>::infinity()) const
      {
        xi = eta                         = 0;
        const Tensor<1, dim> d           = xs - centre;
        bool                 was_clamped = false;
        for (unsigned int it = 0; it < 20; ++it)
          {
            const Tensor<1, dim> dxi  = g1 + eta * w;
            const Tensor<1, dim> deta = g2 + xi * w;
            const Tensor<1, dim> r    = xi * g1 + eta * g2 + (xi * eta) * w - d;
            const double         a11 = dxi * dxi, a12 = dxi * deta, a22 = deta * deta;
            const double         b1 = dxi * r, b2 = deta * r;
            const double         det = a11 * a22 - a12 * a12;
            if (!(det > 0))
              break;
            const double dx      = -(a22 * b1 - a12 * b2) / det;
            const double de      = -(a11 * b2 - a12 * b1) / det;
            const bool   clamped = std::abs(xi + dx) > 3. || std::abs(eta + de) > 3.;
            xi                   = std::clamp(xi + dx, -3., 3.);
            eta                  = std::clamp(eta + de, -3., 3.);
            const double step    = std::abs(dx) + std::abs(de);
            if (step < 1e-13)
              break;
            if (it > 0 && !clamped &&
                std::max(std::abs(xi), std::abs(eta)) - 1. - 2. * step > wanted_out)
              break;
            // the closest point lies far outside the face (beyond the
            // clamp twice in a row): the callers only use projections
            // within 1.1, and iterating on (the clamp stops Newton from
            // converging) would take all 20 iterations
            if (clamped && was_clamped)
              break;
            was_clamped = clamped;
          }
      }
    };



    inline void
    BilinearFace::project(const Point<dim> &xs, double &xi, double &eta) const
    {
      FaceFrame(*this).project(xs, xi, eta);
    }
  } // namespace ContactGeometry
} // namespace WheelRail

#endif
