/* evgrid_check: what the evgrid tests need to look into outputs (through
 * MRPT and OpenCV, as other programs would read them) and to prepare inputs.
 *
 *   evgrid_check image FILE               -> "WIDTH HEIGHT"
 *   evgrid_check gridmap FILE             -> "SIZE_X SIZE_Y RESOLUTION" of a .gridmap
 *   evgrid_check video FILE               -> "FRAMES WIDTH HEIGHT"
 *   evgrid_check cells MAP                -> "free X Y" and "occupied X Y": centres
 *                                            of the cells of largest m(F) and m(O)
 *   evgrid_check odometry-path RAWLOG OUT -> OUT: "time x y phi" of every scan of
 *                                            an action/sensory-frame rawlog
 *   evgrid_check to-obs-only RAWLOG OUT   -> OUT (gzip): the same rawlog in the
 *                                            observation-only format
 *   evgrid_check farther RAWLOG M OUT     -> OUT (gzip): the same rawlog, every
 *                                            scan's ranges M metres longer
 *   evgrid_check to-simplemap RAWLOG POSES OUT
 *                                         -> OUT (gzip): a simplemap of the
 *                                            rawlog's sensory frames, frame k at
 *                                            line k of POSES ("time x y phi")
 *   evgrid_check rotating-scan OUT        -> OUT (gzip): an observation-only rawlog
 *                                            of one CObservationRotatingScan (16
 *                                            rings, 360 firings, all at 5 m) and
 *                                            one 2-D scan (181 beams at 2 m)
 *   evgrid_check mrpt-version             -> MRPT's version, e.g. "2.5.8"
 *   evgrid_check scene FILE               -> the names of a .3Dscene's objects,
 *                                            one a line, those of a set after
 *                                            it indented, a set of lines with
 *                                            "(N lines)"
 *   evgrid_check footprint MAP FOOTPRINT  -> for each class of evgrid-simulate's
 *                                            footprint (ground, obstacle, low,
 *                                            overhang): "CLASS SEEN OCCUPIED_PCT",
 *                                            SEEN its cells the map decides Free or
 *                                            Occupied at their centres
 * Exit code 0 on success, 1 with a message otherwise. */

#include <mrpt/core/Clock.h>
#include <mrpt/version.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <vector>
#include <iostream>
#include <opencv2/videoio.hpp>
#include <stdexcept>
#include <string>

using namespace mrpt::obs;
using mrpt::poses::CPose2D;

namespace
{
/** Calls `visit(object)` for every object of a rawlog, in order. */
void forEachObject(
	const std::string& path,
	const std::function<void(const mrpt::serialization::CSerializable::Ptr&)>&
		visit)
{
	mrpt::io::CFileGZInputStream in(path);
	auto archive = mrpt::serialization::archiveFrom(in);
	for (;;)
	{
		mrpt::serialization::CSerializable::Ptr object;
		try
		{
			object = archive.ReadObject();
		}
		catch (const mrpt::serialization::CExceptionEOF&)
		{
			if (in.checkEOF()) return;
			throw;
		}
		visit(object);
	}
}

/** Calls `visit(odometry, frame)` for every sensory frame, with the sum of
 * the movement increments of the actions before it. */
void forEachFrame(
	const std::string& path,
	const std::function<void(const CPose2D&, const CSensoryFrame&)>& visit)
{
	CPose2D odometry;
	forEachObject(path, [&](const auto& object) {
		if (const auto actions =
				std::dynamic_pointer_cast<CActionCollection>(object))
		{
			if (const auto move = actions->getBestMovementEstimation())
				odometry = odometry + move->poseChange->getMeanVal();
		}
		else if (const auto frame =
					 std::dynamic_pointer_cast<CSensoryFrame>(object))
			visit(odometry, *frame);
	});
}

int image(const std::string& path)
{
	mrpt::img::CImage img;
	if (!img.loadFromFile(path)) throw std::runtime_error("cannot read " + path);
	std::cout << img.getWidth() << " " << img.getHeight() << "\n";
	return 0;
}

/** Lists `objects` (a viewport or a set), those of sets indented below them. */
template <typename Objects>
void listObjects(const Objects& objects, const std::string& indent)
{
	for (const auto& o : objects)
	{
		if (!o) continue;
		std::cout << indent << o->getName();
		if (const auto lines = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(o))
			std::cout << " (" << lines->getLineCount() << " lines)";
		std::cout << "\n";
		if (const auto set = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(o))
			listObjects(*set, indent + "  ");
	}
}

int scene(const std::string& path)
{
	// As SceneViewer3D opens it.
	mrpt::opengl::COpenGLScene s;
	if (!s.loadFromFile(path)) throw std::runtime_error("cannot read the scene " + path);
	listObjects(*s.getViewport(), "");
	return 0;
}

int gridmap(const std::string& path)
{
	// As pf-localization reads its map_file.
	mrpt::maps::COccupancyGridMap2D grid;
	mrpt::io::CFileGZInputStream in(path);
	mrpt::serialization::archiveFrom(in) >> grid;
	std::cout << grid.getSizeX() << " " << grid.getSizeY() << " "
			  << grid.getResolution() << "\n";
	return 0;
}

int video(const std::string& path)
{
	cv::VideoCapture capture(path, cv::CAP_OPENCV_MJPEG);
	if (!capture.isOpened()) throw std::runtime_error("cannot read " + path);
	int frames = 0, width = 0, height = 0;
	for (cv::Mat frame; capture.read(frame); ++frames)
		width = frame.cols, height = frame.rows;
	std::cout << frames << " " << width << " " << height << "\n";
	return 0;
}

int cells(const std::string& path)
{
	mrpt_evidential::CEvidentialGridMap2D map;
	mrpt::io::CFileGZInputStream in(path);
	mrpt::serialization::archiveFrom(in) >> map;
	const auto& g = map.geometry();
	double bestFree = -1, bestOccupied = -1;
	int fx = 0, fy = 0, ox = 0, oy = 0;
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (int cx = 0; cx < g.sizeX; ++cx)
		{
			const auto m = map.getCellMassesByIndex(cx, cy);
			if (m.free > bestFree) bestFree = m.free, fx = cx, fy = cy;
			if (m.occupied > bestOccupied)
				bestOccupied = m.occupied, ox = cx, oy = cy;
		}
	std::printf(
		"free %.17g %.17g\noccupied %.17g %.17g\n", g.cellCenterX(fx),
		g.cellCenterY(fy), g.cellCenterX(ox), g.cellCenterY(oy));
	return 0;
}

int odometryPath(const std::string& rawlog, const std::string& out)
{
	FILE* f = std::fopen(out.c_str(), "w");
	if (!f) throw std::runtime_error("cannot write " + out);
	std::fprintf(f, "# time x y phi: odometry at each scan of %s\n", rawlog.c_str());
	forEachFrame(rawlog, [f](const CPose2D& odometry, const CSensoryFrame& sf) {
		for (const auto& obs : sf)
			if (IS_CLASS(*obs, CObservation2DRangeScan))
				std::fprintf(
					f, "%.6f %.17g %.17g %.17g\n",
					mrpt::Clock::toDouble(obs->timestamp), odometry.x(),
					odometry.y(), odometry.phi());
	});
	return std::fclose(f) == 0 ? 0 : 1;
}

int toObservationOnly(const std::string& rawlog, const std::string& out)
{
	mrpt::io::CFileGZOutputStream f(out);
	auto archive = mrpt::serialization::archiveFrom(f);
	forEachFrame(rawlog, [&](const CPose2D& odometry, const CSensoryFrame& sf) {
		// A reading before each frame's observations: every scan then finds
		// the odometry its frame had.
		CObservationOdometry reading;
		reading.odometry = odometry;
		if (sf.size() > 0) reading.timestamp = sf.getObservationByIndex(0)->timestamp;
		archive << reading;
		for (const auto& obs : sf) archive << *obs;
	});
	return 0;
}
int farther(const std::string& rawlog, double metres, const std::string& out)
{
	mrpt::io::CFileGZOutputStream f(out);
	auto archive = mrpt::serialization::archiveFrom(f);
	forEachObject(rawlog, [&](const auto& object) {
		if (const auto frame = std::dynamic_pointer_cast<CSensoryFrame>(object))
			for (const auto& obs : *frame)
				if (auto* scan = dynamic_cast<CObservation2DRangeScan*>(obs.get()))
				{
					scan->maxRange += static_cast<float>(metres);
					for (std::size_t i = 0; i < scan->getScanSize(); ++i)
						scan->setScanRange(
							i, scan->getScanRange(i) + static_cast<float>(metres));
				}
		archive << *object;
	});
	return 0;
}
}  // namespace

int toSimplemap(const std::string& rawlog, const std::string& poses, const std::string& out)
{
	std::ifstream file(poses);
	std::vector<CPose2D> path;
	for (std::string line; std::getline(file, line);)
	{
		if (line.empty() || line[0] == '%' || line[0] == '#') continue;
		std::istringstream words(line);
		double t, x, y, phi;
		if (!(words >> t >> x >> y >> phi)) throw std::runtime_error(poses + ": bad line " + line);
		path.emplace_back(x, y, phi);
	}
	mrpt::maps::CSimpleMap simplemap;
	std::size_t k = 0;
	forEachFrame(rawlog, [&](const CPose2D&, const CSensoryFrame& sf) {
		if (k >= path.size()) throw std::runtime_error(poses + ": fewer poses than frames");
		// Shared pointers: MRPT 2.14 has no insert() that copies.
		simplemap.insert(
			std::make_shared<mrpt::poses::CPose3DPDFGaussian>(
				mrpt::poses::CPose3D(path[k++])),
			std::make_shared<CSensoryFrame>(sf));
	});
	mrpt::io::CFileGZOutputStream f(out);
	mrpt::serialization::archiveFrom(f) << simplemap;
	return 0;
}

int rotatingScan(const std::string& out)
{
	CObservationRotatingScan scan;
	scan.sensorLabel = "LIDAR";
	scan.timestamp = mrpt::Clock::fromDouble(1000.0);
	scan.rowCount = 16;
	scan.columnCount = 360;
	scan.rangeResolution = 0.01;
	scan.rangeImage.setConstant(scan.rowCount, scan.columnCount, 500);
	CObservation2DRangeScan flat;
	flat.sensorLabel = "LASER";
	flat.timestamp = mrpt::Clock::fromDouble(1000.1);
	flat.aperture = static_cast<float>(M_PI);
	flat.resizeScan(181);
	for (std::size_t i = 0; i < 181; ++i) flat.setScanRange(i, 2.0f), flat.setScanRangeValidity(i, true);
	mrpt::io::CFileGZOutputStream f(out);
	mrpt::serialization::archiveFrom(f) << scan << flat;
	return 0;
}

/** The cells of a footprint line's items ("I" or "I-J"). */
std::vector<long> footprintCells(std::istringstream& items)
{
	std::vector<long> cells;
	long count = 0;
	items >> count;
	std::string item;
	while (items >> item)
	{
		const auto dash = item.find('-');
		const long a = std::stol(item.substr(0, dash));
		const long b = dash == std::string::npos ? a : std::stol(item.substr(dash + 1));
		for (long c = a; c <= b; ++c) cells.push_back(c);
	}
	if (static_cast<long>(cells.size()) != count)
		throw std::runtime_error("a footprint line whose count is not its cells'");
	return cells;
}

int footprint(const std::string& mapPath, const std::string& footprintPath)
{
	mrpt_evidential::CEvidentialGridMap2D map;
	mrpt::io::CFileGZInputStream in(mapPath);
	mrpt::serialization::archiveFrom(in) >> map;
	mrpt::io::CFileGZInputStream fp(footprintPath);
	std::string line, text;
	while (fp.getline(line)) text += line + "\n";
	std::istringstream lines(text);
	double x0 = 0, y0 = 0, res = 0;
	long nx = 0, ny = 0;
	std::map<long, std::string> classOf;
	while (std::getline(lines, line))
	{
		std::istringstream words(line);
		std::string key;
		words >> key;
		if (key == "grid") words >> x0 >> y0 >> res >> nx >> ny;
		if (key == "obstacle" || key == "low" || key == "overhang")
			for (const long c : footprintCells(words)) classOf[c] = key;
	}
	if (!(res > 0) || nx <= 0 || ny <= 0) throw std::runtime_error(footprintPath + ": no grid line");
	std::map<std::string, std::pair<long, long>> seenAndOccupied;
	for (long c = 0; c < nx * ny; ++c)
	{
		const auto it = classOf.find(c);
		const std::string cls = it == classOf.end() ? "ground" : it->second;
		const double x = x0 + (static_cast<double>(c % nx) + 0.5) * res;
		const double y = y0 + (static_cast<double>(c / nx) + 0.5) * res;
		const auto d = map.getCellDecision(x, y);
		auto& [seen, occupied] = seenAndOccupied[cls];
		if (d == mrpt_evidential::Decision::Free || d == mrpt_evidential::Decision::Occupied) ++seen;
		if (d == mrpt_evidential::Decision::Occupied) ++occupied;
	}
	for (const auto& [cls, n] : seenAndOccupied)
		std::printf("%s %ld %.2f\n", cls.c_str(), n.first,
					n.first > 0 ? 100.0 * static_cast<double>(n.second) / static_cast<double>(n.first) : 0.0);
	return 0;
}

int main(int argc, char** argv)
{
	try
	{
		const std::string what = argc > 1 ? argv[1] : "";
		if (what == "image" && argc == 3) return image(argv[2]);
		if (what == "gridmap" && argc == 3) return gridmap(argv[2]);
		if (what == "scene" && argc == 3) return scene(argv[2]);
		if (what == "video" && argc == 3) return video(argv[2]);
		if (what == "cells" && argc == 3) return cells(argv[2]);
		if (what == "to-simplemap" && argc == 5) return toSimplemap(argv[2], argv[3], argv[4]);
		if (what == "rotating-scan" && argc == 3) return rotatingScan(argv[2]);
		if (what == "mrpt-version" && argc == 2)
			return std::printf(
					   "%d.%d.%d\n", MRPT_EVIDENTIAL_MRPT_VERSION >> 16,
					   (MRPT_EVIDENTIAL_MRPT_VERSION >> 8) & 0xFF, MRPT_EVIDENTIAL_MRPT_VERSION & 0xFF) < 0;
		if (what == "footprint" && argc == 4) return footprint(argv[2], argv[3]);
		if (what == "odometry-path" && argc == 4)
			return odometryPath(argv[2], argv[3]);
		if (what == "to-obs-only" && argc == 4)
			return toObservationOnly(argv[2], argv[3]);
		if (what == "farther" && argc == 5)
			return farther(argv[2], std::stod(argv[3]), argv[4]);
		std::cerr << "usage: see the comment at the top of evgrid_check.cpp\n";
		return 2;
	}
	catch (const std::exception& e)
	{
		std::cerr << "evgrid_check: " << e.what() << "\n";
		return 1;
	}
}
