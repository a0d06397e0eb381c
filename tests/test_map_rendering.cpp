/* How CEvidentialGridMap2D is drawn: the classes of cells and their colours,
 * the 3-D view's planes, the rendering options in .ini files, the legends of
 * saved pictures, video frames and scene files. */

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/img/CImage.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
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
 * appeared and where something left: on the left half of the scans a wall
 * seen at 3 m comes forward to 2 m (the cells at 2 m were free), on the right
 * half a wall at 2 m goes back to 3 m (the cells at 2 m were occupied). */
CEvidentialGridMap2D movingWallMap()
{
	CEvidentialGridMap2D map(-4.0, 4.0, -4.0, 4.0, 0.1);
	map.insertionOptions.growthMargin = 0.0;
	map.insertionOptions.motionWindow = 100.0;
	const mrpt::poses::CPose3D origin;
	for (int phase = 0; phase < 2; ++phase)
		for (int i = 0; i < 3; ++i)
			map.insertObservation(
				test::scanByIndex(
					kRays, kSetup.at(1.0 + 3 * phase + i),
					[phase](std::size_t ray) { return (ray < kRays / 2) == (phase == 0) ? 3.0 : 2.0; }),
				origin);
	return map;
}

std::set<std::string> filesIn(const fs::path& dir)
{
	std::set<std::string> names;
	for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
	return names;
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

/** The planes of the map's 3-D view by name. */
std::map<std::string, mrpt::opengl::CTexturedPlane::Ptr> planesOf(
	const CEvidentialGridMap2D& map)
{
	mrpt::opengl::CSetOfObjects set;
	map.getVisualizationInto(set);
	std::map<std::string, mrpt::opengl::CTexturedPlane::Ptr> planes;
	for (const auto& o : set)
	{
		auto plane = std::dynamic_pointer_cast<mrpt::opengl::CTexturedPlane>(o);
		EXPECT_TRUE(plane) << "not a textured plane: " << o->GetRuntimeClass()->className;
		if (plane) planes[plane->getName()] = plane;
	}
	EXPECT_EQ(planes.size(), set.size()) << "two planes share a name";
	return planes;
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

TEST(MapRendering, TheThreeDViewHasOneUnlitPlanePerClassShown)
{
	const CEvidentialGridMap2D map = movingWallMap();
	const auto planes = planesOf(map);
	// Unknown cells are transparent by default: no plane for them.
	const std::vector<std::pair<std::string, CellClass>> expected{
		{"evidentialGrid.free", CellClass::Free},
		{"evidentialGrid.occupied", CellClass::Occupied},
		{"evidentialGrid.disappeared", CellClass::Disappeared},
		{"evidentialGrid.appeared", CellClass::Appeared}};
	ASSERT_EQ(planes.size(), expected.size());

	const GridGeometry& g = map.geometry();
	double previousZ = -1e9;
	for (const auto& [name, cls] : expected)
	{
		ASSERT_EQ(planes.count(name), 1u) << name;
		const auto& plane = planes.at(name);
		EXPECT_FALSE(plane->CRenderizableShaderTexturedTriangles::isLightEnabled()) << name;
		// Later planes lie above earlier ones, all at or under `height`.
		EXPECT_GT(plane->getPoseZ(), previousZ) << name;
		EXPECT_LE(plane->getPoseZ(), map.renderingOptions.height + 1e-9) << name;
		previousZ = plane->getPoseZ();

		// The plane covers the bounding box of its cells; a texel is opaque
		// exactly where the cell is of the plane's class, in its colour.
		float xMin, xMax, yMin, yMax;
		plane->getPlaneCorners(xMin, xMax, yMin, yMax);
		const int cx0 = g.cellX(xMin + 0.5 * g.resolution);
		const int cy0 = g.cellY(yMin + 0.5 * g.resolution);
		const mrpt::img::CImage& texture = plane->getTextureImage();
		const mrpt::img::CImage& alpha = plane->getTextureAlphaImage();
		ASSERT_NEAR((xMax - xMin) / g.resolution, texture.getWidth(), 1e-3) << name;
		ASSERT_NEAR((yMax - yMin) / g.resolution, texture.getHeight(), 1e-3) << name;
		std::size_t opaque = 0;
		bool touchesLeft = false, touchesBottom = false;
		for (unsigned ty = 0; ty < texture.getHeight(); ++ty)
			for (unsigned tx = 0; tx < texture.getWidth(); ++tx)
			{
				const int cx = cx0 + static_cast<int>(tx), cy = cy0 + static_cast<int>(ty);
				const bool mine = map.classOfCell(g.cellCenterX(cx), g.cellCenterY(cy)) == cls;
				ASSERT_EQ(alpha.at<std::uint8_t>(tx, ty), mine ? 255 : 0)
					<< name << " at cell (" << cx << ", " << cy << ")";
				if (!mine) continue;
				++opaque;
				touchesLeft |= tx == 0;
				touchesBottom |= ty == 0;
				ASSERT_TRUE(sameColor(pixel(texture, tx, ty), map.renderingOptions.colorOf(cls)));
			}
		EXPECT_EQ(opaque, classCounts(map).at(cls)) << name;
		EXPECT_TRUE(touchesLeft && touchesBottom) << name << ": not the cells' bounding box";
	}
}

TEST(MapRendering, OptionsChooseWhatTheThreeDViewShows)
{
	CEvidentialGridMap2D map = movingWallMap();
	auto& ro = map.renderingOptions;
	ro.showUnknown = true;
	ro.showFree = false;
	auto planes = planesOf(map);
	EXPECT_EQ(planes.count("evidentialGrid.unknown"), 1u);
	EXPECT_EQ(planes.count("evidentialGrid.free"), 0u);

	// Without the motion planes, moving cells join their decision's plane.
	ro = CEvidentialGridMap2D::TRenderingOptions();
	ro.showMotion = false;
	planes = planesOf(map);
	EXPECT_EQ(planes.count("evidentialGrid.appeared"), 0u);
	EXPECT_EQ(planes.count("evidentialGrid.disappeared"), 0u);
	std::size_t opaque = 0;
	for (const auto& [name, plane] : planes)
	{
		const mrpt::img::CImage& a = plane->getTextureAlphaImage();
		for (unsigned y = 0; y < a.getHeight(); ++y)
			for (unsigned x = 0; x < a.getWidth(); ++x) opaque += a.at<std::uint8_t>(x, y) == 255;
	}
	const auto counts = map.countDecisions();
	EXPECT_EQ(opaque, counts.free + counts.occupied + counts.conflict);

	// The masses: one plane, vacuous cells transparent.
	ro = CEvidentialGridMap2D::TRenderingOptions();
	ro.style = RenderStyle::Masses;
	planes = planesOf(map);
	ASSERT_EQ(planes.size(), 1u);
	ASSERT_EQ(planes.count("evidentialGrid.masses"), 1u);
	const auto& plane = planes.at("evidentialGrid.masses");
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
}

TEST(MapRendering, SceneFilesHoldTheMapAndThePath)
{
	const fs::path dir = test::scratchDir("map_rendering", "scene");
	const CEvidentialGridMap2D map = movingWallMap();
	const std::string file = (dir / "run.3Dscene").string();
	map.saveAsScene(file, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.2}});
	EXPECT_EQ(filesIn(dir), (std::set<std::string>{"run.3Dscene"}));

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
	EXPECT_EQ(filesIn(dir), (std::set<std::string>{"run.3Dscene"}));
}
