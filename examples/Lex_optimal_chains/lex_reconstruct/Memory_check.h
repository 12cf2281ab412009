// lex_reconstruct: a cloud too large for the memory left is refused before the triangulation,
// with one line that says how much it needs, instead of being killed by the kernel halfway.
// The need is estimated from the number of points: the peak resident memory per point measured
// on a million points of a sphere (closed 578, open 606 and features 957 bytes a point; Debian
// 12, December 2026; the 3D Delaunay triangulation and its chains dominate), times 1.25. The
// memory left is MemAvailable of /proc/meminfo, or what the control group (container, batch
// job) leaves if less (Linux; elsewhere nothing is checked); --max-memory MB replaces it, to
// refuse earlier or to try anyway.
#ifndef URBAN_LEX_RECONSTRUCT_MEMORY_CHECK_H
#define URBAN_LEX_RECONSTRUCT_MEMORY_CHECK_H

#include "options_and_output.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace lex_reconstruct {

// peak resident bytes per input point of each subcommand (see above)
constexpr double closed_bytes_per_point = 578, open_bytes_per_point = 606, features_bytes_per_point = 957;

// The memory left to the process's control group (a container, a SLURM job) in MB: its limit
// minus its usage, from cgroup v2 (memory.max, memory.current) or v1 (memory.limit_in_bytes,
// memory.usage_in_bytes), in the group's folder or at the root of the mount (a cgroup
// namespace); 0 if there is no limit or none can be read.
inline double control_group_memory_left_mb()
{
#ifdef __linux__
  std::string v2_path, v1_path; // of the process's groups, from /proc/self/cgroup
  {
    std::ifstream groups("/proc/self/cgroup");
    std::string line;
    while(std::getline(groups, line)) {
      if(line.compare(0, 3, "0::") == 0) v2_path = line.substr(3);
      const std::size_t at = line.find(":memory:");
      if(at != std::string::npos) v1_path = line.substr(at + 8);
    }
  }
  auto read_number = [](const std::string& file, double& value) {
    std::ifstream in(file);
    std::string text;
    if(!(in >> text) || text == "max") return false;
    value = std::strtod(text.c_str(), nullptr);
    return value > 0 && value < 1e18; // larger: no limit
  };
  const std::pair<std::string, std::string> candidates[] = {
    {"/sys/fs/cgroup" + v2_path + "/memory.max", "/sys/fs/cgroup" + v2_path + "/memory.current"},
    {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current"},
    {"/sys/fs/cgroup/memory" + v1_path + "/memory.limit_in_bytes", "/sys/fs/cgroup/memory" + v1_path + "/memory.usage_in_bytes"},
    {"/sys/fs/cgroup/memory/memory.limit_in_bytes", "/sys/fs/cgroup/memory/memory.usage_in_bytes"}};
  for(const auto& [limit_file, usage_file] : candidates) {
    double limit = 0, usage = 0;
    if(!read_number(limit_file, limit)) continue;
    read_number(usage_file, usage);
    return std::max(limit - usage, 1.) / (1024 * 1024);
  }
#endif
  return 0;
}

// The memory left in MB: MemAvailable of /proc/meminfo, or less if the control group allows
// less; 0 if unknown
inline double available_memory_mb()
{
  double available = 0;
#ifdef __linux__
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  double kilobytes = 0;
  while(meminfo >> key >> kilobytes >> unit)
    if(key == "MemAvailable:") { available = kilobytes / 1024; break; }
#endif
  const double group = control_group_memory_left_mb();
  return group > 0 && (available <= 0 || group < available) ? group : available;
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
