// What the processes of one command do together (Process_group.h): with MPI when compiled with
// PROCESS_GROUP_WITH_MPI (lex_reconstruct_mpi, lod2_reconstruct_mpi), the identity without.
#include "Process_group.h"

#ifdef PROCESS_GROUP_WITH_MPI
#include <mpi.h>
#endif

#include <algorithm>
#include <stdexcept>

Process_group::Process_group(int& argc, char**& argv)
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

Process_group::~Process_group()
{
#ifdef PROCESS_GROUP_WITH_MPI
  MPI_Finalize();
#endif
}

void Process_group::barrier() const
{
#ifdef PROCESS_GROUP_WITH_MPI
  MPI_Barrier(MPI_COMM_WORLD);
#endif
}

std::vector<double> Process_group::sum(std::vector<double> values) const
{
#ifdef PROCESS_GROUP_WITH_MPI
  MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
#endif
  return values;
}

double Process_group::max(double value) const
{
#ifdef PROCESS_GROUP_WITH_MPI
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
#endif
  return value;
}

long long Process_group::min(long long value) const
{
#ifdef PROCESS_GROUP_WITH_MPI
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
#endif
  return value;
}

std::vector<std::string> Process_group::gather(const std::string& bytes) const
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
