/* evgrid: opening a file through zlib, which reads plain and gzip-compressed
 * files alike. */
#pragma once

#include <zlib.h>

#include <string>

namespace evgrid
{
/** Opens `path` for reading. \throws std::runtime_error naming the file if it
 * is a directory or cannot be opened. */
gzFile openGzipForReading(const std::string& path);
}  // namespace evgrid
