// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_BUCKETS_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_BUCKETS_H

// The points of a cloud bucketed into files, one per cell of the grid of the tiles, for the
// out-of-core tiled reconstruction: the cloud streams through once, and each bucket is read
// back alone. A bucket holds the coordinates as raw doubles (x, y, z, in the byte order of the
// machine: the files live as long as the call). The files are in a fresh directory made in the
// given one, removed with them when the buckets are destroyed (on an error too).

#include <CGAL/Lex_optimal_chains/Input_error.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

template <class Point>
class Tile_buckets
{
public:
  // `cells` buckets in a new directory inside `parent`, which must exist
  Tile_buckets(const std::string& parent, std::size_t cells) : buffers_(cells), sizes_(cells, 0)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    if(!fs::is_directory(parent, error))
      throw Input_error(Input_error_code::INVALID_PARAMETER, "the bucket directory '" + parent + "' is not a directory");
    std::random_device seed;
    for(int attempt = 0; directory_.empty() && attempt < 100; ++attempt) {
      const fs::path candidate = fs::path(parent) / (".lex_tile_buckets_" + std::to_string(seed()));
      if(fs::create_directory(candidate, error)) directory_ = candidate.string();
      else if(error) break;
    }
    if(directory_.empty())
      throw Input_error(Input_error_code::WRITE_FAILED, "cannot make a directory for the bucket files in '" + parent + "'" +
                                                          (error ? " (" + error.message() + ")" : std::string()));
    // a buffer per bucket: about 64 MiB in all, at least 4 KiB and at most 1.5 MiB each
    buffer_points_ = std::max<std::size_t>(4096 / (3 * sizeof(double)), (std::size_t(64) << 20) / (3 * sizeof(double)) / cells);
    buffer_points_ = std::min<std::size_t>(buffer_points_, 65536);
  }
  ~Tile_buckets()
  {
    std::error_code ignored;
    std::filesystem::remove_all(directory_, ignored);
  }
  Tile_buckets(const Tile_buckets&) = delete;
  Tile_buckets& operator=(const Tile_buckets&) = delete;

  // appends p to bucket `cell` (through its buffer)
  void add(std::size_t cell, const Point& p)
  {
    std::vector<double>& b = buffers_[cell];
    b.push_back(p.x());
    b.push_back(p.y());
    b.push_back(p.z());
    if(b.size() >= 3 * buffer_points_) flush(cell);
  }

  // writes what the buffers hold
  void flush()
  {
    for(std::size_t cell = 0; cell < buffers_.size(); ++cell) flush(cell);
  }

  // the points of bucket `cell` (thread-safe between distinct cells)
  std::vector<Point> read(std::size_t cell) const
  {
    std::vector<double> coordinates(3 * sizes_[cell]);
    if(!coordinates.empty()) {
      std::ifstream in(path(cell), std::ios::binary);
      in.read(reinterpret_cast<char*>(coordinates.data()), std::streamsize(coordinates.size() * sizeof(double)));
      if(!in) throw Input_error(Input_error_code::WRITE_FAILED, "cannot read back the bucket file " + path(cell));
    }
    std::vector<Point> points;
    points.reserve(sizes_[cell]);
    for(std::size_t i = 0; i < coordinates.size(); i += 3)
      points.emplace_back(coordinates[i], coordinates[i + 1], coordinates[i + 2]);
    return points;
  }

  // replaces the points of bucket `cell` (whose buffer is empty: after flush())
  void replace(std::size_t cell, const std::vector<Point>& points)
  {
    std::vector<double> coordinates;
    coordinates.reserve(3 * points.size());
    for(const Point& p : points) {
      coordinates.push_back(p.x());
      coordinates.push_back(p.y());
      coordinates.push_back(p.z());
    }
    std::ofstream out(path(cell), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(coordinates.data()), std::streamsize(coordinates.size() * sizeof(double)));
    if(!out.flush())
      throw Input_error(Input_error_code::WRITE_FAILED, "cannot write the bucket file " + path(cell) + " (no space left?)");
    sizes_[cell] = points.size();
  }

  std::size_t size(std::size_t cell) const { return sizes_[cell]; }

private:
  std::string path(std::size_t cell) const
  {
    return (std::filesystem::path(directory_) / ("bucket_" + std::to_string(cell) + ".bin")).string();
  }

  void flush(std::size_t cell)
  {
    std::vector<double>& b = buffers_[cell];
    if(b.empty()) return;
    std::ofstream out(path(cell), std::ios::binary | std::ios::app);
    out.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size() * sizeof(double)));
    if(!out.flush())
      throw Input_error(Input_error_code::WRITE_FAILED, "cannot write the bucket file " + path(cell) + " (no space left?)");
    sizes_[cell] += b.size() / 3;
    b.clear();
  }

  std::string directory_;
  std::vector<std::vector<double>> buffers_;
  std::vector<std::size_t> sizes_; // points written to each file
  std::size_t buffer_points_ = 0;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_TILE_BUCKETS_H
