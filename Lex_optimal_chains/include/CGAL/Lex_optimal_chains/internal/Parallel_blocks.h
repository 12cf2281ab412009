// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PARALLEL_BLOCKS_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PARALLEL_BLOCKS_H

// The one way the package runs a loop over many items on several threads: the items
// [begin, end) are cut into blocks of a fixed size, numbered from 0, and the blocks are
// handed to the threads of a TBB arena of the requested size. The cut does not depend on the
// number of threads, so a loop that writes the results of block b to slot b and reads them
// back in block order gives the same output for any number of threads. Without TBB, or with
// one thread, or for loops too short to pay the start of the threads, the blocks run in order
// on the calling thread.

#include <CGAL/Lex_optimal_chains/Cancelled.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

class Parallel_blocks
{
public:
  // Runs on `threads` threads the loops of at least `minimum_items` items.
  Parallel_blocks(unsigned threads, std::size_t minimum_items)
    : threads_(threads), minimum_items_(minimum_items)
  {}

  // Whether a loop of `n` items runs on several threads.
  bool is_parallel(std::size_t n) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    return threads_ > 1 && n >= minimum_items_;
#else
    (void)n;
    return false;
#endif
  }

  // The number of blocks of `block` items in [begin, end).
  static std::size_t number_of_blocks(std::size_t begin, std::size_t end, std::size_t block)
  {
    return (end - begin + block - 1) / block;
  }

  // Calls `body(b, first, last)` for every block b of [begin, end): [first, last) is
  // [begin + b * block, begin + (b + 1) * block) cut at `end`. With several threads, the
  // calls run concurrently in no particular order: `body` must be safe to call so.
  // `total` is the size of the whole loop this range belongs to (which decides if it runs in
  // parallel: a loop is cut into ranges to report progress between them).
  template <class Body>
  void run(std::size_t begin, std::size_t end, std::size_t block, std::size_t total, const Body& body)
  {
    const std::size_t blocks = number_of_blocks(begin, end, block);
    auto one = [&](std::size_t b) { body(b, begin + b * block, (std::min)(end, begin + (b + 1) * block)); };
#ifdef CGAL_LINKED_WITH_TBB
    if(is_parallel(total)) {
      if(!arena_) arena_.reset(new tbb::task_arena(static_cast<int>(threads_)));
      arena_->execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
          for(std::size_t b = r.begin(); b != r.end(); ++b) one(b);
        });
      });
      return;
    }
#else
    (void)total;
#endif
    for(std::size_t b = 0; b < blocks; ++b) one(b);
  }

  // Runs `body` over [0, n) as `run()` does, in waves of `wave` items: before each wave,
  // `progress(fraction done)` is called from the calling thread (it returns false to cancel:
  // Cancelled is thrown), and after each wave `wave_done(first block, number of
  // blocks)`, also from the calling thread (blocks are numbered from 0 across the waves).
  template <class Body, class WaveDone, class Progress>
  void run_in_waves(std::size_t n, std::size_t block, std::size_t wave, const Progress& progress, const Body& body,
                    const WaveDone& wave_done)
  {
    wave = (std::max)(block, wave - wave % block);
    for(std::size_t begin = 0; begin < n; begin += wave) {
      if(!progress(double(begin) / double(n))) throw Cancelled();
      const std::size_t end = (std::min)(n, begin + wave), first_block = begin / block;
      run(begin, end, block, n, [&](std::size_t b, std::size_t first, std::size_t last) { body(first_block + b, first, last); });
      wave_done(first_block, number_of_blocks(begin, end, block));
    }
  }

private:
  unsigned threads_;
  std::size_t minimum_items_;
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::task_arena> arena_;
#endif
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PARALLEL_BLOCKS_H
