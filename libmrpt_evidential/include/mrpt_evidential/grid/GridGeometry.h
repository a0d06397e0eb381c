/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Where the cells of a grid lie. Standard library only. */
#pragma once

#include <mrpt_evidential/TInvalidOption.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

namespace mrpt_evidential
{
/** Where the cells of a grid lie. Cell (cx, cy) covers
 * [xMin + cx res, xMin + (cx + 1) res) x [yMin + cy res, yMin + (cy + 1) res),
 * and is stored at index(cx, cy): row by row, each row's cells side by side,
 * the rows `stride()` indices apart from `firstIndex` on. A packed geometry
 * (the default: firstIndex 0, rowStride 0) numbers the cells cx + sizeX cy;
 * a grid that grew may keep room around its cells for the next growth
 * (EvidentialGridStorage), and its rows then lie farther apart. */
struct GridGeometry
{
	double xMin = 0.0, yMin = 0.0, resolution = 0.1;
	int sizeX = 0, sizeY = 0;
	/** Index of cell (0, 0), and from one row to the next (0: sizeX). */
	std::size_t firstIndex = 0, rowStride = 0;

	/** Limits of every grid: bounds within kMaxCoordinate metres of the
	 * origin, cells of kMinResolution to kMaxResolution metres. Beyond them
	 * cell centres lose their precision, and squared distances overflow. */
	static constexpr double kMaxCoordinate = 1e9;
	static constexpr double kMinResolution = 1e-6, kMaxResolution = 1e6;
	/** Largest cell budget of any grid: 8 GB of cells. A map read from a
	 * file must hold no more, so a map must never be given more. */
	static constexpr std::size_t kMaxCellBudget = 1'000'000'000;
	/** True when the bounds and resolution are within the limits (NaN is
	 * not). */
	static bool withinLimits(
		double xMin, double xMax, double yMin, double yMax, double resolution)
	{
		const auto near = [](double v) {
			return v >= -kMaxCoordinate && v <= kMaxCoordinate;
		};
		return resolution >= kMinResolution && resolution <= kMaxResolution &&
			near(xMin) && near(xMax) && near(yMin) && near(yMax);
	}

	/** The first invalid value of a grid over [xMin, xMax] x [yMin, yMax]
	 * with cells of `resolution` metres within a budget of `maxCells` cells,
	 * named by its .ini key (min_x, max_x, min_y, max_y, resolution,
	 * maxCells): the resolution or a bound beyond the limits (NaN
	 * included), min >= max, no budget or one above kMaxCellBudget, or more
	 * cells than the budget. */
	static std::optional<TInvalidOption> firstInvalid(
		double xMin, double xMax, double yMin, double yMax, double resolution,
		std::size_t maxCells);

	/** Number of cells needed to cover `length` metres, at least 1 (a
	 * length within a billionth of a cell above a whole number of cells
	 * needs that number). */
	static double cellsToCover(double length, double resolution)
	{
		return std::max(1.0, std::ceil(length / resolution - 1e-9));
	}

	double xMax() const { return xMin + sizeX * resolution; }
	double yMax() const { return yMin + sizeY * resolution; }
	std::size_t cellCount() const
	{
		return static_cast<std::size_t>(sizeX) * static_cast<std::size_t>(sizeY);
	}
	/** Column of x; may be outside [0, sizeX) (far away or NaN: an int's
	 * smallest or largest value). */
	int cellX(double x) const { return floorToInt((x - xMin) / resolution); }
	int cellY(double y) const { return floorToInt((y - yMin) / resolution); }
	/** floor(v), saturated to an int: a plain cast of a larger value is
	 * undefined behaviour. NaN gives the smallest int. */
	static int floorToInt(double v)
	{
		constexpr double lo = std::numeric_limits<int>::min();
		constexpr double hi = std::numeric_limits<int>::max();
		const double f = std::floor(v);
		if (f >= hi) return std::numeric_limits<int>::max();
		return f >= lo ? static_cast<int>(f) : std::numeric_limits<int>::min();
	}
	double cellCenterX(int cx) const { return xMin + (cx + 0.5) * resolution; }
	double cellCenterY(int cy) const { return yMin + (cy + 0.5) * resolution; }
	bool inside(int cx, int cy) const
	{
		return cx >= 0 && cy >= 0 && cx < sizeX && cy < sizeY;
	}
	/** Index step from a row to the next. */
	std::size_t stride() const
	{
		return rowStride > 0 ? rowStride : static_cast<std::size_t>(sizeX);
	}
	/** Index of cell (cx, cy), inside(). */
	std::size_t index(int cx, int cy) const
	{
		return firstIndex + static_cast<std::size_t>(cy) * stride() +
			static_cast<std::size_t>(cx);
	}
	/** Index of the cell numbered `packedIndex` = cx + sizeX cy (< cellCount()),
	 * as files and TMapChanges number the cells. */
	std::size_t indexOfPacked(std::size_t packedIndex) const
	{
		const auto sx = static_cast<std::size_t>(sizeX);
		return index(static_cast<int>(packedIndex % sx), static_cast<int>(packedIndex / sx));
	}
	/** Column and row of the cell at `idx` (an index() of this geometry). */
	int columnOf(std::size_t idx) const
	{
		return static_cast<int>((idx - firstIndex) % stride());
	}
	int rowOf(std::size_t idx) const
	{
		return static_cast<int>((idx - firstIndex) / stride());
	}
	/** Calls f(index) for every cell, row by row. */
	template <typename F>
	void forEachIndex(F&& f) const
	{
		for (int cy = 0; cy < sizeY; ++cy)
			for (std::size_t i = index(0, cy), end = i + static_cast<std::size_t>(sizeX); i < end; ++i)
				f(i);
	}
	/** The same cells, numbered cx + sizeX cy. */
	GridGeometry packed() const
	{
		GridGeometry g = *this;
		g.firstIndex = 0, g.rowStride = 0;
		return g;
	}
};

}  // namespace mrpt_evidential
