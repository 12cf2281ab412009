// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The checked reading of input files (CGAL/Lex_optimal_chains/IO/input_files.h): what CGAL's
// readers accept is read as they read it, and what they would read in part (a header that
// declares fewer points than the file holds) or not at all is refused with a typed error
// naming the file, the line or the token.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Lex_optimal_chains/IO/input_files.h>

#include <unistd.h>

#include <cassert>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
namespace LOC = CGAL::Lex_optimal_chains;
namespace fs = std::filesystem;

const fs::path directory = fs::temp_directory_path() / ("lex_input_files_" + std::to_string(::getpid()));

std::string file(const std::string& name, const std::string& content)
{
  const fs::path path = directory / name;
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

template <class F>
void expect_unreadable(const F& f, const std::string& part_of_message)
{
  try { f(); }
  catch(const LOC::Input_error& e) {
    std::cout << "  expected error: " << e.what() << std::endl;
    assert(e.code() == LOC::Input_error_code::UNREADABLE_FILE);
    assert(std::string(e.what()).find(part_of_message) != std::string::npos);
    return;
  }
  assert(!"an Input_error was expected");
}

std::size_t cgal_count(const std::string& path)
{
  std::vector<Point> points;
  std::cerr.setstate(std::ios::failbit); // CGAL's diagnostics
  CGAL::IO::read_points(path, std::back_inserter(points));
  std::cerr.clear();
  return points.size();
}

std::string binary_ply(std::size_t declared, const std::vector<Point>& points)
{
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(declared) +
                  "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  for(const Point& p : points)
    for(double c : {p.x(), p.y(), p.z()}) {
      char bytes[8];
      std::memcpy(bytes, &c, 8); // the machines of the test suite are little-endian
      s.append(bytes, 8);
    }
  return s;
}

void test_point_files()
{
  // accepted, as CGAL reads them
  const std::string xyz = file("ok.xyz", "0 0 0\n1 0 0\n0 1 0\n\n0 0 1\n");
  assert(LOC::IO::read_point_file<Point>(xyz).size() == 4 && cgal_count(xyz) == 4);
  const std::string upper = file("ok.XYZ", "0 0 0\n1 0 0\n");
  assert(LOC::IO::read_point_file<Point>(upper).size() == 2);
  const std::string off = file("ok.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n# a comment\n0 1 0\n");
  assert(LOC::IO::read_point_file<Point>(off).size() == 3);
  const std::vector<Point> three{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  const std::string ply = file("ok.ply", binary_ply(3, three));
  assert(LOC::IO::read_point_file<Point>(ply) == three);

  // files that CGAL reads in part: the check is what refuses them
  const std::string short_off = file("short.off", "OFF\n2 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  assert(cgal_count(short_off) == 2);
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(short_off); }, "more records than its header declares");
  const std::string short_ascii_ply =
    file("short_ascii.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
                            "property double z\nend_header\n0 0 0\n1 0 0\n0 1 0\n");
  assert(cgal_count(short_ascii_ply) == 2);
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(short_ascii_ply); }, "2 vertex");
  const std::string short_binary_ply = file("short_binary.ply", binary_ply(2, three));
  assert(cgal_count(short_binary_ply) == 2);
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(short_binary_ply); }, "48 bytes, against 72");

  // not read at all
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("points.txt", "0 0 0\n")); }, "must end in .xyz, .ply or .off");
  expect_unreadable([&] { LOC::IO::read_point_file<Point>((directory / "missing.xyz").string()); }, "cannot open input");
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(directory.string() + "/.xyz"); }, "must end in"); // a hidden file named xyz
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("garbage.off", "not an off file\n1 2\n")); },
                    "cannot read points");
}

void test_polyline_files()
{
  const auto polylines = LOC::IO::read_polyline_file<Point>(
    file("ok.polylines.txt", "4 0 0 0 1 0 0 0 1 0 0 0 0\n\n   \n3 5 5 5 6 5 5 5 5 5\n"));
  assert(polylines.size() == 2 && polylines[0].size() == 4 && polylines[1].size() == 3);
  assert(polylines[0][1] == Point(1, 0, 0) && polylines[1].back() == Point(5, 5, 5));
  assert(LOC::IO::read_polyline_file<Point>(file("empty.polylines.txt", "")).empty());

  expect_unreadable([&] { LOC::IO::read_polyline_file<Point>(file("a.txt", "2 0 0 0 1 1 1\nx 0 0 0\n")); },
                    "line 2 of");
  expect_unreadable([&] { LOC::IO::read_polyline_file<Point>(file("b.txt", "2.5 0 0 0 1 1 1\n")); },
                    "whole number of points");
  expect_unreadable([&] { LOC::IO::read_polyline_file<Point>(file("c.txt", "3 0 0 0 1 1 1\n")); },
                    "announces 3 points (9 coordinates) but has 6 coordinates");
  expect_unreadable([&] { LOC::IO::read_polyline_file<Point>(file("d.txt", "2 0 0 0 1 nan 1\n")); },
                    "coordinate 'nan' of point 2 is not a finite number");
  expect_unreadable([&] { LOC::IO::read_polyline_file<Point>(file("e.txt", "2 0 0 0 1 1e999 1\n")); },
                    "is not a finite number");
  expect_unreadable([&] { LOC::IO::read_polyline_file<Point>(file("f.txt", "-1\n")); }, "bad number of points");
  expect_unreadable([&] { LOC::IO::read_polyline_file<Point>((directory / "missing.txt").string()); },
                    "cannot open boundary file");
}

// A real scan: the same points as CGAL's reader.
void test_real_data(const std::string& data)
{
  for(const char* name : {"points_3/kitten.xyz", "points_3/b9_training.ply"}) {
    const std::string path = data + "/" + name;
    if(!fs::exists(path)) {
      std::cout << "  " << path << " not found: skipped\n";
      continue;
    }
    const std::vector<Point> points = LOC::IO::read_point_file<Point>(path);
    std::cout << "  " << name << ": " << points.size() << " points\n";
    assert(!points.empty() && points.size() == cgal_count(path));
  }
}

int main(int argc, char** argv)
{
  fs::create_directories(directory);
  test_point_files();
  test_polyline_files();
  if(argc > 1) test_real_data(argv[1]);
  fs::remove_all(directory);
  std::cout << "OK\n";
  return 0;
}
