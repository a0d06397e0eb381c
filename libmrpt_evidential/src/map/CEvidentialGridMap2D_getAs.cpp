/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: pictures, conversions and files. */

#include <mrpt/img/CImage.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/archiveFrom_std_streams.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <mrpt_evidential/support/AtomicFile.h>
#include <mrpt_evidential/support/NumberText.h>
#include "map/OptionsCheck.h"
#include "render/PictureLegend.h"

using namespace mrpt_evidential;
using mrpt_evidential::detail::writeFileAtomically;

namespace
{
/** ROS map_server's default thresholds: a cell whose occupancy exceeds the
 * first is an obstacle, below the second it is free, unknown in between. */
constexpr double kRosOccupiedThresh = 0.65;
constexpr double kRosFreeThresh = 0.196;

/** A value in [0, 1] as a byte, rounded to nearest; out of range clamped. */
std::uint8_t toByte(double v)
{
	return static_cast<std::uint8_t>(
		std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

/** Fills img with one pixel per cell, row 0 holding the largest y;
 * `pixel(cellIndex, out)` writes the channels of one cell. */
template <typename PixelFn>
void paint(
	const EvidentialGridStorage& grid, mrpt::img::CImage& img,
	mrpt::img::TImageChannels channels, PixelFn pixel)
{
	const GridGeometry& g = grid.geometry();
	img.resize(
		static_cast<std::size_t>(g.sizeX), static_cast<std::size_t>(g.sizeY),
		channels);
	for (int row = 0; row < g.sizeY; ++row)
	{
		auto* out = img.ptrLine<std::uint8_t>(static_cast<unsigned>(row));
		const std::size_t first = g.index(0, g.sizeY - 1 - row);
		for (int cx = 0; cx < g.sizeX; ++cx, out += channels)
			pixel(first + static_cast<std::size_t>(cx), out);
	}
}

/** A number's text as a YAML 1.1 float: that grammar (PyYAML's, ROS's
 * Python tools') wants a point, and reads "1e+06" or "5e-05" as strings. */
std::string yamlFloat(std::string text)
{
	const auto exponent = text.find_first_of("eE");
	if (exponent != std::string::npos && text.find('.') == std::string::npos)
		text.insert(exponent, ".0");
	return text;
}

/** A file name as a YAML scalar: plain when that is unambiguous, else
 * double-quoted. */
std::string yamlScalar(const std::string& s)
{
	const bool plain = !s.empty() &&
		std::all_of(s.begin(), s.end(), [](char c) {
						   return std::isalnum(static_cast<unsigned char>(c)) ||
							   c == '.' || c == '_' || c == '-' || c == '+';
					   }) &&
		s.front() != '-';
	if (plain) return s;
	std::string q = "\"";
	for (const char c : s)
	{
		if (c == '"' || c == '\\') q += '\\';
		q += c;
	}
	return q + "\"";
}

/** Writes savePictures()'s pictures into `files`. */
void stagePictures(
	const CEvidentialGridMap2D& map, detail::CAtomicFileSet& files, const std::string& prefix,
	bool withLegend)
{
	mrpt::img::CImage img;
	for (std::size_t i = 0; i < CEvidentialGridMap2D::pictureNames().size(); ++i)
	{
		map.getAsPicture(i, img, withLegend);
		files.addByName(prefix + CEvidentialGridMap2D::pictureNames()[i], [&img](const std::string& tmp) {
			return img.saveToFile(tmp);
		});
	}
}
}  // namespace

void CEvidentialGridMap2D::getAsEvidentialImage(mrpt::img::CImage& img) const
{
	// CImage keeps colour pixels in OpenCV's order, blue first: the order its
	// setPixel(0xRRGGBB), saveToFile and the OpenGL texture upload assume.
	paint(m_grid, img, mrpt::img::CH_RGB, [this](std::size_t idx, std::uint8_t* p) {
		const Mass m = m_grid.read(idx);
		p[0] = toByte(m.unknown + m.conflict);
		p[1] = toByte(m.free + m.conflict);
		p[2] = toByte(m.occupied + m.conflict);
	});
}

void CEvidentialGridMap2D::getAsBetPImage(mrpt::img::CImage& img) const
{
	paint(m_grid, img, mrpt::img::CH_GRAY, [this](std::size_t idx, std::uint8_t* p) {
		p[0] = toByte(1.0 - betP(m_grid.read(idx)));
	});
}

void CEvidentialGridMap2D::getAsConflictImage(mrpt::img::CImage& img) const
{
	paint(m_grid, img, mrpt::img::CH_GRAY, [this](std::size_t idx, std::uint8_t* p) {
		p[0] = toByte(m_grid.read(idx).conflict);
	});
}

void CEvidentialGridMap2D::getAsMotionImage(mrpt::img::CImage& img) const
{
	paintMotion(img, [this](std::size_t idx) { return motionOf(idx); });
}

void CEvidentialGridMap2D::paintMotion(
	mrpt::img::CImage& img, const std::function<Motion(std::size_t)>& motion) const
{
	const auto put = [](std::uint8_t* p, const mrpt::img::TColor& c) {
		p[0] = c.B, p[1] = c.G, p[2] = c.R;  // blue first, as in getAsEvidentialImage()
	};
	paint(m_grid, img, mrpt::img::CH_RGB, [&](std::size_t idx, std::uint8_t* p) {
		switch (motion(idx))
		{
			case Motion::Appeared: return put(p, renderingOptions.appearedColor);
			case Motion::Disappeared: return put(p, renderingOptions.disappearedColor);
			case Motion::None: break;
		}
		p[0] = p[1] = p[2] = toByte(1.0 - betP(m_grid.read(idx)));
	});
}

void CEvidentialGridMap2D::getAsOccupancyGrid(
	mrpt::maps::COccupancyGridMap2D& grid) const
{
	// COccupancyGridMap2D snaps its bounds to multiples of the resolution and
	// stores floats. With as many cells as ours (our origin on its lattice,
	// give or take a float's rounding: up to 0.25 m at UTM coordinates), each
	// of its cells takes ours of the same index; else (an origin off its
	// lattice) the cell holding its centre, worked out in doubles (its own
	// float centres repeat from 1e6 m on, and rows would be copied in place
	// of others). Its cells hold the probability of being free (0 = occupied).
	const GridGeometry& g = geometry();
	grid.setSize(
		static_cast<float>(g.xMin), static_cast<float>(g.xMax()),
		static_cast<float>(g.yMin), static_cast<float>(g.yMax()),
		static_cast<float>(g.resolution), 0.5f);
	const double x0 = grid.getXMin(), y0 = grid.getYMin();
	const bool sameCells = static_cast<int>(grid.getSizeX()) == g.sizeX &&
		static_cast<int>(grid.getSizeY()) == g.sizeY;
	for (unsigned cy = 0; cy < grid.getSizeY(); ++cy)
		for (unsigned cx = 0; cx < grid.getSizeX(); ++cx)
		{
			const double p = sameCells
				? betP(m_grid.read(g.index(static_cast<int>(cx), static_cast<int>(cy))))
				: getCellBetP(x0 + (cx + 0.5) * g.resolution, y0 + (cy + 0.5) * g.resolution);
			grid.setCell(static_cast<int>(cx), static_cast<int>(cy), static_cast<float>(1.0 - p));
		}
}

void CEvidentialGridMap2D::saveAsROSMap(const std::string& prefix) const
{
	const GridGeometry& g = geometry();
	const std::string pgmPath = prefix + ".pgm";
	// map_server's trinary convention: 0 occupied, 254 free, 205 unknown; it
	// reads a pixel back as occupancy (255 - value) / 255 against the same
	// thresholds, so each class survives a load.
	writeFileAtomically(pgmPath, [&](std::ostream& os) {
		os << "P5\n# mrpt-evidential: occupancy = BetP\n"
		   << g.sizeX << ' ' << g.sizeY << "\n255\n";
		std::vector<char> line(static_cast<std::size_t>(g.sizeX));
		for (int row = 0; row < g.sizeY; ++row)
		{
			const std::size_t first = g.index(0, g.sizeY - 1 - row);
			for (std::size_t cx = 0; cx < line.size(); ++cx)
			{
				const double p = betP(m_grid.read(first + cx));
				line[cx] = static_cast<char>(
					p > kRosOccupiedThresh ? 0 : p < kRosFreeThresh ? 254 : 205);
			}
			os.write(line.data(), static_cast<std::streamsize>(line.size()));
		}
	});
	writeFileAtomically(prefix + ".yaml", [&](std::ostream& os) {
		os << "image: "
		   << yamlScalar(std::filesystem::path(pgmPath).filename().string())
		   << "\nresolution: " << yamlFloat(detail::shortestText(g.resolution))
		   << "\norigin: [" << yamlFloat(detail::metresText(g.xMin)) << ", "
		   << yamlFloat(detail::metresText(g.yMin)) << ", 0.0]\nnegate: 0\noccupied_thresh: "
		   << yamlFloat(detail::shortestText(kRosOccupiedThresh))
		   << "\nfree_thresh: " << yamlFloat(detail::shortestText(kRosFreeThresh)) << "\n";
	});
}

std::vector<std::pair<double, double>>
	CEvidentialGridMap2D::getOccupiedCellCenters() const
{
	const GridGeometry& g = geometry();
	std::vector<std::pair<double, double>> centers;
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (int cx = 0; cx < g.sizeX; ++cx)
			if (decide(m_grid.read(g.index(cx, cy))) == Decision::Occupied)
				centers.emplace_back(g.cellCenterX(cx), g.cellCenterY(cy));
	return centers;
}

const std::array<const char*, 5>& CEvidentialGridMap2D::pictureNames()
{
	static const std::array<const char*, 5> names{
		"map.png", "evidential.png", "betp.png", "conflict.png", "motion.png"};
	return names;
}

namespace
{
/** What the colours of picture `which` (of pictureNames()) mean. */
std::vector<detail::LegendEntry> legendOf(
	std::size_t which, const CEvidentialGridMap2D::TRenderingOptions& ro)
{
	const mrpt::img::TColor white{255, 255, 255}, black{0, 0, 0}, grey{128, 128, 128};
	switch (which)
	{
		case 0:
			return {{ro.freeColor, "free"},         {ro.occupiedColor, "occupied"},
					{ro.unknownColor, "unknown"},   {ro.conflictColor, "conflict"},
					{ro.appearedColor, "appeared"}, {ro.disappearedColor, "disappeared"}};
		case 1:
			return {{{255, 0, 0}, "m(O)"}, {{0, 255, 0}, "m(F)"}, {{0, 0, 255}, "m(Omega)"},
					{white, "conflict"}};
		case 2: return {{white, "BetP 0 (free)"}, {grey, "0.5"}, {black, "1 (occupied)"}};
		case 3: return {{black, "no conflict"}, {white, "total conflict"}};
		default:
			return {{white, "free"},
					{black, "occupied"},
					{grey, "unknown"},
					{ro.appearedColor, "appeared"},
					{ro.disappearedColor, "disappeared"}};
	}
}
constexpr std::size_t kMotionPicture = 4;
}  // namespace

void CEvidentialGridMap2D::getAsPicture(
	std::size_t which, mrpt::img::CImage& img, bool withLegend, int width, int height) const
{
	// A frame of any size would be allocated (100000 x 100000: 30 GB).
	constexpr int kMaxFrame = 8192;
	if (width < 0 || height < 0 || width > kMaxFrame || height > kMaxFrame)
		throw std::invalid_argument(
			"getAsPicture: a frame of " + std::to_string(width) + " x " + std::to_string(height) +
			" pixels; each side must be in [0, 8192]");
	using Painter = void (CEvidentialGridMap2D::*)(mrpt::img::CImage&) const;
	const std::array<Painter, 5> painters{
		&CEvidentialGridMap2D::getAsImage, &CEvidentialGridMap2D::getAsEvidentialImage,
		&CEvidentialGridMap2D::getAsBetPImage, &CEvidentialGridMap2D::getAsConflictImage,
		&CEvidentialGridMap2D::getAsMotionImage};
	(this->*painters.at(which))(img);
	if (withLegend)
		img = detail::withLegend(
			img, geometry().resolution, legendOf(which, renderingOptions), width, height);
}

void CEvidentialGridMap2D::getAsChangesImage(
	const TMapChanges& changes, mrpt::img::CImage& img, bool withLegend) const
{
	// The changes are numbered cx + sizeX cy; the grid's own indices may
	// leave room between rows.
	const GridGeometry& g = geometry();
	std::vector<Motion> motion(g.cellCount(), Motion::None);
	const auto mark = [&](const std::vector<std::size_t>& cells, Motion m) {
		for (const std::size_t i : cells)
			if (i < motion.size()) motion[i] = m;
	};
	mark(changes.appeared, Motion::Appeared);
	mark(changes.disappeared, Motion::Disappeared);
	const GridGeometry packed = g.packed();
	paintMotion(
		img, [&](std::size_t idx) { return motion[packed.index(g.columnOf(idx), g.rowOf(idx))]; });
	if (withLegend)
		img = detail::withLegend(
			img, geometry().resolution, legendOf(kMotionPicture, renderingOptions));
}

void CEvidentialGridMap2D::savePictures(const std::string& prefix, bool withLegend) const
{
	detail::CAtomicFileSet files;
	stagePictures(*this, files, prefix, withLegend);
	files.commit();
}

std::string CEvidentialGridMap2D::geometryText(const std::string& indent) const
{
	const GridGeometry& g = geometry();
	using detail::metresText;
	std::ostringstream s;
	s << indent << "x: [" << metresText(g.xMin) << ", " << metresText(g.xMax())
	  << "] m\n"
	  << indent << "y: [" << metresText(g.yMin) << ", " << metresText(g.yMax())
	  << "] m\n"
	  << indent << "resolution: " << metresText(g.resolution) << " m\n"
	  << indent << "cells: " << g.sizeX << " x " << g.sizeY << " (budget "
	  << m_maxCells << ")\n";
	return s.str();
}

void CEvidentialGridMap2D::saveMetricMapRepresentationToFile(
	const std::string& filNamePrefix) const
{
	// A prefix that names a folder (out/, or nothing) would write hidden
	// files (out/.evgrid) beside pictures named _map.png.
	if (filNamePrefix.empty() || filNamePrefix.back() == '/')
		throw std::invalid_argument(
			"CEvidentialGridMap2D::saveMetricMapRepresentationToFile: the prefix '" +
			filNamePrefix + "' names a folder, not the files' name (e.g. out/map)");
	// Before any file: the .evgrid's write would refuse them after the pictures.
	detail::validateSavedOptions(
		insertionOptions, likelihoodOptions, renderingOptions, geometry().resolution);
	// All or nothing: a failure (a full disk) leaves an earlier call's files
	// as they were, not pictures of one map beside the file of another.
	detail::CAtomicFileSet files;
	stagePictures(*this, files, filNamePrefix + "_", true);
	files.addByName(
		filNamePrefix + ".3Dscene", [this](const std::string& tmp) { return writeScene(tmp, {}); });
	files.add(filNamePrefix + "_info.txt", [this](std::ostream& os) {
		const TDecisionCounts c = countDecisions();
		os << "mrpt_evidential::CEvidentialGridMap2D\n"
		   << geometryText() << "insertions: " << insertionCount() << "\n"
		   << "latest time: " << detail::shortestText(latestTime()) << " s\n"
		   << "cells by decision: free " << c.free << ", occupied "
		   << c.occupied << ", unknown " << c.unknown << ", conflict "
		   << c.conflict << "\n\n";
		insertionOptions.dumpToTextStream(os);
		likelihoodOptions.dumpToTextStream(os);
		renderingOptions.dumpToTextStream(os);
		os << "// genericMapParams\n";
		genericMapParams.dumpToTextStream(os);
	});

	files.add(filNamePrefix + ".evgrid", [this](std::ostream& os) {
		auto ar = mrpt::serialization::archiveFrom<std::ostream>(os);
		ar << *this;
	});
	files.commit();
}
