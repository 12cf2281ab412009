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

#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
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

  // PLY files that CGAL's reader cannot read safely (internal/PLY_structure_check.h); fuzz_point_file
  // found the first (a property taken for one of the last of no element), the int coordinate and
  // the names given twice
  const std::string ascii_header = "ply\nformat ascii 1.0\n";
  struct Refused_header { const char* file; const char* after_format; const char* reason; };
  const Refused_header refused_headers[] = {
    {"property_first.ply", "property float x\nelement vertex 1\nproperty float y\nproperty float z\nend_header\n0 0\n",
     "a property before any element"},
    {"no_property.ply", "element vertex 3\nelement face 1000\nend_header\n", "has no property"},
    {"huge_count.ply", "element vertex 4000000000\nproperty double x\nproperty double y\nproperty double z\nend_header\n0 0 0\n",
     "cannot hold the 4000000000 items declared"},
    {"negative_count.ply", "element vertex -1\nproperty double x\nend_header\n", "is not a whole number"},
    {"int_coordinate.ply", "element vertex 1\nproperty float x\nproperty int y\nproperty float z\nend_header\n0 0 0\n",
     "the point coordinate 'y' is not a float or a double"},
    {"one_name_twice.ply",
     "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty uint c\nproperty ushort c\n"
     "end_header\n0 0 0 1 1\n",
     "a second property named 'c' in one element"},
    {"element_twice.ply", "element vertex 1\nproperty float x\nelement vertex 1\nproperty int x\nend_header\n0\n0\n",
     "a second element named 'vertex'"}};
  for(const Refused_header& r : refused_headers)
    expect_unreadable([&] { LOC::IO::read_point_file<Point>(file(r.file, ascii_header + r.after_format)); }, r.reason);
  const std::string faces = ascii_header + "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                            "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  assert(LOC::IO::read_point_file<Point>(file("faces.ply", faces + "3 0 1 2\n")).size() == 3);
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("long_list.ply", faces + "4000000000 0 1 2\n")); },
                    "a list of 4000000000 values is longer than the rest of the file");
  std::string binary_faces = "ply\nformat binary_little_endian 1.0\nelement face 1\nproperty list uint int vertex_indices\n"
                             "end_header\n";
  binary_faces += std::string("\xff\xff\xff\xff", 4) + std::string(12, '\0');
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("long_binary_list.ply", binary_faces)); },
                    "a list of 4294967295 values is longer than the rest of the file");
  // data that ends within a point (a file cut short), before its list: CGAL's reader fails
  std::string cut_short = "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
                          "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  cut_short += std::string(26, '\0');
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("cut_short.ply", cut_short)); }, "cannot read points");

  // not read at all
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("points.txt", "0 0 0\n")); }, "must end in .xyz, .pwn, .ply, .off or .las");
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
  for(const char* name : {"points_3/kitten.xyz", "points_3/b9_training.ply", "points_3/cube.pwn"}) {
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

// An uncompressed LAS file written here, as the specification lays it out (little-endian):
// version 1.`minor`, point data record format `format`, the points as integers of scale
// `scale` and offset `offset`, each with its classification; `declared` points in the header.
std::string las_file(const std::string& name, unsigned minor, unsigned format, const std::vector<Point>& points,
                     const std::vector<int>& classes, double scale, const std::array<double, 3>& offset,
                     std::size_t declared)
{
  const std::uint16_t lengths[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  const std::uint16_t header_size = minor >= 4 ? 375 : 227, record = lengths[format];
  std::vector<unsigned char> bytes(header_size, 0);
  auto put = [&](std::size_t at, const void* value, std::size_t size) { std::memcpy(&bytes[at], value, size); };
  std::memcpy(bytes.data(), "LASF", 4);
  bytes[24] = 1;
  bytes[25] = std::uint8_t(minor);
  put(94, &header_size, 2);
  const std::uint32_t offset_to_points = header_size;
  put(96, &offset_to_points, 4);
  bytes[104] = std::uint8_t(format);
  put(105, &record, 2);
  const std::uint32_t legacy = minor >= 4 ? 0 : std::uint32_t(declared);
  put(107, &legacy, 4);
  for(int c = 0; c < 3; ++c) {
    put(131 + 8 * c, &scale, 8);
    put(155 + 8 * c, &offset[c], 8);
  }
  if(minor >= 4) {
    const std::uint64_t count = declared;
    put(247, &count, 8);
  }
  for(std::size_t i = 0; i < points.size(); ++i) {
    std::vector<unsigned char> r(record, 0);
    const double xyz[3] = {points[i].x(), points[i].y(), points[i].z()};
    for(int c = 0; c < 3; ++c) {
      const std::int32_t v = std::int32_t(std::lround((xyz[c] - offset[c]) / scale));
      std::memcpy(&r[4 * c], &v, 4);
    }
    r[format <= 5 ? 15 : 16] = std::uint8_t(classes[i] | (format <= 5 ? 0x20 : 0)); // a flag bit above the class (0-5)
    bytes.insert(bytes.end(), r.begin(), r.end());
  }
  return file(name, std::string(bytes.begin(), bytes.end()));
}

void test_las_files()
{
  std::cout << "LAS files" << std::endl;
  const std::vector<Point> points{Point(600000.25, 5400000.5, 101.75), Point(600010.5, 5400002.25, 99.5),
                                  Point(600003.75, 5400008.0, 112.25), Point(600007.0, 5400004.75, 100.0)};
  const std::vector<int> classes{2, 6, 5, 2};
  const std::array<double, 3> offset{600000, 5400000, 0};
  for(unsigned minor : {2u, 4u})
    for(unsigned format : {0u, 1u, 3u, 6u, 7u, 10u}) {
      if(minor < 4 && format > 5) continue; // formats 6 to 10 came with LAS 1.4
      const std::string path = las_file("p" + std::to_string(minor) + std::to_string(format) + ".las", minor, format,
                                        points, classes, 0.01, offset, points.size());
      const std::vector<Point> all = LOC::IO::read_point_file<Point>(path);
      assert(all == points); // the scale and offset applied: these coordinates are exact
      const std::vector<Point> ground_and_buildings = LOC::IO::read_point_file<Point>(path, {2, 6});
      assert(ground_and_buildings == (std::vector<Point>{points[0], points[1], points[3]}));
    }
  const std::string good = las_file("good.las", 2, 1, points, classes, 0.01, offset, points.size());
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("a.laz", "LASF")); }, "LAZ");
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("a.xyz", "0 0 0\n1 0 0\n"), {2}); }, "LAS files only");
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("b.las", "PLY and more bytes than a header needs")); }, "LASF");
  // more points declared than the file holds
  const std::string cut = las_file("cut.las", 2, 1, points, classes, 0.01, offset, points.size() + 1);
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(cut); }, "shorter than its header says");
  // compressed data (LASzip sets the high bits of the format)
  std::string compressed;
  {
    std::ifstream in(good, std::ios::binary);
    compressed.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    compressed[104] = char(0x80 | 1);
  }
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("zipped.las", compressed)); }, "LAZ");
  // a record length too short for its format, a version beyond 1.4
  std::string short_records = compressed;
  short_records[104] = 1;
  short_records[105] = 20;
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("short.las", short_records)); }, "too short");
  std::string version = short_records;
  version[105] = 28;
  version[25] = 5;
  expect_unreadable([&] { LOC::IO::read_point_file<Point>(file("v15.las", version)); }, "version");
}

int main(int argc, char** argv)
{
  fs::create_directories(directory);
  test_point_files();
  test_polyline_files();
  test_las_files();
  if(argc > 1) test_real_data(argv[1]);
  fs::remove_all(directory);
  std::cout << "OK\n";
  return 0;
}
