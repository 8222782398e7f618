// The rigid contact search of two profiles (geometry/profile_contact.h)
// against closed forms: a cylinder on the crown R 300 mm (the paper's pair), a
// cone 1:40 on the same crown, and a wheel of two arcs touching the crown at
// two points with equal separation, then with the second 20 um higher.
#include <wheelrail/geometry/profile_contact.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace WheelRail::Geometry;

namespace
{
  constexpr double rho = 0.3;  // the rail's crown radius [m]
  constexpr double R0  = 0.46; // the wheel's nominal radius [m]

  // a printed value [any unit]: 0 where it rounds to 0 at `digits` decimals (no "-0")
  double
  clean(const double value, const int digits)
  {
    return std::abs(value) < 0.5 * std::pow(10., -digits) ? 0. : value;
  }

  const char *
  ok(const bool good)
  {
    return good ? "yes" : "NO";
  }

  void
  print(const ProfileContactPoint &p)
  {
    std::printf("  y = %.6f mm, z = %.6f mm, d = %.6f um, normal d = %.6f um, delta = %.9f rad\n"
                "  r = %.6f mm, rail curvature %.6f 1/m, wheel curvature %.6f 1/m\n"
                "  A = %.6f 1/m, B = %.6f 1/m, lift = %.6f um\n",
                clean(p.y * 1e3, 6),
                clean(p.z * 1e3, 6),
                clean(p.separation * 1e6, 6),
                clean(p.normal_separation * 1e6, 6),
                clean(p.contact_angle, 9),
                p.rolling_radius * 1e3,
                clean(p.rail_curvature, 6),
                clean(p.wheel_curvature, 6),
                p.A,
                p.B,
                clean(p.lift * 1e6, 6));
  }

  // the wheel min(arc A + offset, arc B): two arcs of radius R convex upwards
  // with their tops at (-b, offset) and (b, 0) [m]; they meet in a ridge
  class TwoArcs : public ProfileCurve
  {
  public:
    TwoArcs(const double R, const double b, const double offset)
      : a(R, -b, offset, -0.03, 0.03)
      , c(R, b, 0, -0.03, 0.03)
    {}

    double
    z(const double y) const override
    {
      return std::min(a.z(y), c.z(y));
    }
    double
    slope(const double y) const override
    {
      return a.z(y) < c.z(y) ? a.slope(y) : c.slope(y);
    }
    double
    curvature_z(const double y) const override
    {
      return a.z(y) < c.z(y) ? a.curvature_z(y) : c.curvature_z(y);
    }
    double
    y_min() const override
    {
      return -0.03;
    }
    double
    y_max() const override
    {
      return 0.03;
    }
    std::string
    description() const override
    {
      return "two arcs";
    }

  private:
    const CircularProfile a, c;
  };
} // namespace

int
main()
{
  const CircularProfile rail(rho, 0, 0, -0.035, 0.035);

  // cylinder on the crown: one point at y = 0, A = 1/(2 R0), B = 1/(2 rho)
  const auto cylinder = rigid_contact(FlatProfile(-0.07, 0.07), rail, R0, 1e-3);
  std::printf("cylinder R 460 mm on the crown R 300 mm: %zu point(s)\n", cylinder.size());
  print(cylinder.at(0));
  std::printf("  y = 0, delta = 0 to 1e-9: %s; A = 1/(2 R0), B = 1/(2 rho) to 1e-12 1/m: %s\n",
              ok(std::abs(cylinder[0].y) < 1e-9 && std::abs(cylinder[0].contact_angle) < 1e-9),
              ok(std::abs(cylinder[0].A - 0.5 / R0) < 1e-12 &&
                 std::abs(cylinder[0].B - 0.5 / rho) < 1e-12));

  // cone 1:40 (z_w = y/40, a spline through 61 points) on the crown: the
  // slopes are equal where -y/sqrt(rho^2 - y^2) = 1/40, y* = -rho sin(delta),
  // delta = atan(1/40); the lift is rho (1/cos(delta) - 1); B = 1/(2 rho)
  std::vector<std::array<double, 2>> line;
  for (int k = 0; k <= 60; ++k)
    line.push_back({{-0.03 + 1e-3 * k, (-0.03 + 1e-3 * k) / 40}});
  const auto   cone  = SplineProfile::from_points(line, {}, "cone 1:40");
  const auto   coned = rigid_contact(*cone, rail, R0, 1e-3);
  const double delta = std::atan(1. / 40), y_star = -rho * std::sin(delta);
  const double lift = rho * (1 / std::cos(delta) - 1), r = R0 - y_star / 40;
  std::printf("cone 1:40 on the crown R 300 mm: %zu point(s)\n", coned.size());
  print(coned.at(0));
  std::printf("  expected y* = %.6f mm, delta = %.9f rad, lift = %.6f um, r = %.6f mm\n",
              y_star * 1e3,
              delta,
              lift * 1e6,
              r * 1e3);
  std::printf("  y to 1e-9 m, delta to 1e-9, lift to 1e-12 m, r to 1e-12 m: %s; B = 1/(2 rho), "
              "A = cos(delta)/(2 r) to 1e-9 1/m: %s\n",
              ok(std::abs(coned[0].y - y_star) < 1e-9 &&
                 std::abs(coned[0].contact_angle - delta) < 1e-9 &&
                 std::abs(coned[0].lift - lift) < 1e-12 &&
                 std::abs(coned[0].rolling_radius - r) < 1e-12),
              ok(std::abs(coned[0].B - 0.5 / rho) < 1e-9 &&
                 std::abs(coned[0].A - std::cos(delta) / (2 * r)) < 1e-9));

  // two arcs R 500 mm, tops at y = -+4 mm: the slopes match the crown's where
  // (y - -+b)/R = y/rho, y = -+b/(R/rho - 1) = -+6 mm; B = (1/rho - 1/R)/2
  const double R = 0.5, b = 0.004, y2 = b / (R / rho - 1);
  for (const double offset : {0., 20e-6})
    {
      auto two = rigid_contact(TwoArcs(R, b, offset), rail, R0, 50e-6);
      if (offset == 0) // equal separations: their order is rounding's, print by y
        std::sort(two.begin(), two.end(), [](auto &p, auto &q) { return p.y < q.y; });
      std::printf("two arcs R 500 mm, the right one %.0f um higher, on the crown: %zu point(s)\n",
                  offset * 1e6,
                  two.size());
      for (const auto &p : two)
        print(p);
      const auto &second = two.at(1);
      std::printf("  y = -+%.1f mm to 1e-9 m: %s; B = %.6f 1/m to 1e-9: %s; d of the second = "
                  "%.6f um to 1e-12 m: %s; normal d = d cos(delta) to 1e-12 m: %s\n",
                  y2 * 1e3,
                  ok(std::abs(two[0].y + y2) < 1e-9 && std::abs(second.y - y2) < 1e-9),
                  (1 / rho - 1 / R) / 2,
                  ok(std::abs(second.B - (1 / rho - 1 / R) / 2) < 1e-9),
                  clean(second.separation * 1e6, 6),
                  ok(std::abs(second.separation - offset) < 1e-12),
                  ok(std::abs(second.normal_separation - offset * std::cos(second.contact_angle)) <
                     1e-12));
    }
  const auto one = rigid_contact(TwoArcs(R, b, 20e-6), rail, R0, 10e-6);
  std::printf("the same with separations up to 10 um: %zu point(s)\n", one.size());
  return 0;
}
