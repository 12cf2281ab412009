// The programs write each output under a temporary name and rename it once it is complete, so
// that a failed run leaves nothing behind and overwrites nothing. A run interrupted by a signal
// (SIGINT from Ctrl-C, SIGTERM from a scheduler or `timeout`, SIGHUP) runs no destructor: the
// temporary files known here are removed by the signal handler, which then lets the signal end
// the program as it would have (same signal, same exit status). A signal that the program was
// started with ignored (nohup, a background job) stays ignored. The handler uses only what is
// safe in a signal handler: unlink() of paths stored in fixed arrays, lock-free atomic flags
// (a slot is claimed by one thread, as tiles are written from several, and marked ready once
// its path is stored, with release and acquire order).
// Shared by lex_reconstruct, lod2_reconstruct and simplify_partition (and their MPI builds).

#ifndef URBAN_PROGRAMS_TEMPORARY_OUTPUT_FILES_H
#define URBAN_PROGRAMS_TEMPORARY_OUTPUT_FILES_H

#include <signal.h>
#include <unistd.h>

#include <atomic>
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
enum : int { free_slot = 0, claimed = 1, ready = 2 }; // a slot is claimed, its path written, then ready
inline std::atomic<int> in_use[capacity];
static_assert(ATOMIC_INT_LOCK_FREE == 2, "the flags are read in a signal handler");

extern "C" inline void remove_and_reraise(int signal_number)
{
  for(std::size_t i = 0; i < capacity; ++i)
    if(in_use[i].load(std::memory_order_acquire) == ready) ::unlink(paths[i]);
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
    for(int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, s); // one handler at a time
    for(int s : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction before;
      if(::sigaction(s, nullptr, &before) == 0 && before.sa_handler == SIG_IGN) continue; // nohup
      ::sigaction(s, &action, nullptr);
    }
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
    for(std::size_t i = 0; i < d::capacity; ++i) {
      int expected = d::free_slot;
      if(d::in_use[i].compare_exchange_strong(expected, d::claimed, std::memory_order_acquire)) { // one thread
        std::memcpy(d::paths[i], path.c_str(), path.size() + 1);
        d::in_use[i].store(d::ready, std::memory_order_release); // after the path: never half a path
        slot_ = i;
        return;
      }
    }
    throw std::runtime_error("too many output files at once");
  }
  ~Temporary_output_file()
  {
    namespace d = temporary_output_files_detail;
    d::in_use[slot_].store(d::free_slot, std::memory_order_release);
  }
  Temporary_output_file(const Temporary_output_file&) = delete;
  Temporary_output_file& operator=(const Temporary_output_file&) = delete;

private:
  std::size_t slot_ = 0;
};

} // namespace urban_programs

#endif // URBAN_PROGRAMS_TEMPORARY_OUTPUT_FILES_H
