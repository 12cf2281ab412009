// Shared by the benchmarks: peak memory of this process, and one measurement run in a
// child process (peak memory is per process) whose one-line flat JSON is parsed.
#ifndef LEX_OPTIMAL_CHAINS_BENCHMARK_SUPPORT_H
#define LEX_OPTIMAL_CHAINS_BENCHMARK_SUPPORT_H

#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

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

#endif // LEX_OPTIMAL_CHAINS_BENCHMARK_SUPPORT_H
