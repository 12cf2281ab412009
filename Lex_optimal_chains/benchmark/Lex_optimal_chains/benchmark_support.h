// Shared by the benchmarks: peak memory of this process, one measurement run in a child
// process (peak memory is per process) whose one-line flat JSON is parsed, the median of
// repeated measurements, and the command line (sizes and --repeat R).
#ifndef LEX_OPTIMAL_CHAINS_BENCHMARK_SUPPORT_H
#define LEX_OPTIMAL_CHAINS_BENCHMARK_SUPPORT_H

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

inline double peak_rss_mb()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0; // kilobytes on Linux
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
