// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_LARGE_ARRAY_ALLOCATOR_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_LARGE_ARRAY_ALLOCATOR_H

// The allocator of the package's arrays of one entry per facet, half-edge or record (tens to
// hundreds of megabytes). Such an array is written once, at random or in one pass, soon after
// it is allocated, so the first touch of its pages costs as much as its use: one page fault
// per 4 KiB page, in which the kernel zeroes the page (and, under a hypervisor, the host may
// have to back it). On Linux, arrays of 8 MiB or more are aligned on 2 MiB and marked with
// `madvise(MADV_HUGEPAGE)`: with transparent huge pages in their default `madvise` mode, the
// kernel then backs them with 2 MiB pages, one fault for 512 small ones. Smaller arrays are
// left to `std::allocator`: a huge page is committed whole, and the rounding of many small
// arrays to 2 MiB would raise the peak memory of small inputs. Elsewhere, or when the kernel
// does not follow the advice, this is `std::allocator`.
//
// The advice is given for the package's own arrays only, never through the global allocator:
// the memory of the user's triangulation and mesh is not the package's to place.

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
// <sys/mman.h> defines MAP_TYPE, the name of a template parameter in CGAL 5.5's
// compare_vertices.h (included by CGAL/estimate_scale.h): that header comes first, so that a
// user's later inclusion of it still compiles
#include <CGAL/compare_vertices.h>
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

template <class T>
class Large_array_allocator
{
public:
  using value_type = T;

  Large_array_allocator() noexcept = default;
  template <class U>
  Large_array_allocator(const Large_array_allocator<U>&) noexcept {}

  T* allocate(std::size_t n)
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if(is_large(n)) {
      const std::size_t bytes = rounded_size(n);
      void* p = std::aligned_alloc(huge_page_size, bytes);
      if(p == nullptr) throw std::bad_alloc();
      ::madvise(p, bytes, MADV_HUGEPAGE); // advice only: its failure changes nothing
      return static_cast<T*>(p);
    }
#endif
    return std::allocator<T>().allocate(n);
  }

  void deallocate(T* p, std::size_t n) noexcept
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if(is_large(n)) {
      std::free(p);
      return;
    }
#endif
    std::allocator<T>().deallocate(p, n);
  }

  template <class U>
  bool operator==(const Large_array_allocator<U>&) const noexcept { return true; }
  template <class U>
  bool operator!=(const Large_array_allocator<U>&) const noexcept { return false; }

private:
  static constexpr std::size_t huge_page_size = std::size_t(1) << 21;
  static constexpr std::size_t minimum_bytes = std::size_t(1) << 23;
  static bool is_large(std::size_t n) { return n >= minimum_bytes / sizeof(T); }
  // aligned_alloc wants a multiple of the alignment
  static std::size_t rounded_size(std::size_t n)
  {
    return (n * sizeof(T) + huge_page_size - 1) / huge_page_size * huge_page_size;
  }
};

// A vector with that allocator, for the arrays of one entry per facet, half-edge or record.
template <class T>
using Large_vector = std::vector<T, Large_array_allocator<T>>;

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_LARGE_ARRAY_ALLOCATOR_H
