// lex_reconstruct: a cloud too large for the memory left is refused before the triangulation,
// with one line that says how much it needs, instead of being killed by the kernel halfway.
// The need is estimated from the number of points: the peak resident memory per point measured
// on a million points of a sphere (closed 578, open 606 and features 957 bytes a point; Debian
// 12, December 2026; the 3D Delaunay triangulation and its chains dominate), times 1.25. The
// memory left is MemAvailable of /proc/meminfo (Linux; elsewhere nothing is checked);
// --max-memory MB replaces it, to refuse earlier or to try anyway.
#ifndef URBAN_LEX_RECONSTRUCT_MEMORY_CHECK_H
#define URBAN_LEX_RECONSTRUCT_MEMORY_CHECK_H

#include "options_and_output.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace lex_reconstruct {

// peak resident bytes per input point of each subcommand (see above)
constexpr double closed_bytes_per_point = 578, open_bytes_per_point = 606, features_bytes_per_point = 957;

// MemAvailable of /proc/meminfo in MB; 0 if unknown
inline double available_memory_mb()
{
#ifdef __linux__
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0;
  std::string unit;
  while(meminfo >> key >> kilobytes >> unit)
    if(key == "MemAvailable:") return kilobytes / 1024;
#endif
  return 0;
}

inline void add_memory_option(CLI::App* command, double& max_memory_mb)
{
  command->add_option("--max-memory", max_memory_mb,
                      "memory in MB the run may use (default: what the system says is available); a cloud whose "
                      "estimated need is larger is refused before the triangulation")
    ->check(positive_number());
}

// Throws std::runtime_error (one line) when `points` points need more than `max_memory_mb`
// (0: the memory available) by the estimate of `bytes_per_point`.
inline void check_memory(std::size_t points, double bytes_per_point, double max_memory_mb)
{
  const double limit = max_memory_mb > 0 ? max_memory_mb : available_memory_mb();
  const double need = 1.25 * bytes_per_point * double(points) / (1024 * 1024);
  if(limit <= 0 || need <= limit) return;
  std::ostringstream message;
  message << points << " points need about " << std::ceil(need) << " MB, more than the " << std::floor(limit)
          << " MB " << (max_memory_mb > 0 ? "of --max-memory" : "available")
          << ": cut the cloud into tiles (the tiles subcommand), thin it, or give --max-memory MB to try anyway";
  throw std::runtime_error(message.str());
}

} // namespace lex_reconstruct

#endif // URBAN_LEX_RECONSTRUCT_MEMORY_CHECK_H
