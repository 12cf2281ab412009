// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PEAK_MEMORY_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PEAK_MEMORY_H

// The peak resident size of the process (its high-water mark), and a reset of it, so that the
// peak of one stage can be told from that of the stages before it. Linux only: the mark is
// VmHWM of /proc/self/status, reset to the current resident size by writing 5 to
// /proc/self/clear_refs (proc(5)). Elsewhere, or where /proc cannot be read or written, the
// peak is 0 and the reset fails.

#include <cstddef>
#include <fstream>
#include <string>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

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

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PEAK_MEMORY_H
