/* evgrid: opening a file through zlib. */

#include "GzipFile.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace evgrid
{
gzFile openGzipForReading(const std::string& path)
{
	// zlib would open a directory and fail only on the first read.
	std::error_code ec;
	if (std::filesystem::is_directory(path, ec))
		throw std::runtime_error(path + ": is a directory, not a file");
	errno = 0;
	gzFile f = gzopen(path.c_str(), "rb");
	if (!f)
		throw std::runtime_error(
			path + ": cannot open: " +
			(errno != 0 ? std::strerror(errno) : "out of memory"));
	return f;
}
}  // namespace evgrid
