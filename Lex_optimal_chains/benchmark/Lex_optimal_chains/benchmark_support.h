// Shared by the benchmarks: a terrain-like cloud, peak memory of this process, one measurement run in a child
// process (peak memory is per process) whose one-line flat JSON is parsed, all the
// measurements of a run on one CPU, the median of repeated measurements, and the command line
// (sizes and --repeat R).
#ifndef LEX_OPTIMAL_CHAINS_BENCHMARK_SUPPORT_H
#define LEX_OPTIMAL_CHAINS_BENCHMARK_SUPPORT_H

#include <sched.h>
#include <unistd.h>
#include <sys/resource.h>

#include <CGAL/Random.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

// n points on a 1 km x 1 km terrain: hills, a grid of flat-roofed blocks 12 m high, noise 5 cm
template <class Point>
std::vector<Point> noisy_terrain(std::size_t n)
{
  CGAL::Random rng(42);
  std::vector<Point> pts;
  pts.reserve(n);
  while(pts.size() < n) {
    const double x = rng.get_double(0, 1000), y = rng.get_double(0, 1000);
    double z = 20 * std::sin(x / 160) * std::cos(y / 210) + 0.01 * x;
    const double bx = std::fmod(x, 100), by = std::fmod(y, 100);
    if(bx > 30 && bx < 70 && by > 25 && by < 75) z += 12;
    pts.emplace_back(x, y, z + rng.get_double(-0.05, 0.05));
  }
  return pts;
}

inline double peak_rss_mb()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0; // kilobytes on Linux
}

// Pins this process, and so the children it starts, to the lowest-numbered CPU it may run on,
// and says which on std::cout (or that it could not). The ratios of a run
// compare measurements made in different processes: on the 2-vCPU virtual machine of the
// project the two CPUs differ in speed, by workload (the Delaunay triangulation took the same
// time on both, a reconstruction's cut 0.48 s on one and 0.71 to 1.12 s on the other), so that
// a ratio of two processes placed on different CPUs by the scheduler mixes in that difference.
inline void pin_measurements_to_one_cpu()
{
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  int pinned = -1;
  if(sched_getaffinity(0, sizeof allowed, &allowed) == 0)
    for(int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
      if(CPU_ISSET(cpu, &allowed)) {
        cpu_set_t one;
        CPU_ZERO(&one);
        CPU_SET(cpu, &one);
        if(sched_setaffinity(0, sizeof one, &one) == 0) pinned = cpu;
        break;
      }
  if(pinned >= 0) std::cout << "all measurements on CPU " << pinned << "\n";
  else std::cout << "measurements not pinned to one CPU\n";
}

// Ends the one-line JSON of a measurement with the memory before it (`base_mb`) and the peak
// memory, and prints it: what run_child() reads back.
inline int print_measurement(const std::string& json_so_far, double base_mb)
{
  std::cout << json_so_far << ",\"points_mb\":" << base_mb << ",\"peak_rss_mb\":" << peak_rss_mb() << "}" << std::endl;
  return 0;
}

// Lets the calling process run on every online CPU again (a measurement on several threads,
// started by a process pinned to one CPU).
inline void allow_all_cpus()
{
  cpu_set_t all;
  CPU_ZERO(&all);
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  for(long cpu = 0; cpu < online && cpu < CPU_SETSIZE; ++cpu) CPU_SET(int(cpu), &all);
  sched_setaffinity(0, sizeof all, &all);
}

// Runs `command`, echoes its output to stderr and returns its numeric "key":value pairs.
inline std::map<std::string, double> run_child(const std::string& command)
{
  std::map<std::string, double> values;
  FILE* p = popen(command.c_str(), "r");
  if(!p) return values;
  std::string out;
  char buf[4096];
  while(fgets(buf, sizeof buf, p)) out += buf;
  pclose(p);
  std::cerr << out;
  std::size_t pos = 0;
  while((pos = out.find('"', pos)) != std::string::npos) {
    const std::size_t end = out.find('"', pos + 1);
    const std::string key = out.substr(pos + 1, end - pos - 1);
    pos = end + 1;
    if(pos < out.size() && out[pos] == ':' && out[pos + 1] != '"') values[key] = std::atof(out.c_str() + pos + 1);
  }
  return values;
}

// Key by key, the median of the values of `runs` (the lower middle one for an even count):
// on a shared machine a single run can be off by 50% in either direction.
inline std::map<std::string, double> median(const std::vector<std::map<std::string, double>>& runs)
{
  std::map<std::string, double> result;
  if(runs.empty()) return result;
  for(const auto& [key, value] : runs.front()) {
    std::vector<double> values;
    for(const auto& r : runs) {
      const auto it = r.find(key);
      if(it != r.end()) values.push_back(it->second);
    }
    std::nth_element(values.begin(), values.begin() + (values.size() - 1) / 2, values.end());
    result[key] = values[(values.size() - 1) / 2];
  }
  return result;
}

// The command line of the table mode: point counts and an optional `--repeat R` (R >= 1 runs
// of every measurement, whose medians are shown). Returns false on anything else.
inline bool parse_sizes(int argc, char** argv, std::vector<std::size_t>& sizes, std::size_t& repeat)
{
  repeat = 1;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    char* end = nullptr;
    const bool option = a == "--repeat" && i + 1 < argc;
    const char* number = option ? argv[++i] : argv[i];
    const unsigned long long v = std::strtoull(number, &end, 10);
    if(end == number || *end != '\0' || v == 0 || number[0] == '-') return false;
    if(option) repeat = std::size_t(v);
    else sizes.push_back(std::size_t(v));
  }
  return true;
}

#endif // LEX_OPTIMAL_CHAINS_BENCHMARK_SUPPORT_H
