// The processes that run one command together: the MPI ranks of lex_reconstruct_mpi and
// lod2_reconstruct_mpi (built with PROCESS_GROUP_WITH_MPI), or the one process of
// lex_reconstruct and lod2_reconstruct. The programs need only what is here: the rank and the
// number of ranks, the deal of jobs to the ranks, a barrier, reductions of a few numbers, and
// the bytes of every rank gathered on the first (collective: every rank calls them in the same
// order). Without MPI they are the identity.
#ifndef URBAN_EXAMPLES_PROCESS_GROUP_H
#define URBAN_EXAMPLES_PROCESS_GROUP_H

#ifdef PROCESS_GROUP_WITH_MPI
#include <mpi.h>
#endif

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
  Process_group(int& argc, char**& argv)
  {
#ifdef PROCESS_GROUP_WITH_MPI
    if(MPI_Init(&argc, &argv) != MPI_SUCCESS) throw std::runtime_error("MPI_Init failed");
    int r = 0, s = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    MPI_Comm_size(MPI_COMM_WORLD, &s);
    rank_ = std::size_t(r);
    size_ = std::size_t(s);
#else
    (void)argc;
    (void)argv;
#endif
  }
  ~Process_group()
  {
#ifdef PROCESS_GROUP_WITH_MPI
    MPI_Finalize();
#endif
  }
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

  void barrier() const
  {
#ifdef PROCESS_GROUP_WITH_MPI
    MPI_Barrier(MPI_COMM_WORLD);
#endif
  }

  // the element-wise sum of `values` over the ranks, on every rank (doubles hold the counts
  // exactly up to 2^53)
  std::vector<double> sum(std::vector<double> values) const
  {
#ifdef PROCESS_GROUP_WITH_MPI
    MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
#endif
    return values;
  }

  // the largest of `value` over the ranks, on every rank
  double max(double value) const
  {
#ifdef PROCESS_GROUP_WITH_MPI
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
#endif
    return value;
  }

  // the smallest of `value` over the ranks, on every rank
  long long min(long long value) const
  {
#ifdef PROCESS_GROUP_WITH_MPI
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
#endif
    return value;
  }

  // on the first rank, the `bytes` of every rank by rank; on the others, nothing
  std::vector<std::string> gather(const std::string& bytes) const
  {
#ifdef PROCESS_GROUP_WITH_MPI
    unsigned long long size = bytes.size();
    std::vector<unsigned long long> sizes(size_);
    MPI_Gather(&size, 1, MPI_UNSIGNED_LONG_LONG, sizes.data(), 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    const std::size_t chunk = std::size_t(1) << 30; // an MPI count is an int
    if(!is_root()) {
      for(std::size_t offset = 0; offset < bytes.size(); offset += chunk)
        MPI_Send(bytes.data() + offset, int(std::min(chunk, bytes.size() - offset)), MPI_CHAR, 0, 0, MPI_COMM_WORLD);
      return {};
    }
    std::vector<std::string> parts(size_);
    parts[0] = bytes;
    for(std::size_t r = 1; r < size_; ++r) {
      parts[r].resize(std::size_t(sizes[r]));
      for(std::size_t offset = 0; offset < parts[r].size(); offset += chunk)
        MPI_Recv(&parts[r][offset], int(std::min(chunk, parts[r].size() - offset)), MPI_CHAR, int(r), 0, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
    }
    return parts;
#else
    return {bytes};
#endif
  }

private:
  std::size_t rank_ = 0, size_ = 1;
};

#endif // URBAN_EXAMPLES_PROCESS_GROUP_H
