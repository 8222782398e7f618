// Unit test of the closest-point projection onto a bilinear master face
// (ContactGeometry::FaceFrame): faces of 0.33 mm on a wheel-like surface
// (radii 0.46 m and 0.3 m) with their corners jittered, slaves up to three
// face sizes aside and 0.4 mm (the search margin) off the surface.
//  - the closed form x = c + xi g1 + eta g2 + xi eta w is the surface of the
//    shape functions (BilinearFace::evaluate);
//  - a converged projection is a closest point: x_s - x is normal to both
//    tangents there (its tangential part below 1e-10 h);
//  - the early stop (wanted_out = 0.1) never changes the caller's decision:
//    where it stops, the full iteration ends beyond 1.1 too, and where it
//    does not, both give the same bits.
#include <wheelrail/contact/bilinear_face.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace WheelRail;
using namespace WheelRail::ContactGeometry;

namespace
{
  /** A point of a torus-like surface: radius R along x, r across y. */
  Point<dim>
  surface(const double x, const double y)
  {
    const double R = 0.46, r = 0.3;
    return Point<dim>(x, y, R - std::sqrt(R * R - x * x) + r - std::sqrt(r * r - y * y));
  }
} // namespace

int
main()
{
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> u(-1., 1.);
  const double                           h = 3.3e-4;

  double             surface_error = 0, normal_error = 0;
  unsigned int       converged = 0, used = 0, stopped = 0, wrong_stop = 0, changed = 0;
  const unsigned int n = 200000;
  for (unsigned int i = 0; i < n; ++i)
    {
      // a face near (x0, y0) with corners moved by up to 10 % of h
      const double x0 = 0.02 * u(random), y0 = 0.01 * u(random);
      Point<dim>   p[4];
      for (unsigned int v = 0; v < 4; ++v)
        p[v] = surface(x0 + ((v & 1) ? h : 0.) + 0.1 * h * u(random),
                       y0 + ((v & 2) ? h : 0.) + 0.1 * h * u(random));
      const BilinearFace bf{{&p[0], &p[1], &p[2], &p[3]}};
      const FaceFrame    frame(bf);

      // the closed form against the shape functions
      {
        const double   xi = u(random), eta = u(random);
        Point<dim>     x;
        Tensor<1, dim> dxi, deta;
        double         N[4];
        bf.evaluate(xi, eta, x, dxi, deta, N);
        const Point<dim> y = frame.centre + xi * frame.g1 + eta * frame.g2 + (xi * eta) * frame.w;
        surface_error      = std::max(surface_error, x.distance(y) / std::max(x.norm(), h));
      }

      // a slave up to 3 h aside (in face coordinates) and 0.4 mm off
      const double     sx = 3. * u(random), sy = 3. * u(random);
      const Point<dim> on = surface(x0 + 0.5 * h * (1 + sx), y0 + 0.5 * h * (1 + sy));
      const Point<dim> xs = on + Tensor<1, dim>({0., 0., 4e-4 * u(random)});

      double xi, eta, xi_e, eta_e;
      frame.project(xs, xi, eta);
      frame.project(xs, xi_e, eta_e, 0.1);
      const double out   = std::max(std::abs(xi), std::abs(eta)) - 1.;
      const double out_e = std::max(std::abs(xi_e), std::abs(eta_e)) - 1.;

      if (std::max(std::abs(xi), std::abs(eta)) < 3.)
        {
          ++converged;
          Point<dim>     x;
          Tensor<1, dim> dxi, deta;
          double         N[4];
          bf.evaluate(xi, eta, x, dxi, deta, N);
          const Tensor<1, dim> r = xs - x;
          normal_error           = std::max({normal_error,
                                             std::abs(r * dxi) / (h * dxi.norm()),
                                             std::abs(r * deta) / (h * deta.norm())});
        }
      if (out <= 0.1)
        ++used;
      if (xi_e != xi || eta_e != eta)
        {
          ++stopped;
          if (!(out > 0.1) || !(out_e > 0.1))
            ++wrong_stop;
        }
      else if (out_e != out)
        ++changed;
    }

  std::printf("%u faces and slaves\n", n);
  std::printf("closed form against the shape functions: largest |x - x_N| / max(|x|, h) %s 1e-14\n",
              surface_error < 1e-14 ? "<" : ">=");
  std::printf("converged projections: %.2f of all; largest tangential part of x_s - x, over h, "
              "%s 1e-10\n",
              double(converged) / n,
              normal_error < 1e-10 ? "<" : ">=");
  std::printf("projections within 1.1 (used): %.2f of all; stopped early: %.2f of all\n",
              double(used) / n,
              double(stopped) / n);
  std::printf("early stops within 1.1 by either iteration: %u\n", wrong_stop);
  std::printf("projections not stopped early that differ: %u\n", changed);
  return (surface_error < 1e-14 && normal_error < 1e-10 && wrong_stop == 0 && changed == 0) ? 0 : 1;
}
