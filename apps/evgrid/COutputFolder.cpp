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
	// Checked before anything moves: an entry of the other kind where ours
	// goes (a folder named map.png) is the user's, not ours to remove.
	std::vector<std::string> toMove;
	for (const std::string& name : names)
	{
		std::error_code ec;
		const fs::path from = staged(name), to = final(name);
		if (!fs::exists(from, ec)) continue;
		const auto old = fs::symlink_status(to, ec);  // not_found when absent
		if (fs::exists(old) && fs::is_directory(old) != fs::is_directory(from, ec))
			throw std::runtime_error(
				to.string() + ": cannot be replaced: " +
				(fs::is_directory(old) ? "it is a folder" : "it is not a folder"));
		toMove.push_back(name);
	}
	// Each old entry moves aside into the staging folder (removed below),
	// then the new one into place. When a step fails, the steps done are
	// undone in reverse: the folder is left as it was, not half new.
	struct TStep
	{
		std::string name;
		bool movedAside = false, placed = false;
	};
	std::vector<TStep> done;
	const auto aside = [this](const std::string& name) { return staged(".replaced-" + name); };
	const auto undo = [&]() {
		for (auto step = done.rbegin(); step != done.rend(); ++step)
		{
			std::error_code ignored;
			if (step->placed) fs::rename(final(step->name), staged(step->name), ignored);
			if (step->movedAside) fs::rename(aside(step->name), final(step->name), ignored);
		}
	};
	for (const std::string& name : toMove)
	{
		const std::string to = final(name);
		TStep step{name};
		std::error_code ec, absent;
		if (fs::exists(fs::symlink_status(to, absent)))
		{
			fs::rename(to, aside(name), ec);
			step.movedAside = !ec;
		}
		if (!ec)
		{
			fs::rename(staged(name), to, ec);
			step.placed = !ec;
		}
		done.push_back(step);
		if (ec)
		{
			undo();
			throw std::runtime_error(to + ": cannot be replaced: " + ec.message());
		}
	}
	std::error_code ignored;
	fs::remove_all(m_staging, ignored);
}

}  // namespace evgrid
