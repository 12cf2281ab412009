// Copyright (c) 2026  The Lex_optimal_chains and Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// What the fuzz harnesses of both packages share: the readers under test take a path, so the
// fuzzer's bytes are written to a file of this process, with the extension that selects the
// reader; and a finding is reported by aborting, after a line that says what was found.

#ifndef URBAN_FUZZ_INPUT_FILE_H
#define URBAN_FUZZ_INPUT_FILE_H

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

namespace urban_fuzz {

// Writes `size` bytes to a file of this process in the temporary folder, named with
// `extension` (".xyz", ...), and returns its path; the same path for every call of a process.
inline std::string input_file(const std::uint8_t* data, std::size_t size, const std::string& extension)
{
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("urban_fuzz_" + std::to_string(::getpid()) + extension);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  out.close();
  if(!out) {
    std::cerr << "fuzz harness: cannot write " << path.string() << std::endl;
    std::abort();
  }
  return path.string();
}

inline void remove_input_file(const std::string& path)
{
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

// A finding: what the harness checks does not hold.
[[noreturn]] inline void finding(const std::string& what)
{
  std::cerr << "fuzz finding: " << what << std::endl;
  std::abort();
}

} // namespace urban_fuzz

#endif // URBAN_FUZZ_INPUT_FILE_H
