// Profile files that must be refused (geometry/profile.h), each with its
// message: the file, the line, what is wrong and the entry that asked for it.
#include <wheelrail/geometry/profile.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace WheelRail::Geometry;

namespace
{
  // "y z" lines [mm] of the arc R 300 mm every `step` mm from y0 to y1
  std::string
  arc(const double y0, const double y1, const double step = 0.5)
  {
    std::string text;
    for (double y = y0; y <= y1 + 1e-9; y += step)
      {
        char line[80];
        std::snprintf(line, sizeof(line), "%.4f %.9f\n", y, std::sqrt(9e4 - y * y) - 300.);
        text += line;
      }
    return text;
  }

  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  void
  expect_failure(const std::string        &title,
                 const std::string        &file,
                 const ProfileReadOptions &options)
  {
    try
      {
        SplineProfile::read(file, options);
        std::printf("%s: accepted, WRONG\n", title.c_str());
      }
    catch (const std::runtime_error &e)
      {
        std::printf("%s:\n  %s\n", title.c_str(), e.what());
      }
  }
} // namespace

int
main()
{
  ProfileReadOptions options;
  options.parameter = "Geometry/Rail/Profile file";

  expect_failure("missing file", "no_such_profile.txt", options);
  std::filesystem::create_directory("profile_folder");
  expect_failure("a directory", "profile_folder", options);
  expect_failure("no file name", "", options);
  write("comments_only.prr", "% a CONTACT-like header\n%\n\n");
  expect_failure("no points", "comments_only.prr", options);

  write("one_number.txt", arc(-10, -5) + "3.0\n" + arc(-4.5, 0));
  expect_failure("one number on a line", "one_number.txt", options);
  write("three_numbers.csv", "y,z\n" + arc(-10, -5) + "3.0,1.0,2.0\n");
  expect_failure("three numbers on a line", "three_numbers.csv", options);
  write("word.txt", arc(-10, -5) + "-4.5 abc\n");
  expect_failure("a word", "word.txt", options);
  write("late_header.txt", arc(-10, -5) + "y z\n" + arc(-4.5, 0));
  expect_failure("a header after the data", "late_header.txt", options);
  write("nan.txt", arc(-10, -5) + "nan 1.0\n");
  expect_failure("NaN", "nan.txt", options);
  write("inf.txt", arc(-10, -5) + "-4.5 -inf\n");
  expect_failure("inf", "inf.txt", options);
  write("decimal_comma.txt", "-10,0 -0,167\n");
  expect_failure("decimal comma, space separated", "decimal_comma.txt", options);
  write("decimal_comma.csv", "y;z\n-10,0;-0,167\n");
  expect_failure("decimal comma, semicolon separated", "decimal_comma.csv", options);

  write("five_points.txt", arc(-1, 1));
  expect_failure("fewer than 10 points", "five_points.txt", options);
  write("duplicate.txt", arc(-10, -5) + arc(-5, 0));
  expect_failure("duplicate consecutive points", "duplicate.txt", options);
  // a loop: along the arc, then down, back to the left and up across it
  write("loop.txt", arc(-10, 0) + "0.5 -2\n-5 -2\n-5.2 1\n");
  expect_failure("self-intersection", "loop.txt", options);
  write("fold.txt", arc(-10, 0) + "-0.5 -0.000416667\n");
  expect_failure("folding back", "fold.txt", options);
  // a flange: y turns back below the tread without crossing it
  write("flange.txt", arc(-10, 0) + "-0.5 -3\n-1 -6\n-1.5 -9\n");
  expect_failure("not single-valued in y", "flange.txt", options);

  write("arc.txt", arc(-30, 30));
  options.max_spacing = 0.4e-3;
  expect_failure("spacing above the largest", "arc.txt", options);
  options.max_spacing = 0;
  options.y_from      = -0.04;
  options.y_to        = 0.01;
  expect_failure("window not covered", "arc.txt", options);
  options.y_from = 0.02;
  options.y_to   = 0.024;
  expect_failure("fewer than 10 points in the window", "arc.txt", options);
  options.y_from = 0.04;
  options.y_to   = 0.05;
  expect_failure("no point in the window", "arc.txt", options);
  options.y_from = 0.01;
  options.y_to   = -0.01;
  expect_failure("an empty window", "arc.txt", options);
  options.y_from = options.y_to = std::nan("");
  options.smoothing_tolerance   = -1e-5;
  expect_failure("a negative smoothing tolerance", "arc.txt", options);
  options.smoothing_tolerance = 0;

  // from_points names its points by their number
  std::vector<std::array<double, 2>> points;
  for (int k = 0; k < 12; ++k)
    points.push_back({{1e-3 * (k < 6 ? k : 10 - k), 1e-3 * k}});
  try
    {
      SplineProfile::from_points(points, options, "wheel points");
    }
  catch (const std::runtime_error &e)
    {
      std::printf("from_points, turning back:\n  %s\n", e.what());
    }
  return 0;
}
