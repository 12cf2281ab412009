// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_WRITE_TEXT_FILE_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_WRITE_TEXT_FILE_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

/// writes `text` to the file `file_name`: whether it was written. The text is made before the
/// file is opened, so that an error in making it leaves the file untouched; a file whose
/// writing failed is removed, so that no partial output is left.
inline bool write_text_file(const std::string& file_name, const std::string& text)
{
  std::ofstream out(file_name, std::ios::binary);
  if(!out) return false;
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if(!out) {
    std::error_code error;
    std::filesystem::remove(file_name, error);
    return false;
  }
  return true;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_WRITE_TEXT_FILE_H
