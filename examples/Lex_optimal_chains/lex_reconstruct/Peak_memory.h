// The peak resident memory of the process, and of each tile of a tiled reconstruction, for
// the statistics of lex_reconstruct. Linux only: the peak is VmHWM of /proc/self/status,
// reset to the current resident size by writing 5 to /proc/self/clear_refs (proc(5)), so that
// the peak of one tile can be told from that of the work before it. Elsewhere, or where /proc
// cannot be read or written, the peak is 0 and nothing is measured.
#ifndef URBAN_EXAMPLES_PEAK_MEMORY_H
#define URBAN_EXAMPLES_PEAK_MEMORY_H

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <map>
#include <string>
#include <utility>

// the peak resident size of the process, in bytes (0 if unknown)
inline std::size_t peak_resident_bytes()
{
#ifdef __linux__
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.compare(0, 6, "VmHWM:") == 0) return std::size_t(std::stoull(line.substr(6))) * 1024; // in kB
#endif
  return 0;
}

// Resets the peak resident size to the current resident size; false if it cannot.
inline bool reset_peak_resident_bytes()
{
#ifdef __linux__
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << "5";
  clear_refs.flush();
  return bool(clear_refs);
#else
  return false;
#endif
}

// The peak resident memory of each tile of lex_optimal_tiled_surface_reconstruction() when
// its tiles are reconstructed one at a time (one thread: the peak is the process's), measured
// through the hooks of the call: `start()` from the tile filter, before the first tile;
// `tile_done()` first in the tile visitor (the peak since the last reset is the tile's:
// its points and its reconstruction); `visitor_done()` last in the visitor (the visitor's work,
// writing the tile, counts for the call, not for the next tile; the peak is reset). Resetting
// the peak makes getrusage() forget the peak before it: `call_peak()` keeps it.
class Tile_peak_memory
{
public:
  explicit Tile_peak_memory(bool enabled) : enabled_(enabled) {}

  void start()
  {
    enabled_ = enabled_ && peak_resident_bytes() > 0;
    if(!enabled_) return;
    call_peak_ = std::max(call_peak_, peak_resident_bytes());
    measuring_ = reset_peak_resident_bytes();
  }
  void tile_done(std::size_t column, std::size_t row)
  {
    if(!measuring_) return;
    const std::size_t peak = peak_resident_bytes();
    tile_peak_[{column, row}] = peak;
    call_peak_ = std::max(call_peak_, peak);
  }
  void visitor_done()
  {
    if(!enabled_) return;
    call_peak_ = std::max(call_peak_, peak_resident_bytes());
    measuring_ = reset_peak_resident_bytes();
  }

  // the peak of the tile, in bytes (0: not measured)
  std::size_t tile_peak(std::size_t column, std::size_t row) const
  {
    const auto it = tile_peak_.find({column, row});
    return it == tile_peak_.end() ? 0 : it->second;
  }
  // the peak over the tiles and what came before them, in bytes (0: not measured)
  std::size_t call_peak() const { return call_peak_; }

private:
  bool enabled_, measuring_ = false;
  std::size_t call_peak_ = 0;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> tile_peak_;
};

#endif // URBAN_EXAMPLES_PEAK_MEMORY_H
