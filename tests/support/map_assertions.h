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
	for (std::size_t i = 0; i < a.geometry().cellCount(); ++i)
		if (maxAbsDifference(a.storage().read(i), b.storage().read(i)) > tol)
			return ::testing::AssertionFailure()
				<< "cell " << i << ": " << a.storage().read(i) << " vs "
				<< b.storage().read(i);
	return ::testing::AssertionSuccess();
}
}  // namespace mrpt_evidential::test
