// Copyright (c) 2026  The Lex_optimal_chains and Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The main() of a fuzz harness built without libFuzzer (any compiler): it runs the harness's
// LLVMFuzzerTestOneInput() once on each file given, or on each file of each folder given, in
// the order of their names, so that the seed corpus and every crash the fuzzers found run as
// regression tests in ctest. A harness reports a finding by aborting.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for(int i = 1; i < argc; ++i) {
    const fs::path given(argv[i]);
    if(fs::is_directory(given)) {
      for(const auto& entry : fs::directory_iterator(given))
        if(entry.is_regular_file()) files.push_back(entry.path());
    } else if(fs::is_regular_file(given)) {
      files.push_back(given);
    } else {
      std::cerr << "error: " << given.string() << " is neither a file nor a folder" << std::endl;
      return 1;
    }
  }
  std::sort(files.begin(), files.end());
  if(files.empty()) {
    std::cerr << "error: no input to replay" << std::endl;
    return 1;
  }
  for(const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::cout << file.filename().string() << " (" << bytes.size() << " bytes)" << std::endl;
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << files.size() << " inputs replayed" << std::endl;
  return 0;
}
