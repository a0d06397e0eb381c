/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The shapes evgrid-simulate's worlds are made of, and the grid cells they
 * cover. */
#pragma once

#include <functional>
#include <variant>
#include <vector>

namespace mrpt_evidential::simulate
{
/** An axis-aligned rectangle, metres. */
struct TRect
{
	double xMin, yMin, xMax, yMax;
};

/** A disc, metres. */
struct TDisc
{
	double x, y, radius;
};

using TShape = std::variant<TRect, TDisc>;

/** Where a thing that moves along a path is at time t. */
struct TWaypoint
{
	double t, x, y;
};
/** A path: straight from each waypoint to the next at constant speed,
 * waiting where two waypoints in a row are the same place; before its first
 * waypoint the thing is at the first, after its last at the last. */
using TPath = std::vector<TWaypoint>;
void pointOnPath(const TPath& path, double t, double& x, double& y);
/** A sizeX by sizeY rectangle centred on where a path is at time t. */
TRect rectOnPath(const TPath& path, double t, double sizeX, double sizeY);

/** A grid of square cells: cell (cx, cy) spans x in [xMin + cx * resolution,
 * xMin + (cx + 1) * resolution), and likewise in y. */
struct TGridGeometry
{
	double xMin, yMin, resolution;
	int sizeX, sizeY;
};

/** The grid of cells of `resolution` covering an area from its lower
 * corner, rounded to whole cells. */
TGridGeometry gridOver(const TRect& area, double resolution);

enum class ECoverage
{
	/** Cells whose centres lie inside the shape: how the simulated world is
	 * drawn. */
	Centre,
	/** Cells that share some area with the shape: what the ground truth
	 * lists, so that a cell hit by a ray grazing a thing counts as the
	 * thing's. */
	Overlap
};

/** Calls visit(cx, cy) for every cell of the grid the shape covers. */
void forEachCell(
	const TShape& shape, const TGridGeometry& grid, ECoverage coverage,
	const std::function<void(int, int)>& visit);

}  // namespace mrpt_evidential::simulate
