// simplify_partition: kinetic partition of 2D segments, then its simplification in line space.
//
//   simplify_partition SEGMENTS OUTPUT [--lambda1 V] [--lambda2 V] [--epsilon V]
//                      [--alpha-max DEG] [--svg FILE] [--json]
//
// SEGMENTS: one segment per line, "x0 y0 x1 y1" (blank lines and lines starting with '#' are
// skipped). OUTPUT: the cells of the simplified partition, as GeoJSON (.geojson, .json) or
// WKT (.wkt, a MULTIPOLYGON). On bad input: a one-line reason, exit code 1, no output file.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/WKT.h>
#include <CGAL/Polygon_partition_simplification/IO/GeoJSON.h>
#include <CGAL/Polygon_partition_simplification/IO/segments_file.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/simplify_polygon_partition_2.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "Temporary_output_files.h"
#include "simplify_partition_command_line.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PPS = CGAL::Polygon_partition_simplification;
using Partition = PPS::Line_partition_2<K>;

// the edges of both partitions side by side, before on the left
static void write_svg(std::ostream& out, const Partition& before, const Partition& after)
{
  CGAL::Bbox_2 box;
  for(std::size_t e = 0; e < before.number_of_edges(); ++e) box += before.segment(e).bbox();
  const double w = box.xmax() - box.xmin(), h = box.ymax() - box.ymin(), gap = 0.05 * w;
  out << "<svg xmlns='http://www.w3.org/2000/svg' viewBox='" << box.xmin() - gap << ' ' << -box.ymax() - gap
      << ' ' << 2 * w + 3 * gap << ' ' << h + 2 * gap << "' width='1200'>\n";
  const double stroke = 0.002 * w;
  auto draw = [&](const Partition& p, double shift, const char* color) {
    for(std::size_t e = 0; e < p.number_of_edges(); ++e) {
      const auto s = p.segment(e);
      out << "<line x1='" << s.source().x() + shift << "' y1='" << -s.source().y() << "' x2='"
          << s.target().x() + shift << "' y2='" << -s.target().y() << "' stroke='" << color
          << "' stroke-width='" << stroke << "'/>\n";
    }
  };
  draw(before, 0, "black");
  draw(after, w + gap, "darkblue");
  out << "</svg>\n";
}

int main(int argc, char** argv)
{
  simplify_partition::Command_line command_line;
  try {
    command_line.parse(argc, argv);
  } catch(const CLI::CallForHelp& e) {
    return command_line.app.exit(e);
  } catch(const CLI::ParseError& e) { // one line and exit code 1, as for bad input
    std::cerr << "simplify_partition: error: " << e.what() << " (see --help)" << std::endl;
    return 1;
  }
  const simplify_partition::Options& o = command_line.options;
  const std::string &input = o.input, &output = o.output, &svg = o.svg;
  const double lambda1 = o.lambda1, lambda2 = o.lambda2, alpha_max = o.alpha_max, epsilon = o.epsilon;
  const bool json = o.json, remove_far_points = o.remove_far_points;

  const std::string format = simplify_partition::extension(output);
  const std::string temporary = output + ".partial", svg_temporary = svg + ".partial";
  try {
    // both files are created (empty, under their temporary names) before the work, and removed
    // if a signal interrupts it
    const urban_programs::Temporary_output_file interrupted(temporary);
    std::optional<urban_programs::Temporary_output_file> interrupted_svg;
    if(!svg.empty()) interrupted_svg.emplace(svg_temporary);
    if(!std::ofstream(temporary)) throw std::runtime_error("cannot write " + output);
    if(!svg.empty() && !std::ofstream(svg_temporary)) throw std::runtime_error("cannot write " + svg);
    const std::vector<K::Segment_2> segments = PPS::IO::read_segments_2<K>(input);

    const auto t0 = std::chrono::steady_clock::now();
    PPS::Kinetic_partition_report kinetic_report;
    Partition partition = CGAL::kinetic_partition_2(segments, PPS::parameters::report(&kinetic_report));
    const auto t1 = std::chrono::steady_clock::now();
    const Partition before = partition;
    const double scale = partition.frame().scale;
    const auto stats = CGAL::simplify_polygon_partition_2(
      partition, PPS::parameters::remove_far_points(remove_far_points,
                 PPS::parameters::concurrency_weight(lambda1,
                 PPS::parameters::orthogonality_weight(lambda2,
                 PPS::parameters::collapse_distance(o.epsilon_given ? epsilon : 0.01 * scale,
                 PPS::parameters::maximum_angle(alpha_max))))));

    std::vector<Partition::Polygon_with_holes_2> cells;
    partition.cells(std::back_inserter(cells));
    {
      std::ofstream out(temporary);
      out.precision(17); // coordinates in the millions (projected) keep their centimeters
      if(format == "wkt") CGAL::IO::write_multi_polygon_WKT(out, cells);
      else PPS::IO::write_GeoJSON(out, cells);
      out.close();
      if(!out) throw std::runtime_error("cannot write " + output);
    }
    if(!svg.empty()) {
      std::ofstream out(svg_temporary);
      out.precision(17);
      write_svg(out, before, partition);
      out.close();
      if(!out) throw std::runtime_error("cannot write " + svg);
    }
    // the drawing first: if the cells cannot be renamed, no output is left (the drawing is removed)
    if(!svg.empty() && std::rename(svg_temporary.c_str(), svg.c_str()) != 0)
      throw std::runtime_error("cannot write " + svg);
    if(std::rename(temporary.c_str(), output.c_str()) != 0) {
      if(!svg.empty()) std::remove(svg.c_str());
      throw std::runtime_error("cannot write " + output);
    }

    if(json) {
      nlohmann::json j;
      j["segments"] = segments.size();
      j["equal_segments"] = kinetic_report.equal_segments;
      j["overlapping_segments"] = kinetic_report.overlapping_segments;
      j["lines_before"] = stats.lines_before;
      j["lines_after"] = stats.lines_after;
      j["points_before"] = stats.points_before;
      j["points_after"] = stats.points_after;
      j["cells_before"] = stats.cells_before;
      j["cells_after"] = stats.cells_after;
      j["orthogonal_pairs_before"] = stats.orthogonal_pairs_before;
      j["orthogonal_pairs_after"] = stats.orthogonal_pairs_after;
      j["iterations"] = stats.iterations;
      j["rounds"] = stats.rounds;
      j["line_merges"] = stats.line_merges;
      j["point_merges"] = stats.point_merges;
      j["removed_points"] = stats.removed_points;
      j["far_points"] = stats.far_points;
      j["far_point_removals"] = stats.far_point_removals;
      j["rejected_rounds"] = stats.rejected_rounds;
      j["kinetic_s"] = std::chrono::duration<double>(t1 - t0).count();
      j["simplification_s"] = stats.seconds;
      std::cout << j.dump() << std::endl;
    } else {
      std::cout << "lines " << stats.lines_before << " -> " << stats.lines_after << ", cells "
                << stats.cells_before << " -> " << stats.cells_after << "; cells written to " << output
                << std::endl;
    }
  } catch(const std::exception& e) {
    std::remove(temporary.c_str());
    if(!svg.empty()) std::remove(svg_temporary.c_str());
    std::cerr << "simplify_partition: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
