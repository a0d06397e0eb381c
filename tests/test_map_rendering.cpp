/* How CEvidentialGridMap2D is drawn: the classes of cells and their colours,
 * the 3-D view's objects, the rendering options in .ini files, the legends of
 * saved pictures, video frames and scene files. */

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/img/CImage.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CSetOfTriangles.h>
#include <mrpt/opengl/CTexturedPlane.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "render/CellRectangles.h"
#include "render/PictureLegend.h"
#include "support/maps.h"
#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using CellClass = CEvidentialGridMap2D::CellClass;
namespace fs = std::filesystem;

namespace
{
const test::ScanSetup kSetup = test::ScanSetup().maxRange(10.0);
constexpr std::size_t kRays = 181;

/** A map with free, occupied and unknown cells, and cells where something
 * appeared and where something left: a board seen at 2 m in front of a wall
 * at 3 m moves sideways by an eighth of the field of view (the cells it
 * comes to were free, those it leaves occupied). A thing that moves fills a
 * small share of a scan; a scan half of whose world moved at once would be
 * taken for one whose pose is off. */
CEvidentialGridMap2D movingWallMap()
{
	CEvidentialGridMap2D map(-4.0, 4.0, -4.0, 4.0, 0.1);
	map.insertionOptions.growthMargin = 0.0;
	map.insertionOptions.motionWindow = 100.0;
	const mrpt::poses::CPose3D origin;
	// The board's old place, hit three times, leans free after some six
	// free sights: then its departure is reported.
	for (int phase = 0; phase < 2; ++phase)
		for (int i = 0; i < 3 + 5 * phase; ++i)
			map.insertObservation(
				test::scanByIndex(
					kRays, kSetup.at(1.0 + 3 * phase + i),
					[phase](std::size_t ray) {
						const std::size_t eighth = ray / (kRays / 8);
						return eighth == static_cast<std::size_t>(2 + phase) ? 2.0 : 3.0;
					}),
				origin);
	return map;
}

/** The area a set of triangles covers (the triangles flat in z). */
double areaOf(const mrpt::opengl::CSetOfTriangles& set)
{
	double area = 0.0;
	for (std::size_t i = 0; i < set.getTrianglesCount(); ++i)
	{
		mrpt::opengl::TTriangle t;
		set.getTriangle(i, t);
		area += 0.5 * std::abs(
						  (t.x(1) - t.x(0)) * (t.y(2) - t.y(0)) -
						  (t.x(2) - t.x(0)) * (t.y(1) - t.y(0)));
	}
	return area;
}

/** The map's cells counted by class. */
std::map<CellClass, std::size_t> classCounts(const CEvidentialGridMap2D& map)
{
	std::map<CellClass, std::size_t> n;
	const GridGeometry& g = map.geometry();
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (int cx = 0; cx < g.sizeX; ++cx)
			++n[map.classOfCell(g.cellCenterX(cx), g.cellCenterY(cy))];
	return n;
}

/** The RGB of pixel (x, y) of an 8-bit colour CImage (blue first). */
mrpt::img::TColor pixel(const mrpt::img::CImage& img, unsigned x, unsigned y)
{
	return mrpt::img::TColor(
		img.at<std::uint8_t>(x, y, 2), img.at<std::uint8_t>(x, y, 1),
		img.at<std::uint8_t>(x, y, 0));
}

bool sameColor(const mrpt::img::TColor& a, const mrpt::img::TColor& b)
{
	return a.R == b.R && a.G == b.G && a.B == b.B;
}

/** The objects of the map's 3-D view by name. */
std::map<std::string, mrpt::opengl::CRenderizable::Ptr> objectsOf(const CEvidentialGridMap2D& map)
{
	mrpt::opengl::CSetOfObjects set;
	map.getVisualizationInto(set);
	std::map<std::string, mrpt::opengl::CRenderizable::Ptr> objects;
	for (const auto& o : set) objects[o->getName()] = o;
	EXPECT_EQ(objects.size(), set.size()) << "two objects share a name";
	return objects;
}

/** The class objects of the map's 3-D view by name. */
std::map<std::string, mrpt::opengl::CSetOfTriangles::Ptr> trianglesOf(
	const CEvidentialGridMap2D& map)
{
	std::map<std::string, mrpt::opengl::CSetOfTriangles::Ptr> sets;
	for (const auto& [name, o] : objectsOf(map))
	{
		auto t = std::dynamic_pointer_cast<mrpt::opengl::CSetOfTriangles>(o);
		EXPECT_TRUE(t) << name << " is a " << o->GetRuntimeClass()->className;
		if (t) sets[name] = t;
	}
	return sets;
}
}  // namespace

TEST(MapRendering, ThePictureColoursEachCellByItsClass)
{
	const CEvidentialGridMap2D map = movingWallMap();
	auto n = classCounts(map);
	// The scene has every class but conflict (the map does not keep it).
	for (const CellClass c :
		 {CellClass::Free, CellClass::Occupied, CellClass::Unknown, CellClass::Appeared,
		  CellClass::Disappeared})
		ASSERT_GT(n[c], 0u) << "class " << int(c);
	EXPECT_EQ(n[CellClass::Conflict], 0u);
	EXPECT_EQ(n[CellClass::Appeared], map.countMotion().appeared);
	EXPECT_EQ(n[CellClass::Disappeared], map.countMotion().disappeared);

	mrpt::img::CImage img;
	map.getAsImage(img);
	const GridGeometry& g = map.geometry();
	ASSERT_EQ(img.getWidth(), static_cast<std::size_t>(g.sizeX));
	ASSERT_EQ(img.getHeight(), static_cast<std::size_t>(g.sizeY));
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (int cx = 0; cx < g.sizeX; ++cx)
		{
			const CellClass c = map.classOfCell(g.cellCenterX(cx), g.cellCenterY(cy));
			ASSERT_TRUE(sameColor(
				pixel(img, static_cast<unsigned>(cx), static_cast<unsigned>(g.sizeY - 1 - cy)),
				map.renderingOptions.colorOf(c)))
				<< "cell (" << cx << ", " << cy << ")";
		}
	// Outside the map, and at NaN: unknown.
	EXPECT_EQ(map.classOfCell(100.0, 0.0), CellClass::Unknown);
	EXPECT_EQ(map.classOfCell(std::nan(""), 0.0), CellClass::Unknown);
}

TEST(MapRendering, TheThreeDViewHasOneUnlitObjectPerClassShown)
{
	const CEvidentialGridMap2D map = movingWallMap();
	const auto sets = trianglesOf(map);
	// Unknown cells are transparent by default: no object for them.
	const std::vector<std::pair<std::string, CellClass>> expected{
		{"evidentialGrid.free", CellClass::Free},
		{"evidentialGrid.occupied", CellClass::Occupied},
		{"evidentialGrid.disappeared", CellClass::Disappeared},
		{"evidentialGrid.appeared", CellClass::Appeared}};
	ASSERT_EQ(sets.size(), expected.size());

	const GridGeometry& g = map.geometry();
	const double cellArea = g.resolution * g.resolution;
	for (const auto& [name, cls] : expected)
	{
		ASSERT_EQ(sets.count(name), 1u) << name;
		const auto& set = sets.at(name);
		EXPECT_FALSE(set->isLightEnabled()) << name;
		// The triangles cover the class's cells, flat at `height`, in the
		// class's colour: each triangle's centroid lies in such a cell, and
		// together they have the cells' area (and their seams).
		for (std::size_t i = 0; i < set->getTrianglesCount(); ++i)
		{
			mrpt::opengl::TTriangle t;
			set->getTriangle(i, t);
			double cx = 0, cy = 0;
			for (int k = 0; k < 3; ++k)
			{
				ASSERT_FLOAT_EQ(t.z(k), static_cast<float>(map.renderingOptions.height));
				ASSERT_TRUE(sameColor(
					mrpt::img::TColor(t.r(k), t.g(k), t.b(k)), map.renderingOptions.colorOf(cls)))
					<< name;
				cx += t.x(k) / 3.0, cy += t.y(k) / 3.0;
			}
			// Vertices are given from the set's pose (the grid's origin).
			cx += set->getPose().x, cy += set->getPose().y;
			ASSERT_EQ(map.classOfCell(cx, cy), cls) << name << " at (" << cx << ", " << cy << ")";
		}
		const double area = areaOf(*set);
		// Each rectangle overlaps its neighbours by a tenth of a cell (no
		// cracks at T-junctions): at most 1.2^2 times the area of its cells.
		const double cells = static_cast<double>(classCounts(map).at(cls));
		EXPECT_GE(area / cellArea, cells - 1e-3) << name;
		EXPECT_LE(area / cellArea, cells * 1.2 * 1.2 + 1e-3) << name;
	}
}

TEST(MapRendering, RectanglesCoverExactlyTheCellsOfALabel)
{
	// A pattern with runs that continue, split and join from row to row.
	const int sx = 13, sy = 11;
	std::vector<std::uint8_t> labels(sx * sy);
	for (int cy = 0; cy < sy; ++cy)
		for (int cx = 0; cx < sx; ++cx)
			labels[cy * sx + cx] = static_cast<std::uint8_t>(((cx * 7 + cy * 3) / 5 + (cx > 8)) % 3);
	for (const int maxSide : {1, 2, 3, 100})
		for (std::uint8_t label = 0; label < 4; ++label)
		{
			std::vector<int> cover(labels.size(), 0);
			for (const auto& r : detail::rectanglesOf(labels, sx, sy, label, maxSide))
			{
				ASSERT_LE(r.cx1 - r.cx0 + 1, maxSide);
				ASSERT_LE(r.cy1 - r.cy0 + 1, maxSide);
				for (int cy = r.cy0; cy <= r.cy1; ++cy)
					for (int cx = r.cx0; cx <= r.cx1; ++cx) ++cover[cy * sx + cx];
			}
			for (std::size_t i = 0; i < labels.size(); ++i)
				ASSERT_EQ(cover[i], labels[i] == label ? 1 : 0)
					<< "label " << int(label) << ", cell " << i << ", sides of " << maxSide;
		}
	// A uniform grid is one rectangle, or as many as its sides' cuts make.
	const std::vector<std::uint8_t> uniform(sx * sy, 1);
	EXPECT_EQ(detail::rectanglesOf(uniform, sx, sy, 1, 100).size(), 1u);
	EXPECT_EQ(detail::rectanglesOf(uniform, sx, sy, 1, 4).size(), 4u * 3u);
	EXPECT_THROW(detail::rectanglesOf(uniform, sx, sy, 1, 0), std::invalid_argument);
}

TEST(MapRendering, OptionsChooseWhatTheThreeDViewShows)
{
	CEvidentialGridMap2D map = movingWallMap();
	auto& ro = map.renderingOptions;
	ro.showUnknown = true;
	ro.showFree = false;
	auto sets = trianglesOf(map);
	EXPECT_EQ(sets.count("evidentialGrid.unknown"), 1u);
	EXPECT_EQ(sets.count("evidentialGrid.free"), 0u);

	// Without the motion objects, moving cells join their decision's object:
	// no cell left out.
	ro = CEvidentialGridMap2D::TRenderingOptions();
	ro.showMotion = false;
	sets = trianglesOf(map);
	EXPECT_EQ(sets.count("evidentialGrid.appeared"), 0u);
	EXPECT_EQ(sets.count("evidentialGrid.disappeared"), 0u);
	double area = 0.0;
	for (const auto& [name, set] : sets) area += areaOf(*set);
	const auto counts = map.countDecisions();
	const double res = map.getResolution();
	const double decided = static_cast<double>(counts.free + counts.occupied + counts.conflict);
	EXPECT_GE(area / (res * res), decided - 1e-3);
	EXPECT_LE(area / (res * res), decided * 1.2 * 1.2 + 1e-3);

	// The masses: one plane, vacuous cells transparent.
	ro = CEvidentialGridMap2D::TRenderingOptions();
	ro.style = RenderStyle::Masses;
	const auto objects = objectsOf(map);
	ASSERT_EQ(objects.size(), 1u);
	const auto plane =
		std::dynamic_pointer_cast<mrpt::opengl::CTexturedPlane>(objects.begin()->second);
	ASSERT_TRUE(plane);
	EXPECT_EQ(plane->getName(), "evidentialGrid.masses");
	EXPECT_EQ(plane->getTextureImage().getWidth(), static_cast<std::size_t>(map.getSizeX()));
	const mrpt::img::CImage& alpha = plane->getTextureAlphaImage();
	std::size_t seen = 0;
	for (unsigned y = 0; y < alpha.getHeight(); ++y)
		for (unsigned x = 0; x < alpha.getWidth(); ++x) seen += alpha.at<std::uint8_t>(x, y) == 255;
	EXPECT_EQ(seen, test::informedCells(map));

	map.genericMapParams.enableSaveAs3DObject = false;
	mrpt::opengl::CSetOfObjects none;
	map.getVisualizationInto(none);
	EXPECT_EQ(none.size(), 0u);
}

TEST(MapRendering, FarFromTheOriginTheViewStaysOnItsCells)
{
	// UTM-like coordinates that floats cannot hold (their step is 1 m at
	// 1e7 m, and MRPT's .3Dscene files keep an object's pose in floats):
	// each triangle's centroid, from its set's pose, must lie in a cell of
	// its class in memory and after a scene file; the plane must span the
	// grid; the path must pass where it was.
	const double x0 = 1e7 + 0.35, y0 = 3e6 - 0.15;
	CEvidentialGridMap2D map(x0, x0 + 6.0, y0, y0 + 6.0, 0.05);
	map.insertionOptions.growthMargin = 0.0;
	map.insertObservation(
		test::scanByIndex(kRays, kSetup, [](std::size_t) { return 2.5; }),
		mrpt::poses::CPose3D(x0 + 3.0, y0 + 3.0, 0, 0, 0, 0));
	const auto checkTriangles = [&](const std::string& name,
									const mrpt::opengl::CSetOfTriangles& set) {
		std::size_t checked = 0;
		for (std::size_t i = 0; i < set.getTrianglesCount(); ++i)
		{
			mrpt::opengl::TTriangle t;
			set.getTriangle(i, t);
			const double cx = set.getPose().x + (t.x(0) + t.x(1) + t.x(2)) / 3.0;
			const double cy = set.getPose().y + (t.y(0) + t.y(1) + t.y(2)) / 3.0;
			const CellClass cls =
				name == "evidentialGrid.free" ? CellClass::Free : CellClass::Occupied;
			EXPECT_EQ(map.classOfCell(cx, cy), cls)
				<< name << " at (" << cx - x0 << ", " << cy - y0 << ")";
			++checked;
		}
		return checked;
	};
	std::size_t checked = 0;
	for (const auto& [name, set] : trianglesOf(map)) checked += checkTriangles(name, *set);
	EXPECT_GT(checked, 10u);

	const fs::path dir = test::scratchDir("map_rendering", "far_scene");
	const std::string file = (dir / "far.3Dscene").string();
	map.saveAsScene(file, {{x0 + 1.0, y0 + 1.0, 0}, {x0 + 2.0, y0 + 1.0, 0}});
	mrpt::opengl::COpenGLScene scene;
	ASSERT_TRUE(scene.loadFromFile(file));
	std::size_t checkedInFile = 0;
	for (const char* name : {"evidentialGrid.free", "evidentialGrid.occupied"})
	{
		const auto set =
			std::dynamic_pointer_cast<mrpt::opengl::CSetOfTriangles>(scene.getByName(name));
		ASSERT_TRUE(set) << name;
		checkedInFile += checkTriangles(name, *set);
	}
	EXPECT_EQ(checkedInFile, checked);
	const auto path =
		std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(scene.getByName("path"));
	ASSERT_TRUE(path);
	ASSERT_EQ(path->getLineCount(), 1u);
	const mrpt::math::TSegment3D& line = *path->begin();
	EXPECT_NEAR(path->getPose().x + line.point1.x, x0 + 1.0, 1e-3);
	EXPECT_NEAR(path->getPose().y + line.point1.y, y0 + 1.0, 1e-3);

	map.renderingOptions.style = RenderStyle::Masses;
	const auto plane = std::dynamic_pointer_cast<mrpt::opengl::CTexturedPlane>(
		objectsOf(map).begin()->second);
	ASSERT_TRUE(plane);
	float px0, px1, py0, py1;
	plane->getPlaneCorners(px0, px1, py0, py1);
	EXPECT_NEAR(plane->getPose().x + px0, map.getXMin(), 1e-5);
	EXPECT_NEAR(plane->getPose().x + px1, map.getXMax(), 1e-5);
	EXPECT_NEAR(plane->getPose().y + py0, map.getYMin(), 1e-5);
	EXPECT_NEAR(plane->getPose().y + py1, map.getYMax(), 1e-5);
}

TEST(MapRendering, OptionsRoundTripThroughIniFilesAndMapDefinitions)
{
	CEvidentialGridMap2D::TRenderingOptions o;
	o.style = RenderStyle::Masses;
	o.freeColor = mrpt::img::TColor(0x12, 0xAB, 0xEF);
	o.disappearedColor = mrpt::img::TColor(0, 0, 0);
	o.showConflict = false;
	o.showUnknown = true;
	o.height = -0.125;
	mrpt::config::CConfigFileMemory ini;
	o.saveToConfigFile(ini, "r");
	EXPECT_NE(ini.getContent().find("#12ABEF"), std::string::npos) << ini.getContent();
	CEvidentialGridMap2D::TRenderingOptions back;
	back.loadFromConfigFile(ini, "r");
	std::ostringstream a, b;
	o.dumpToTextStream(a);
	back.dumpToTextStream(b);
	EXPECT_EQ(a.str(), b.str());

	// From a map list, as the stock programs read it; colours without '#'.
	mrpt::config::CConfigFileMemory cfg(
		"[Map]\nevidentialGrid_count=1\n[Map_evidentialGrid_00_renderOpts]\n"
		"occupiedColor=000080\nshowFree=false\nheight=0.5\n");
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(cfg, "Map");
	mrpt::maps::CMultiMetricMap maps;
	maps.setListOfMaps(inits);
	const auto map = maps.mapByClass<CEvidentialGridMap2D>();
	ASSERT_TRUE(map);
	EXPECT_TRUE(sameColor(map->renderingOptions.occupiedColor, mrpt::img::TColor(0, 0, 0x80)));
	EXPECT_FALSE(map->renderingOptions.showFree);
	EXPECT_EQ(map->renderingOptions.height, 0.5);
	EXPECT_TRUE(map->renderingOptions.showMotion);  // absent keys keep their defaults

	// A bad value changes nothing.
	CEvidentialGridMap2D::TRenderingOptions kept = o;
	mrpt::config::CConfigFileMemory bad("[r]\nfreeColor=#000000\nheight=inf\n");
	EXPECT_THROW(kept.loadFromConfigFile(bad, "r"), std::invalid_argument);
	EXPECT_TRUE(sameColor(kept.freeColor, o.freeColor));
	o.height = std::nan("");
	EXPECT_THROW(o.validate(), std::invalid_argument);
}

TEST(MapRendering, InvalidOptionsSetInCodeDrawNothing)
{
	// The 3-D view and scene files refuse invalid options, naming the
	// field, and draw nothing.
	CEvidentialGridMap2D map = movingWallMap();
	map.renderingOptions.height = std::nan("");
	mrpt::opengl::CSetOfObjects set;
	try
	{
		map.getVisualizationInto(set);
		ADD_FAILURE() << "a NaN height was drawn";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("height"), std::string::npos) << e.what();
	}
	EXPECT_EQ(set.size(), 0u);
	map.renderingOptions.height = 0.0;
	map.renderingOptions.style = static_cast<RenderStyle>(7);
	EXPECT_THROW(map.getVisualizationInto(set), std::invalid_argument);
	EXPECT_EQ(set.size(), 0u);
	const fs::path dir = test::scratchDir("map_rendering", "invalid");
	EXPECT_THROW(map.saveAsScene((dir / "x.3Dscene").string()), std::invalid_argument);
	EXPECT_TRUE(test::filesIn(dir).empty());
}

TEST(MapRendering, SavedPicturesCarryTheirLegendAndAScaleBar)
{
	const fs::path dir = test::scratchDir("map_rendering", "legend");
	const CEvidentialGridMap2D map = movingWallMap();
	map.savePictures((dir / "").string());
	mrpt::img::CImage saved, bare;
	ASSERT_TRUE(saved.loadFromFile((dir / "map.png").string()));
	map.getAsImage(bare);
	// The map at the top left, unchanged; the strip below, at least
	// kMinLegendWidth wide for a small map.
	ASSERT_EQ(saved.getWidth(), static_cast<std::size_t>(detail::kMinLegendWidth));
	ASSERT_GT(saved.getHeight(), bare.getHeight());
	for (unsigned y = 0; y < bare.getHeight(); ++y)
		for (unsigned x = 0; x < bare.getWidth(); ++x)
			ASSERT_TRUE(sameColor(pixel(saved, x, y), pixel(bare, x, y)));
	// Every class's swatch is in the strip, and the bar's dark ink.
	std::set<std::uint32_t> stripColours;
	for (unsigned y = static_cast<unsigned>(bare.getHeight()); y < saved.getHeight(); ++y)
		for (unsigned x = 0; x < saved.getWidth(); ++x)
		{
			const auto c = pixel(saved, x, y);
			stripColours.insert((c.R << 16) | (c.G << 8) | c.B);
		}
	const auto& ro = map.renderingOptions;
	for (const auto& c :
		 {ro.freeColor, ro.occupiedColor, ro.unknownColor, ro.conflictColor, ro.appearedColor,
		  ro.disappearedColor})
		EXPECT_EQ(stripColours.count((c.R << 16) | (c.G << 8) | c.B), 1u)
			<< "no swatch of #" << std::hex << ((c.R << 16) | (c.G << 8) | c.B);

	// Without the legend: the bare pictures.
	map.savePictures((dir / "bare_").string(), false);
	ASSERT_TRUE(saved.loadFromFile((dir / "bare_map.png").string()));
	EXPECT_EQ(saved.getWidth(), bare.getWidth());
	EXPECT_EQ(saved.getHeight(), bare.getHeight());
	EXPECT_THROW(map.getAsPicture(5, saved), std::out_of_range);
}

TEST(MapRendering, ScaleBarsHaveRoundLengths)
{
	EXPECT_DOUBLE_EQ(detail::scaleBarLength(0.05, 160), 5.0);
	EXPECT_DOUBLE_EQ(detail::scaleBarLength(0.1, 100), 10.0);
	EXPECT_DOUBLE_EQ(detail::scaleBarLength(0.1, 45), 2.0);
	EXPECT_DOUBLE_EQ(detail::scaleBarLength(0.001, 10), 0.01);
	// Never shorter than a cell.
	EXPECT_DOUBLE_EQ(detail::scaleBarLength(0.3, 1), 0.3);
}

TEST(MapRendering, VideoFramesHaveTheAskedSize)
{
	const CEvidentialGridMap2D map = movingWallMap();
	mrpt::img::CImage frame;
	map.getAsPicture(0, frame, true, 320, 240);
	EXPECT_EQ(frame.getWidth(), 320u);
	EXPECT_EQ(frame.getHeight(), 240u);
	EXPECT_TRUE(frame.isColor());
	// Too small for a legend: the map alone, still of the asked size.
	map.getAsPicture(0, frame, true, 40, 30);
	EXPECT_EQ(frame.getWidth(), 40u);
	EXPECT_EQ(frame.getHeight(), 30u);
	// Too narrow for the legend's words (which would be cut at the edge),
	// though tall enough: the map alone too, centred on the dark backdrop,
	// where a wide frame has the legend's white strip at the bottom.
	const auto bottomLeft = [&frame]() {
		return frame.getPixelDepth() == mrpt::img::PixelDepth::D8U
			? static_cast<int>(*frame.ptr<std::uint8_t>(0, frame.getHeight() - 1))
			: -1;
	};
	map.getAsPicture(0, frame, true, 320, 400);
	EXPECT_EQ(bottomLeft(), 0xFF);
	map.getAsPicture(0, frame, true, 40, 400);
	EXPECT_EQ(frame.getWidth(), 40u);
	EXPECT_EQ(frame.getHeight(), 400u);
	EXPECT_EQ(bottomLeft(), 0x40);
}

TEST(MapRendering, SceneFilesHoldTheMapAndThePath)
{
	const fs::path dir = test::scratchDir("map_rendering", "scene");
	const CEvidentialGridMap2D map = movingWallMap();
	const std::string file = (dir / "run.3Dscene").string();
	map.saveAsScene(file, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.2}});
	EXPECT_EQ(test::filesIn(dir), (std::set<std::string>{"run.3Dscene"}));

	mrpt::opengl::COpenGLScene scene;
	ASSERT_TRUE(scene.loadFromFile(file));
	const auto grid = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(
		scene.getByName("evidentialGrid"));
	ASSERT_TRUE(grid);
	EXPECT_TRUE(grid->getByName("evidentialGrid.free"));
	EXPECT_TRUE(grid->getByName("evidentialGrid.appeared"));
	const auto path =
		std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(scene.getByName("path"));
	ASSERT_TRUE(path);
	EXPECT_EQ(path->getLineCount(), 2u);

	// Without a path, only the map; a file that cannot be written throws and
	// leaves nothing.
	map.saveAsScene(file);
	ASSERT_TRUE(scene.loadFromFile(file));
	EXPECT_FALSE(scene.getByName("path"));
	EXPECT_THROW(map.saveAsScene((dir / "missing" / "x.3Dscene").string()), std::runtime_error);
	EXPECT_EQ(test::filesIn(dir), (std::set<std::string>{"run.3Dscene"}));
}
