/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */
#include <mrpt_evidential/grid/GridGeometry.h>
#include <mrpt_evidential/support/NumberText.h>

#include <string>
#include <utility>

namespace mrpt_evidential
{
std::optional<TInvalidOption> GridGeometry::firstInvalid(
	double xMin, double xMax, double yMin, double yMax, double resolution,
	std::size_t maxCells)
{
	// Written as !(valid) so that NaN fails every test.
	if (!(resolution >= kMinResolution && resolution <= kMaxResolution))
		return TInvalidOption{"resolution", "in [1e-6, 1e6] m", resolution};
	for (const auto& [key, value] :
		 {std::pair("min_x", xMin), {"max_x", xMax}, {"min_y", yMin}, {"max_y", yMax}})
		if (!(std::abs(value) <= kMaxCoordinate))
			return TInvalidOption{key, "within 1e9 m of the origin", value};
	if (!(xMin < xMax))
		return TInvalidOption{
			"min_x", "below max_x (" + detail::shortestText(xMax) + ")", xMin};
	if (!(yMin < yMax))
		return TInvalidOption{
			"min_y", "below max_y (" + detail::shortestText(yMax) + ")", yMin};
	if (maxCells == 0 || maxCells > kMaxCellBudget)
		return TInvalidOption{"maxCells", "in [1, 1e9]", static_cast<double>(maxCells)};
	const double sx = cellsToCover(xMax - xMin, resolution);
	const double sy = cellsToCover(yMax - yMin, resolution);
	if (sx * sy > static_cast<double>(maxCells) ||
		std::max(sx, sy) > std::numeric_limits<int>::max())
		return TInvalidOption{
			"maxCells",
			"at least the " + detail::shortestText(sx) + " x " +
				detail::shortestText(sy) + " cells of the grid (its cell budget)",
			static_cast<double>(maxCells)};
	return std::nullopt;
}
}  // namespace mrpt_evidential
