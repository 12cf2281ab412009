// A model computed in a child process that is killed at a time limit, for the benchmarks that
// run PolyFit (benchmark_lod2, benchmark_polyfit): its solver, GLPK as CGAL calls it, has no
// time limit of its own, and a crash of the child does not end the benchmark.

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_BENCHMARK_CHILD_PROCESS_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_BENCHMARK_CHILD_PROCESS_H

#include <CGAL/IO/OFF.h>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <sstream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace benchmark {

namespace internal {

// Sends all of `text` to a file descriptor.
inline void write_all(int descriptor, const std::string& text)
{
  for(std::size_t written = 0; written < text.size();) {
    const ssize_t count = ::write(descriptor, text.data() + written, text.size() - written);
    if(count <= 0) return;
    written += std::size_t(count);
  }
}

// Reads a file descriptor until its end or the deadline; false at the deadline.
inline bool read_all(int descriptor, std::chrono::steady_clock::time_point deadline, std::string& text)
{
  char buffer[1 << 16];
  for(;;) {
    const double remaining = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    pollfd ready{descriptor, POLLIN, 0};
    const int polled = remaining > 0 ? ::poll(&ready, 1, int(1000 * remaining) + 1) : 0;
    if(polled < 0 && errno == EINTR) continue;
    if(polled == 0) return false;
    const ssize_t count = ::read(descriptor, buffer, sizeof buffer);
    if(count <= 0) return true;
    text.append(buffer, std::size_t(count));
  }
}

} // namespace internal

struct Time_limit_reached : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Calls `compute` (which returns a polygon mesh or throws) in a child process that is killed
// after `time_limit` seconds (Time_limit_reached). The child sends "ok" and the mesh as OFF
// text, or the message of its exception, through a pipe.
template <class Compute>
auto compute_in_child(Compute compute, double time_limit) -> decltype(compute())
{
  using Mesh = decltype(compute());
  int channel[2];
  if(::pipe(channel) != 0) throw std::runtime_error("no pipe to a child process");
  const pid_t child = ::fork();
  if(child < 0) throw std::runtime_error("no child process (fork failed)");
  if(child == 0) {
    ::close(channel[0]);
    std::ostringstream out;
    try {
      const Mesh model = compute();
      out << "ok\n";
      IO::write_OFF(out, model, parameters::stream_precision(17));
    } catch(const std::exception& error) {
      out << error.what() << "\n";
    }
    internal::write_all(channel[1], out.str());
    ::_exit(0); // no destructors, no flush of the parent's buffered output
  }
  ::close(channel[1]);
  std::string text;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                              std::chrono::duration<double>(time_limit));
  const bool finished = internal::read_all(channel[0], deadline, text);
  ::close(channel[0]);
  if(!finished) ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  if(!finished) {
    std::ostringstream message;
    message << "stopped at the time limit of " << time_limit << " s";
    throw Time_limit_reached(message.str());
  }
  std::istringstream in(text);
  std::string first_line;
  std::getline(in, first_line);
  if(WIFSIGNALED(status)) throw std::runtime_error("the child process died of signal " + std::to_string(WTERMSIG(status)));
  if(first_line != "ok") throw std::runtime_error(first_line.empty() ? "the child process sent no model" : first_line);
  Mesh model;
  if(!IO::read_OFF(in, model)) throw std::runtime_error("the child's model is unreadable");
  return model;
}

} // namespace benchmark
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_BENCHMARK_CHILD_PROCESS_H
