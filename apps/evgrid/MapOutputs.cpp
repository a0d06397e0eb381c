/* evgrid: what more than one subcommand writes about a map. */

#include "MapOutputs.h"

#include <unistd.h>

#include <filesystem>
#include <iomanip>
#include <stdexcept>
#include <system_error>

#include <mrpt_evidential/support/NumberText.h>

using mrpt_evidential::CEvidentialGridMap2D;

namespace evgrid
{
void createFolder(const std::string& dir)
{
	if (dir.empty()) return;
	std::error_code ec;
	std::filesystem::create_directories(dir, ec);
	if (ec)
		throw std::runtime_error(
			dir + ": cannot create the folder: " + ec.message());
}

void checkOutputFile(const std::string& path, const std::vector<std::string>& inputs)
{
	namespace fs = std::filesystem;
	std::string dir = fs::path(path).parent_path().string();
	createFolder(dir);
	if (dir.empty()) dir = ".";
	std::error_code ec;
	const fs::file_status status = fs::status(path, ec);
	if (fs::is_directory(status))
		throw std::runtime_error(path + ": is a folder, not a file");
	if (fs::exists(status) && !fs::is_regular_file(status))
		throw std::runtime_error(
			path + ": is not a regular file (a device, a pipe or a socket); give a file");
	for (const auto& input : inputs)
		if (!input.empty() && fs::exists(status) && fs::equivalent(path, input, ec))
			throw std::runtime_error(
				path + ": is also an input (" + input + "): writing it would destroy it");
	if (access(dir.c_str(), W_OK) != 0)
		throw std::runtime_error(
			path + ": cannot be written: its folder is not writable");
}

std::vector<std::string> savePicturesIn(
	const CEvidentialGridMap2D& map, const std::string& dir, bool withLegend)
{
	createFolder(dir);
	// Appending an empty name gives the folder with exactly one trailing
	// separator, whether `dir` had one or not.
	const std::string prefix = (std::filesystem::path(dir) / "").string();
	map.savePictures(prefix, withLegend);
	std::vector<std::string> written;
	for (const char* name : CEvidentialGridMap2D::pictureNames())
		written.push_back(prefix + name);
	return written;
}

void printDecisionCounts(
	std::ostream& os, const CEvidentialGridMap2D::TDecisionCounts& counts,
	std::size_t cellCount)
{
	const auto flags = os.flags();
	const auto precision = os.precision();
	const auto line = [&](const char* what, std::size_t n) {
		os << "  " << std::left << std::setw(9) << what << std::right
		   << std::setw(12) << n << "  " << std::fixed << std::setprecision(2)
		   << std::setw(6)
		   << 100.0 * static_cast<double>(n) / static_cast<double>(cellCount)
		   << "%\n";
	};
	os << "cells by decision:\n";
	line("free", counts.free);
	line("occupied", counts.occupied);
	line("unknown", counts.unknown);
	line("conflict", counts.conflict);
	os.flags(flags);
	os.precision(precision);
}

void printMotionCounts(std::ostream& os, const CEvidentialGridMap2D& map)
{
	if (map.storage().keepsConflict())
	{
		os << "motion: none (the map keeps conflict: no motion layer)\n";
		return;
	}
	const auto counts = map.countMotion();
	os << "motion, within the last "
	   << mrpt_evidential::detail::shortestText(map.insertionOptions.motionWindow)
	   << " s of data time: appeared " << counts.appeared << " cells, disappeared "
	   << counts.disappeared << " cells\n";
}

void printMapOptions(std::ostream& os, const CEvidentialGridMap2D& map)
{
	os << std::defaultfloat << "options:\n";
	map.insertionOptions.dumpToTextStream(os);
	map.likelihoodOptions.dumpToTextStream(os);
	map.renderingOptions.dumpToTextStream(os);
}

}  // namespace evgrid
