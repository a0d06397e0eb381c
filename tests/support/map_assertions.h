/* GoogleTest assertions on whole maps, for EXPECT_TRUE / ASSERT_TRUE. */
#pragma once

#include <gtest/gtest.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>
#include <string>

#include "maps.h"
#include "test_helpers.h"

namespace mrpt_evidential::test
{
/** Every cell a valid mass function, within the cell budget. */
inline ::testing::AssertionResult mapIsValid(const CEvidentialGridMap2D& map)
{
	const std::string defect = mapDefect(map);
	if (defect.empty()) return ::testing::AssertionSuccess();
	return ::testing::AssertionFailure() << defect;
}

/** Same geometry, and every cell within `tol` (decayed reads included). */
inline ::testing::AssertionResult sameCells(
	const CEvidentialGridMap2D& a, const CEvidentialGridMap2D& b, double tol = 0.0)
{
	if (a.getSizeX() != b.getSizeX() || a.getSizeY() != b.getSizeY() ||
		a.getXMin() != b.getXMin() || a.getYMin() != b.getYMin())
		return ::testing::AssertionFailure() << "geometries differ";
	// Cell by cell: either grid may keep room between its rows.
	const GridGeometry &ga = a.geometry(), &gb = b.geometry();
	for (int cy = 0; cy < ga.sizeY; ++cy)
		for (int cx = 0; cx < ga.sizeX; ++cx)
		{
			const Mass ma = a.storage().read(ga.index(cx, cy)), mb = b.storage().read(gb.index(cx, cy));
			if (maxAbsDifference(ma, mb) > tol)
				return ::testing::AssertionFailure()
					<< "cell (" << cx << ", " << cy << "): " << ma << " vs " << mb;
		}
	return ::testing::AssertionSuccess();
}
}  // namespace mrpt_evidential::test
