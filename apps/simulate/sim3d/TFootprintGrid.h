/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The 2-D footprint truth of a 3-D scene: what a ground vehicle meets in
 * each cell. */
#pragma once

#include <cstdint>
#include <vector>

#include "Shapes.h"
#include "TBody.h"
#include "TGround.h"

namespace mrpt_evidential::simulate
{
/** What a cell holds, for a vehicle driving on the ground. When several
 * bodies share a cell, the larger value wins: Obstacle over Low over
 * Overhang over Ground. */
enum class EFootprint : uint8_t
{
	/** Nothing above the ground. */
	Ground = 0,
	/** Only above the vehicle: all of it at kHigh or higher above the
	 * ground. Not an obstacle. */
	Overhang = 1,
	/** Only low: nothing above kLow (a kerb). */
	Low = 2,
	/** Something between kLow and kHigh above the ground. */
	Obstacle = 3
};

/** A grid of footprint classes in the world frame of the scene. */
struct TFootprintGrid
{
	/** Heights above the local ground (at the cell's centre), metres, that
	 * split a body's extent into low, in the way, and above. */
	static constexpr double kLow = 0.2, kHigh = 2.0;

	TGridGeometry geometry;
	/** Cell (cx, cy) is cells[cx + geometry.sizeX * cy]. */
	std::vector<EFootprint> cells;

	/** The class of the cell holding (x, y).
	 * \throws std::out_of_range if (x, y) lies outside the grid. */
	EFootprint at(double x, double y) const;
};

/** The footprint of the bodies over the ground: every cell a body's shape
 * shares some area with (ECoverage::Overlap, as the motion ground truth
 * counts cells) takes the class of the part of the body above the ground
 * at the cell's centre. A body wholly under the ground leaves the cell
 * Ground.
 * \throws std::invalid_argument if the geometry has no cell or a
 * resolution <= 0. */
TFootprintGrid footprintOf(
	const TGround& ground, const std::vector<TBody>& bodies,
	const TGridGeometry& geometry);

}  // namespace mrpt_evidential::simulate
