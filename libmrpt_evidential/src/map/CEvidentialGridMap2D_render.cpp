/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: how the map is drawn (rendering options, classes of
 * cells, the 3-D view and scene files). */

#include <mrpt/img/CImage.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CSetOfTriangles.h>
#include <mrpt/opengl/CTexturedPlane.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include <mrpt_evidential/support/AtomicFile.h>
#include "map/ConfigReading.h"
#include "render/CellRectangles.h"

using namespace mrpt_evidential;
using CellClass = CEvidentialGridMap2D::CellClass;

namespace
{
/** The objects of the 3-D view, with their names' suffixes. */
constexpr std::array<std::pair<CellClass, const char*>, 6> kObjects{{
	{CellClass::Unknown, "unknown"},
	{CellClass::Free, "free"},
	{CellClass::Occupied, "occupied"},
	{CellClass::Conflict, "conflict"},
	{CellClass::Disappeared, "disappeared"},
	{CellClass::Appeared, "appeared"},
}};
const char* kPathName = "path";
/** The longest side of a class's rectangles, in cells (rectanglesOf()). */
constexpr int kMaxRectangleSide = 64;
const mrpt::img::TColor kPathColor{0xE0, 0x20, 0x20};

/** Where a 3-D object whose vertices start at (x, y) is placed: a pose on
 * a lattice of 64 m, and the rest, which its vertices add. Vertices in
 * world coordinates would lose cells from 1e6 m (UTM) on, and MRPT's
 * .3Dscene files keep a pose in floats: a pose that floats cannot hold would
 * move the map by up to half a metre in a file. Multiples of 64 m are
 * floats exactly within the grid's 1e9 m (64 x 2^24 m). (Rounding the pose to a float
 * instead is what GCC 12's vectorizer compiled away, at -O2.) */
struct TObjectOrigin
{
	double x, y;  //!< The pose.
	float dx, dy;  //!< (x, y) from the pose: in [0, 64) m.
};
TObjectOrigin objectOrigin(double x, double y)
{
	constexpr double kLattice = 64.0;
	const double px = std::floor(x / kLattice) * kLattice,
				 py = std::floor(y / kLattice) * kLattice;
	return {px, py, static_cast<float>(x - px), static_cast<float>(y - py)};
}

/** A plane of `image` (row 0 at yMin) and its transparency over the grid
 * `g`, unlit, at height z. */
mrpt::opengl::CTexturedPlane::Ptr makePlane(
	const GridGeometry& g, double z, mrpt::img::CImage&& image, mrpt::img::CImage&& alpha)
{
	const TObjectOrigin o = objectOrigin(g.xMin, g.yMin);
	auto plane = mrpt::opengl::CTexturedPlane::Create(
		o.dx, o.dx + static_cast<float>(g.sizeX * g.resolution), o.dy,
		o.dy + static_cast<float>(g.sizeY * g.resolution));
	plane->assignImage(std::move(image), std::move(alpha));
	// Unlit, so that the colour on screen is the option's (MRPT 2.14's
	// default; MRPT 2.5.8 lights planes).
	plane->CRenderizableShaderTexturedTriangles::enableLight(false);
	plane->CRenderizableShaderTriangles::enableLight(false);
	plane->setLocation(o.x, o.y, z);
	return plane;
}
}  // namespace

void TEvidentialRenderingOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	// All or nothing: *this changes only when every value is valid.
	TEvidentialRenderingOptions o = *this;
	detail::readEnum(source, section, "style", o.style);
	detail::readColor(source, section, "freeColor", o.freeColor);
	detail::readColor(source, section, "occupiedColor", o.occupiedColor);
	detail::readColor(source, section, "unknownColor", o.unknownColor);
	detail::readColor(source, section, "conflictColor", o.conflictColor);
	detail::readColor(source, section, "appearedColor", o.appearedColor);
	detail::readColor(source, section, "disappearedColor", o.disappearedColor);
	detail::readBool(source, section, "showFree", o.showFree);
	detail::readBool(source, section, "showOccupied", o.showOccupied);
	detail::readBool(source, section, "showConflict", o.showConflict);
	detail::readBool(source, section, "showMotion", o.showMotion);
	detail::readBool(source, section, "showUnknown", o.showUnknown);
	detail::readDouble(source, section, "height", o.height);
	detail::throwIfInvalid(source, section, o.firstInvalid());
	*this = o;
}

std::optional<TInvalidOption> TEvidentialRenderingOptions::firstInvalid() const
{
	if (style != RenderStyle::Classes && style != RenderStyle::Masses)
		return TInvalidOption{"style", "Classes or Masses", static_cast<double>(style)};
	if (!(std::abs(height) <= 1000.0))  // NaN fails too
		return TInvalidOption{"height", "within [-1000, 1000] m", height};
	return std::nullopt;
}

void TEvidentialRenderingOptions::validate() const
{
	if (const auto bad = firstInvalid())
		throw std::invalid_argument("renderOpts: " + bad->describe());
}

void TEvidentialRenderingOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& target, const std::string& section) const
{
	using detail::writeValue;
	writeValue(target, section, "style", style, "Classes or Masses");
	writeValue(target, section, "freeColor", freeColor, "#RRGGBB");
	writeValue(target, section, "occupiedColor", occupiedColor, "#RRGGBB");
	writeValue(target, section, "unknownColor", unknownColor, "#RRGGBB, pictures and showUnknown");
	writeValue(target, section, "conflictColor", conflictColor, "#RRGGBB");
	writeValue(target, section, "appearedColor", appearedColor, "#RRGGBB");
	writeValue(target, section, "disappearedColor", disappearedColor, "#RRGGBB");
	writeValue(target, section, "showFree", showFree, "3-D view");
	writeValue(target, section, "showOccupied", showOccupied, "3-D view");
	writeValue(target, section, "showConflict", showConflict, "3-D view");
	writeValue(target, section, "showMotion", showMotion, "3-D view: appeared, disappeared");
	writeValue(target, section, "showUnknown", showUnknown, "3-D view: false = transparent");
	writeValue(target, section, "height", height, "m, z of the 3-D view's top plane");
}

void TEvidentialRenderingOptions::dumpToTextStream(std::ostream& out) const
{
	detail::dumpAsIni(*this, "renderOpts", out);
}

CEvidentialGridMap2D::CellClass CEvidentialGridMap2D::classOf(
	std::size_t idx, bool withMotion) const
{
	switch (withMotion ? motionOf(idx) : Motion::None)
	{
		case Motion::Appeared: return CellClass::Appeared;
		case Motion::Disappeared: return CellClass::Disappeared;
		case Motion::None: break;
	}
	switch (decide(m_grid.read(idx)))
	{
		case Decision::Free: return CellClass::Free;
		case Decision::Occupied: return CellClass::Occupied;
		case Decision::Conflict: return CellClass::Conflict;
		case Decision::Unknown: break;
	}
	return CellClass::Unknown;
}

CEvidentialGridMap2D::CellClass CEvidentialGridMap2D::classOfCell(double x, double y) const
{
	const GridGeometry& g = geometry();
	if (!(x >= g.xMin && x < g.xMax() && y >= g.yMin && y < g.yMax()))
		return CellClass::Unknown;  // NaN included
	const int cx = g.cellX(x), cy = g.cellY(y);
	return g.inside(cx, cy) ? classOf(g.index(cx, cy)) : CellClass::Unknown;
}

mrpt::img::TColor TEvidentialRenderingOptions::colorOf(CellClass c) const
{
	switch (c)
	{
		case CellClass::Free: return freeColor;
		case CellClass::Occupied: return occupiedColor;
		case CellClass::Conflict: return conflictColor;
		case CellClass::Appeared: return appearedColor;
		case CellClass::Disappeared: return disappearedColor;
		case CellClass::Unknown: break;
	}
	return unknownColor;
}

void CEvidentialGridMap2D::getAsImage(mrpt::img::CImage& img) const
{
	const GridGeometry& g = geometry();
	img.resize(
		static_cast<std::size_t>(g.sizeX), static_cast<std::size_t>(g.sizeY),
		mrpt::img::CH_RGB);
	for (int row = 0; row < g.sizeY; ++row)
	{
		// CImage keeps colour pixels blue first (OpenCV's order).
		auto* p = img.ptrLine<std::uint8_t>(static_cast<unsigned>(row));
		const std::size_t first = g.index(0, g.sizeY - 1 - row);
		for (int cx = 0; cx < g.sizeX; ++cx, p += 3)
		{
			const mrpt::img::TColor c =
				renderingOptions.colorOf(classOf(first + static_cast<std::size_t>(cx)));
			p[0] = c.B, p[1] = c.G, p[2] = c.R;
		}
	}
}

void CEvidentialGridMap2D::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const
{
	if (!genericMapParams.enableSaveAs3DObject) return;
	const TRenderingOptions& ro = renderingOptions;
	ro.validate();
	const GridGeometry& g = geometry();
	const std::string name = "evidentialGrid.";

	if (ro.style == RenderStyle::Masses)
	{
		mrpt::img::CImage image, alpha(
			static_cast<unsigned>(g.sizeX), static_cast<unsigned>(g.sizeY),
			mrpt::img::CH_GRAY);
		getAsEvidentialImage(image);
		image.flipVertical();  // the plane maps texture row 0 to yMin
		for (int cy = 0; cy < g.sizeY; ++cy)
			for (int cx = 0; cx < g.sizeX; ++cx)
				alpha.at<std::uint8_t>(cx, cy) =
					ro.showUnknown || m_grid.read(g.index(cx, cy)).unknown < 1.0 ? 255 : 0;
		auto plane = makePlane(g, ro.height, std::move(image), std::move(alpha));
		plane->setName(name + "masses");
		o.insert(plane);
		return;
	}

	// Each class as its own opaque triangles over exactly its cells: MRPT
	// draws nearer objects first, and the transparent texels of a plane over
	// the whole grid would hide the classes drawn after it.
	std::vector<std::uint8_t> classes;
	classes.reserve(g.cellCount());
	g.forEachIndex([&](std::size_t idx) {
		classes.push_back(static_cast<std::uint8_t>(classOf(idx, ro.showMotion)));
	});
	const auto shown = [&ro](CellClass c) {
		switch (c)
		{
			case CellClass::Free: return ro.showFree;
			case CellClass::Occupied: return ro.showOccupied;
			case CellClass::Conflict: return ro.showConflict;
			case CellClass::Appeared:
			case CellClass::Disappeared: return ro.showMotion;
			case CellClass::Unknown: break;
		}
		return ro.showUnknown;
	};
	const float z = static_cast<float>(ro.height);
	const TObjectOrigin origin = objectOrigin(g.xMin, g.yMin);
	for (const auto& [cls, suffix] : kObjects)
	{
		if (!shown(cls)) continue;
		const auto rects = detail::rectanglesOf(
			classes, g.sizeX, g.sizeY, static_cast<std::uint8_t>(cls), kMaxRectangleSide);
		if (rects.empty()) continue;
		auto triangles = mrpt::opengl::CSetOfTriangles::Create();
		triangles->setName(name + suffix);
		triangles->setLocation(origin.x, origin.y, 0.0);
		// Unlit, so that the colour on screen is the option's.
		triangles->enableLight(false);
		triangles->reserve(2 * rects.size());
		const mrpt::img::TColor c = ro.colorOf(cls);
		// Rectangles meet at T-junctions, where Mesa's rasterizer leaves
		// cracks of a pixel unless they overlap by about a pixel: each
		// overlaps its neighbours by a tenth of a cell (a fiftieth left
		// 4,000 to 8,000 background pixels in a view of 800 x 600).
		const double seam = 0.1 * g.resolution;
		for (const auto& r : rects)
		{
			const auto x0 = origin.dx + static_cast<float>(r.cx0 * g.resolution - seam);
			const auto x1 = origin.dx + static_cast<float>((r.cx1 + 1) * g.resolution + seam);
			const auto y0 = origin.dy + static_cast<float>(r.cy0 * g.resolution - seam);
			const auto y1 = origin.dy + static_cast<float>((r.cy1 + 1) * g.resolution + seam);
			for (const auto& [p, q, w] :
				 {std::array{mrpt::math::TPoint3Df(x0, y0, z), mrpt::math::TPoint3Df(x1, y0, z),
							 mrpt::math::TPoint3Df(x1, y1, z)},
				  std::array{mrpt::math::TPoint3Df(x0, y0, z), mrpt::math::TPoint3Df(x1, y1, z),
							 mrpt::math::TPoint3Df(x0, y1, z)}})
			{
				mrpt::opengl::TTriangle t(p, q, w);
				t.setColor(c);
				triangles->insertTriangle(t);
			}
		}
		o.insert(triangles);
	}
}

void CEvidentialGridMap2D::saveAsScene(
	const std::string& path3Dscene, const std::vector<mrpt::math::TPoint3D>& path) const
{
	// Before the file: the writer reports its failures as the file's.
	renderingOptions.validate();
	detail::writeFileAtomicallyByName(
		path3Dscene, [&](const std::string& tmp) { return writeScene(tmp, path); });
}

bool CEvidentialGridMap2D::writeScene(
	const std::string& file, const std::vector<mrpt::math::TPoint3D>& path) const
{
	mrpt::opengl::COpenGLScene scene;
	auto map = mrpt::opengl::CSetOfObjects::Create();
	map->setName("evidentialGrid");
	getVisualizationInto(*map);
	scene.insert(map);
	if (path.size() >= 2)
	{
		auto lines = mrpt::opengl::CSetOfLines::Create();
		lines->setName(kPathName);
		lines->setColor_u8(kPathColor);
		lines->setLineWidth(2.0f);
		// Above the map's planes (renderingOptions.height), whatever the path's own z.
		const double lift = renderingOptions.height + 0.01;
		// From the path's start, as the map's objects are placed.
		const TObjectOrigin o = objectOrigin(path[0].x, path[0].y);
		lines->setLocation(o.x, o.y, 0.0);
		for (std::size_t i = 1; i < path.size(); ++i)
			lines->appendLine(
				path[i - 1].x - o.x, path[i - 1].y - o.y, std::max(path[i - 1].z, lift),
				path[i].x - o.x, path[i].y - o.y, std::max(path[i].z, lift));
		scene.insert(lines);
	}
	return scene.saveToFile(file);
}
