// Reading profile files (geometry/profile.h): the formats (text, CSV with a
// header, CONTACT-like '%' comments, reversed order, z positive downwards),
// the window, the placement (mirror, rotation, shift), the interpolating spline
// against a sampled arc R 300 mm and the smoothing spline on noisy points.
#include <wheelrail/geometry/profile.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

using namespace WheelRail::Geometry;

namespace
{
  constexpr double rho = 0.3; // the arc's radius [m]

  // z [mm] of the arc R 300 mm with its top at (y0, 0) [mm]
  double
  arc_mm(const double y, const double y0 = 0)
  {
    return std::sqrt(300. * 300. - (y - y0) * (y - y0)) - 300.;
  }

  // the arc's points every 0.5 mm over [-30, 30] mm: "y<sep>z" lines
  std::string
  arc_lines(const char *separator, const bool descending, const double z_sign, const double y0 = 0)
  {
    std::string text;
    for (int k = 0; k <= 120; ++k)
      {
        const double y = descending ? 30. - 0.5 * k : -30. + 0.5 * k;
        char         line[80];
        std::snprintf(line, sizeof(line), "%.4f%s%.9f\n", y, separator, z_sign * arc_mm(y, y0));
        text += line;
      }
    return text;
  }

  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  // largest errors [m] of z over [a, b] [m], of the slope and d2z/dy2 `margin`
  // [m] inside, against `exact`
  void
  compare(const ProfileCurve    &p,
          const CircularProfile &exact,
          const double           a,
          const double           b,
          const double           margin)
  {
    double ez = 0, es = 0, ec = 0;
    for (double y = a; y <= b + 1e-12; y += 1e-5)
      {
        ez = std::max(ez, std::abs(p.z(y) - exact.z(y)));
        if (y > a + margin && y < b - margin) // the natural ends' s'' = 0 has decayed
          {
            es = std::max(es, std::abs(p.slope(y) - exact.slope(y)));
            ec = std::max(ec, std::abs(p.curvature_z(y) - exact.curvature_z(y)));
          }
      }
    std::printf("    |z - arc| < 1e-7 m: %s, |slope - arc| < 1e-8: %s, |z'' - arc| < 1e-4 1/m: "
                "%s\n",
                ez < 1e-7 ? "yes" : "NO",
                es < 1e-8 ? "yes" : "NO",
                ec < 1e-4 ? "yes" : "NO");
  }

  void
  read_arc(const std::string &file, const ProfileReadOptions &options)
  {
    const auto p = SplineProfile::read(file, options);
    std::printf("%s: %u knots, y from %.4f to %.4f mm\n",
                file.c_str(),
                p->n_knots(),
                p->y_min() * 1e3,
                p->y_max() * 1e3);
    const double margin = std::isnan(options.y_from) ? 5e-3 : 0.;
    std::printf("    slope and z'' checked %.0f mm from the ends\n", margin * 1e3);
    compare(*p, CircularProfile(rho, 0, 0, -0.03, 0.03), p->y_min(), p->y_max(), margin);
  }
} // namespace

int
main()
{
  ProfileReadOptions options;
  options.parameter = "Geometry/Rail/Profile file";

  write("arc.txt", "# arc R 300 mm, every 0.5 mm\nY [mm] Z [mm]\n" + arc_lines(" ", false, 1));
  write("arc.csv", "y,z\n" + arc_lines(",", false, 1));
  write("arc.prr", "% CONTACT-like profile\n% y [mm]   z [mm]\n\n" + arc_lines("\t", false, 1));
  write("arc_reversed.txt", arc_lines(";", true, 1));
  write("arc_down.prr", "% z positive downwards\n" + arc_lines("  ", false, -1));
  for (const char *file : {"arc.txt", "arc.csv", "arc.prr", "arc_reversed.txt"})
    read_arc(file, options);
  options.z_down = true;
  read_arc("arc_down.prr", options);
  options.z_down = false;

  // a window: the knots are its points and the next point beyond an end
  options.y_from = -0.02;
  options.y_to   = 0.02025;
  read_arc("arc.txt", options);
  options.y_from = options.y_to = std::nan("");

  // mirror, rotation 1:40 and shift: the arc with its top at y = 5 mm moves
  // its centre (5, -300) mm to (-5, -300), rotated, then shifted (1, 2) mm
  write("arc_5.txt", arc_lines(" ", false, 1, 5.));
  options.mirror   = true;
  options.rotation = std::atan(1. / 40);
  options.shift_y  = 1e-3;
  options.shift_z  = 2e-3;
  const double c = std::cos(options.rotation), s = std::sin(options.rotation);
  const double yc = c * -5e-3 - s * -rho + 1e-3, zc = s * -5e-3 + c * -rho + 2e-3;
  const auto   placed = SplineProfile::read("arc_5.txt", options);
  std::printf("arc_5.txt mirrored, rotated by atan(1/40), shifted (1, 2) mm: top of the "
              "circle expected at y = %.4f mm, z = %.4f mm\n",
              yc * 1e3,
              (zc + rho) * 1e3);
  compare(*placed,
          CircularProfile(rho, yc, zc + rho, placed->y_min(), placed->y_max()),
          placed->y_min() + 1e-3,
          placed->y_max() - 1e-3,
          5e-3);
  options = ProfileReadOptions{"Geometry/Rail/Profile file"};

  // from_points: the same arc, in m
  std::vector<std::array<double, 2>> points;
  for (int k = 0; k <= 120; ++k)
    points.push_back({{-0.03 + 5e-4 * k, 1e-3 * arc_mm(-30. + 0.5 * k)}});
  const auto from_points = SplineProfile::from_points(points, options, "arc points");
  const auto from_file   = SplineProfile::read("arc.txt", options);
  double     difference  = 0;
  for (double y = -0.03; y <= 0.03; y += 1e-5)
    difference = std::max(difference, std::abs(from_points->z(y) - from_file->z(y)));
  std::printf("from_points = the file's spline to 1e-11 m: %s\n",
              difference < 1e-11 ? "yes" : "NO");

  // the smoothing spline on the arc with uniform noise of +-0.0173 mm (RMS 0.01 mm) (mt19937's
  // raw numbers, the same on every platform)
  std::mt19937 random(2024);
  std::string  noisy;
  for (int k = 0; k <= 120; ++k)
    {
      const double y = -30. + 0.5 * k, noise = 0.0346 * (random() / 4294967296. - 0.5);
      char         line[80];
      std::snprintf(line, sizeof(line), "%.4f %.9f\n", y, arc_mm(y) + noise);
      noisy += line;
    }
  write("arc_noisy.txt", noisy);
  options.smoothing_tolerance = 1e-5;
  const auto smooth           = SplineProfile::read("arc_noisy.txt", options);
  const auto exact            = CircularProfile(rho, 0, 0, -0.03, 0.03);
  double     error            = 0;
  for (double y = -0.025; y <= 0.025; y += 1e-5)
    error = std::max(error, std::abs(smooth->z(y) - exact.z(y)));
  std::printf("smoothing to 0.01 mm: RMS deviation %.4f mm (within 1 %%: %s), largest %.3f mm, "
              "|s - arc| < 0.01 mm 5 mm from the ends: %s\n",
              smooth->rms_deviation() * 1e3,
              std::abs(smooth->rms_deviation() / 1e-5 - 1) < 0.01 ? "yes" : "NO",
              smooth->max_deviation() * 1e3,
              error < 1e-5 ? "yes" : "NO");
  options.smoothing_tolerance = 0;

  // CircularProfile and the paper's crown as the rail chart computed it
  // before profiles: the same to rounding (a compiler may fuse the
  // multiply-adds differently in the two places)
  const CircularProfile circle(rho, 0, 0, -0.04, 0.04);
  double                largest = 0;
  for (int k = -1000; k <= 1000; ++k)
    {
      const double y = 4e-5 * k;
      largest = std::max(largest, std::abs(circle.z(y) - (std::sqrt(rho * rho - y * y) - rho)));
    }
  std::printf("CircularProfile R 300 mm and sqrt(rho^2 - y^2) - rho on 2001 points: largest "
              "difference below 1e-15 m: %s\n",
              largest < 1e-15 ? "yes" : "NO");
  return 0;
}
