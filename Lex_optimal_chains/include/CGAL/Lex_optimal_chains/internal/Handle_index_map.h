// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_HANDLE_INDEX_MAP_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_HANDLE_INDEX_MAP_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Dense indices for the elements of a container whose elements live in a few contiguous
// blocks (CGAL's Compact_container, as used by the triangulation data structures).
// Index i is the position of the element in the iteration order, plus `first_index`.
// The elements are grouped in runs of consecutive addresses; a page table over the
// address range sends a pointer to the first run that can hold it. Memory is
// O(number of runs + address range / page size) and a look-up reads a few cached words,
// instead of a hash table over millions of handles. The reverse look-up (index to element)
// uses a table over pages of 128 indices in the same way.
template <class Element>
class Handle_index_map
{
  struct Run { const Element* begin; std::uint32_t size; std::uint32_t first; };

public:
  Handle_index_map() = default;

  // `range` is iterated once; each element is accessed by address (`&*it`).
  template <class Iterator>
  Handle_index_map(Iterator begin, Iterator end, std::uint32_t first_index = 0)
  {
    std::uint32_t index = first_index;
    for(Iterator it = begin; it != end; ++it, ++index) {
      const Element* p = &*it;
      if(runs_.empty() || p != runs_.back().begin + runs_.back().size)
        runs_.push_back(Run{p, 0, index});
      ++runs_.back().size;
    }
    count_ = index - first_index;
    first_index_ = first_index;
    by_index_ = runs_; // runs in iteration order, for index -> element
    // index page k -> the run holding index first_index + (k << index_page_bits)
    index_page_.resize((count_ >> index_page_bits) + 1);
    for(std::size_t k = 0, r = 0; k < index_page_.size(); ++k) {
      const std::size_t i = first_index + (k << index_page_bits);
      while(r + 1 < by_index_.size() && i >= by_index_[r].first + std::size_t(by_index_[r].size)) ++r;
      index_page_[k] = std::uint32_t(r);
    }
    std::sort(runs_.begin(), runs_.end(),
              [](const Run& a, const Run& b) { return std::less<const Element*>()(a.begin, b.begin); });
    if(runs_.empty()) return;
    low_ = reinterpret_cast<std::uintptr_t>(runs_.front().begin);
    const std::uintptr_t high = reinterpret_cast<std::uintptr_t>(runs_.back().begin + runs_.back().size);
    const std::size_t npages = (high - low_) / page_size + 1;
    // the pages that hold elements
    std::size_t covered = 0;
    for(const Run& run : runs_) covered += page_of(run.begin + run.size - 1) - page_of(run.begin) + 1;
    if(npages <= 2 * covered + 1024) {
      // compact: a table over all the pages of the address range
      page_.assign(npages, 0);
      std::size_t r = 0;
      for(std::size_t k = 0; k < npages; ++k) {
        const std::uintptr_t page_begin = low_ + k * page_size;
        while(r + 1 < runs_.size() &&
              reinterpret_cast<std::uintptr_t>(runs_[r].begin + runs_[r].size) <= page_begin)
          ++r;
        page_[k] = std::uint32_t(r);
      }
    } else {
      // blocks far apart (the allocator may place them in different regions: the range can
      // be terabytes): a hash table over the covered pages only
      std::size_t slots = 16;
      while(slots < 2 * covered) slots *= 2;
      hashed_pages_.assign(slots, Hashed_page{empty_page, 0});
      for(std::uint32_t r = std::uint32_t(runs_.size()); r-- > 0;) // the first run of a page last
        for(std::size_t k = page_of(runs_[r].begin); k <= page_of(runs_[r].begin + runs_[r].size - 1); ++k) {
          std::size_t h = page_hash(k);
          while(hashed_pages_[h].page != empty_page && hashed_pages_[h].page != k) h = (h + 1) & (slots - 1);
          hashed_pages_[h] = Hashed_page{k, r};
        }
    }
  }

  std::size_t size() const { return count_; }

  std::uint32_t index(const Element* p) const
  {
    CGAL_precondition(!runs_.empty() && reinterpret_cast<std::uintptr_t>(p) >= low_);
    std::size_t r = first_run_of_page(page_of(p));
    while(!(p >= runs_[r].begin && p < runs_[r].begin + runs_[r].size)) {
      ++r;
      CGAL_assertion(r < runs_.size());
    }
    return runs_[r].first + std::uint32_t(p - runs_[r].begin);
  }

  const Element* element(std::uint32_t i) const
  {
    CGAL_precondition(i >= first_index_ && i - first_index_ < count_);
    std::size_t r = index_page_[(i - first_index_) >> index_page_bits];
    while(i - by_index_[r].first >= by_index_[r].size) ++r; // a few runs at most
    return by_index_[r].begin + (i - by_index_[r].first);
  }

private:
  struct Hashed_page { std::size_t page; std::uint32_t run; };
  static constexpr std::size_t empty_page = std::numeric_limits<std::size_t>::max();

  std::size_t page_of(const Element* p) const { return (reinterpret_cast<std::uintptr_t>(p) - low_) / page_size; }
  std::size_t page_hash(std::size_t k) const
  {
    return std::size_t((std::uint64_t(k) * 0x9E3779B97F4A7C15ull) >> 32) & (hashed_pages_.size() - 1);
  }
  // the first run (in address order) that has elements in page k, which must hold one
  std::size_t first_run_of_page(std::size_t k) const
  {
    if(!page_.empty()) return page_[k];
    std::size_t h = page_hash(k);
    while(hashed_pages_[h].page != k) {
      CGAL_assertion(hashed_pages_[h].page != empty_page);
      h = (h + 1) & (hashed_pages_.size() - 1);
    }
    return hashed_pages_[h].run;
  }

  static constexpr std::uintptr_t page_size = 1 << 14;
  static constexpr int index_page_bits = 7;
  std::vector<std::uint32_t> index_page_; // index page -> first run (in `by_index_`) that holds it
  std::uint32_t first_index_ = 0;
  std::vector<Run> runs_;     // sorted by address
  std::vector<Run> by_index_; // sorted by index
  std::vector<std::uint32_t> page_;         // page -> first run, over the address range when it is compact
  std::vector<Hashed_page> hashed_pages_;    // otherwise over the covered pages only
  std::uintptr_t low_ = 0;
  std::size_t count_ = 0;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_HANDLE_INDEX_MAP_H
