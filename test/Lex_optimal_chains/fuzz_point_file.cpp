// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Fuzz harness of the point readers of both packages' programs: the first byte chooses the
// extension (.xyz, .ply, .off or .las), the other bytes are the file. IO::read_point_file()
// (lex_reconstruct's reader) must give points or an Input_error. What lod2_reconstruct reads
// with must not fail otherwise: for LAS, IO::for_each_las_record(), points and classes in 0 to
// 255 or an Input_error; for the others, CGAL's read_point_set() into a Point_set_3 (any
// property, the classes among them), after the check of a PLY file's structure. A crash,
// another exception or a sanitizer report is a finding.
#include "../fuzz_support/fuzz_input_file.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Lex_optimal_chains/IO/input_files.h>
#include <CGAL/Lex_optimal_chains/IO/read_las_points.h>
#include <CGAL/Lex_optimal_chains/internal/PLY_structure_check.h>

#include <cstddef>
#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace IO = CGAL::Lex_optimal_chains::IO;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0) return 0;
  static const char* const extensions[] = {".xyz", ".ply", ".off", ".las"};
  const std::string extension = extensions[data[0] % 4];
  const std::string path = urban_fuzz::input_file(data + 1, size - 1, extension);
  try {
    IO::read_point_file<K::Point_3>(path);
  } catch(const CGAL::Lex_optimal_chains::Input_error&) {
    // a refusal: the documented outcome of bad input
  }
  try {
    if(extension == ".las") {
      IO::for_each_las_record<K::Point_3>(path, [](const K::Point_3&, int c) {
        if(c < 0 || c > 255) urban_fuzz::finding("LAS class " + std::to_string(c) + " read");
      });
    } else {
      if(extension == ".ply") // as lod2_reconstruct checks it
        CGAL::Lex_optimal_chains::internal::check_PLY_structure(path, {"x", "y", "z", "nx", "ny", "nz"}, true);
      CGAL::Point_set_3<K::Point_3> points;
      std::ostringstream reader_messages; // CGAL's readers report bad lines on std::cerr
      struct Restored_cerr
      {
        std::streambuf* saved;
        ~Restored_cerr() { std::cerr.rdbuf(saved); } // also when the reader throws
      } restored{std::cerr.rdbuf(reader_messages.rdbuf())};
      CGAL::IO::read_point_set(path, points);
    }
  } catch(const CGAL::Lex_optimal_chains::Input_error&) {
  }
  urban_fuzz::remove_input_file(path);
  return 0;
}
