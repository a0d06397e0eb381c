/* evgrid: an output folder whose files change only when a run succeeds. */

#include "COutputFolder.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <system_error>

#include "StopSignal.h"

namespace fs = std::filesystem;

namespace evgrid
{
COutputFolder::COutputFolder(const std::string& dir) : m_dir(dir)
{
	const auto cannot = [&dir](const std::string& why) {
		return std::runtime_error(
			dir + ": the output folder cannot be written: " + why);
	};
	std::error_code ec;
	if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
		throw cannot("it exists and is not a folder");
	fs::create_directories(dir, ec);
	if (ec) throw cannot(ec.message());

	// A name of our own: pid and a random tag keep concurrent runs apart,
	// the dot keeps it out of the way while it exists.
	const unsigned tag = std::random_device{}();
	m_staging = (fs::path(dir) / (".evgrid-build-" + std::to_string(getpid()) +
								  "-" + std::to_string(tag)))
					.string();
	if (!fs::create_directory(m_staging, ec))
		throw cannot(ec ? ec.message() : "a temporary folder already exists");
	// Creating a folder can succeed where writing a file does not (a full
	// disk, a quota): try one.
	const std::string probe = staged("probe");
	std::ofstream probeFile(probe);
	probeFile << "evgrid\n";
	probeFile.close();  // a full disk shows when the buffer is flushed
	if (!probeFile)
	{
		fs::remove_all(m_staging, ec);
		throw cannot("a test file cannot be created in it");
	}
	fs::remove(probe, ec);
}

COutputFolder::~COutputFolder()
{
	std::error_code ignored;
	fs::remove_all(m_staging, ignored);
}

std::string COutputFolder::staged(const std::string& name) const
{
	return (fs::path(m_staging) / name).string();
}

std::string COutputFolder::final(const std::string& name) const
{
	return (fs::path(m_dir) / name).string();
}

void COutputFolder::commit(const std::vector<std::string>& names)
{
	// Ctrl-C while the outputs were written: nothing moves into place.
	throwIfStopRequested();
	for (const std::string& name : names)
	{
		const std::string from = staged(name), to = final(name);
		std::error_code ec;
		if (!fs::exists(from, ec)) continue;
		if (fs::is_directory(from, ec))
		{
			// A folder cannot be renamed over a non-empty one: the old one
			// goes into the staging folder (removed below) first.
			if (fs::exists(to, ec))
				fs::rename(to, staged(".replaced-" + name), ec);
			if (!ec) fs::rename(from, to, ec);
		}
		else
			fs::rename(from, to, ec);
		if (ec)
			throw std::runtime_error(
				to + ": cannot be replaced: " + ec.message());
	}
	std::error_code ignored;
	fs::remove_all(m_staging, ignored);
}

}  // namespace evgrid
