// The programs write each output under a temporary name and rename it once it is complete, so
// that a failed run leaves nothing behind and overwrites nothing. A run interrupted by a signal
// (SIGINT from Ctrl-C, SIGTERM from a scheduler or `timeout`, SIGHUP) runs no destructor: the
// temporary files known here are removed by the signal handler, which then lets the signal end
// the program as it would have (same signal, same exit status). The handler uses only what is
// safe in a signal handler: unlink() of paths stored in fixed arrays, flags of sig_atomic_t.
// Shared by lex_reconstruct, lod2_reconstruct and simplify_partition (and their MPI builds).

#ifndef URBAN_PROGRAMS_TEMPORARY_OUTPUT_FILES_H
#define URBAN_PROGRAMS_TEMPORARY_OUTPUT_FILES_H

#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>

namespace urban_programs {

namespace temporary_output_files_detail {

constexpr std::size_t capacity = 16;        // files at once
constexpr std::size_t longest_path = 4096;  // bytes, with the final NUL
inline char paths[capacity][longest_path];
inline volatile std::sig_atomic_t in_use[capacity];

extern "C" inline void remove_and_reraise(int signal_number)
{
  for(std::size_t i = 0; i < capacity; ++i)
    if(in_use[i]) ::unlink(paths[i]);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

inline void install_handlers()
{
  static const bool installed = [] {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = remove_and_reraise;
    sigemptyset(&action.sa_mask);
    for(int s : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(s, &action, nullptr);
    return true;
  }();
  (void)installed;
}

} // namespace temporary_output_files_detail

// A temporary output file removed if a signal interrupts the program while this object lives
// (removing it on other exits stays the owner's job).
class Temporary_output_file
{
public:
  explicit Temporary_output_file(const std::string& path)
  {
    namespace d = temporary_output_files_detail;
    if(path.size() + 1 > d::longest_path) throw std::runtime_error("output path too long: '" + path + "'");
    d::install_handlers();
    for(std::size_t i = 0; i < d::capacity; ++i)
      if(!d::in_use[i]) {
        std::memcpy(d::paths[i], path.c_str(), path.size() + 1);
        d::in_use[i] = 1; // set after the path is complete: the handler never sees half a path
        slot_ = i;
        return;
      }
    throw std::runtime_error("too many output files at once");
  }
  ~Temporary_output_file() { temporary_output_files_detail::in_use[slot_] = 0; }
  Temporary_output_file(const Temporary_output_file&) = delete;
  Temporary_output_file& operator=(const Temporary_output_file&) = delete;

private:
  std::size_t slot_ = 0;
};

} // namespace urban_programs

#endif // URBAN_PROGRAMS_TEMPORARY_OUTPUT_FILES_H
