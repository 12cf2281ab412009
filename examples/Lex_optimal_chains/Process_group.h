// The processes that run one command together: the MPI ranks of lex_reconstruct_mpi and
// lod2_reconstruct_mpi (built with PROCESS_GROUP_WITH_MPI), or the one process of
// lex_reconstruct and lod2_reconstruct. The programs need only what is here: the rank and the
// number of ranks, the deal of jobs to the ranks, a barrier, reductions of a few numbers, and
// the bytes of every rank gathered on the first (collective: every rank calls them in the same
// order). Without MPI they are the identity. What MPI does is in Process_group.cpp, compiled
// once with PROCESS_GROUP_WITH_MPI and once without: the programs' own translation unit is
// the same for both builds, and compiled once.
#ifndef URBAN_EXAMPLES_PROCESS_GROUP_H
#define URBAN_EXAMPLES_PROCESS_GROUP_H

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

class Process_group
{
public:
  // MPI_Init (with the program's arguments) when built with MPI
  Process_group(int& argc, char**& argv);
  ~Process_group(); // MPI_Finalize when built with MPI
  Process_group(const Process_group&) = delete;
  Process_group& operator=(const Process_group&) = delete;

  std::size_t rank() const { return rank_; }
  std::size_t size() const { return size_; }
  bool is_root() const { return rank_ == 0; }

  // The rank of each job, given its cost (its number of points): by decreasing cost (then by
  // increasing index), each to the rank with the smallest total cost so far (then the lowest
  // rank), longest processing time first. Only the costs decide, so every rank that has the
  // same costs makes the same deal (no communication).
  std::vector<std::size_t> deal(const std::vector<std::size_t>& costs) const
  {
    std::vector<std::size_t> order(costs.size()), rank_of(costs.size(), 0), load(size_, 0);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
    for(std::size_t job : order) {
      const std::size_t r = std::size_t(std::min_element(load.begin(), load.end()) - load.begin());
      rank_of[job] = r;
      load[r] += costs[job];
    }
    return rank_of;
  }

  void barrier() const;
  // the element-wise sum of `values` over the ranks, on every rank (doubles hold the counts
  // exactly up to 2^53)
  std::vector<double> sum(std::vector<double> values) const;
  // the largest of `value` over the ranks, on every rank
  double max(double value) const;
  // the smallest of `value` over the ranks, on every rank
  long long min(long long value) const;
  // on the first rank, the `bytes` of every rank by rank; on the others, nothing
  std::vector<std::string> gather(const std::string& bytes) const;

private:
  std::size_t rank_ = 0, size_ = 1;
};

#endif // URBAN_EXAMPLES_PROCESS_GROUP_H
