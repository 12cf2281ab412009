// The processes that run one lex_reconstruct command together: the MPI ranks of
// lex_reconstruct_mpi (built with LEX_RECONSTRUCT_WITH_MPI), or the one process of
// lex_reconstruct. The tiles subcommand needs only what is here: its rank and the number of
// ranks, a barrier, and reductions of a few numbers (collective: every rank calls them in
// the same order). Without MPI they are the identity.
#ifndef LEX_RECONSTRUCT_PROCESS_GROUP_H
#define LEX_RECONSTRUCT_PROCESS_GROUP_H

#ifdef LEX_RECONSTRUCT_WITH_MPI
#include <mpi.h>
#endif

#include <cstddef>
#include <stdexcept>
#include <vector>

class Process_group
{
public:
  // MPI_Init (with the program's arguments) when built with MPI
  Process_group(int& argc, char**& argv)
  {
#ifdef LEX_RECONSTRUCT_WITH_MPI
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
#ifdef LEX_RECONSTRUCT_WITH_MPI
    MPI_Finalize();
#endif
  }
  Process_group(const Process_group&) = delete;
  Process_group& operator=(const Process_group&) = delete;

  std::size_t rank() const { return rank_; }
  std::size_t size() const { return size_; }
  bool is_root() const { return rank_ == 0; }

  void barrier() const
  {
#ifdef LEX_RECONSTRUCT_WITH_MPI
    MPI_Barrier(MPI_COMM_WORLD);
#endif
  }

  // the element-wise sum of `values` over the ranks, on every rank (doubles hold the counts
  // exactly up to 2^53)
  std::vector<double> sum(std::vector<double> values) const
  {
#ifdef LEX_RECONSTRUCT_WITH_MPI
    MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
#endif
    return values;
  }

  // the largest of `value` over the ranks, on every rank
  double max(double value) const
  {
#ifdef LEX_RECONSTRUCT_WITH_MPI
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
#endif
    return value;
  }

  // the smallest of `value` over the ranks, on every rank
  long long min(long long value) const
  {
#ifdef LEX_RECONSTRUCT_WITH_MPI
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
#endif
    return value;
  }

private:
  std::size_t rank_ = 0, size_ = 1;
};

#endif // LEX_RECONSTRUCT_PROCESS_GROUP_H
