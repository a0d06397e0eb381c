/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * What a cell of the map shows as, in its pictures and its 3-D view. */
#pragma once

namespace mrpt_evidential
{
/** The classes of cells that CEvidentialGridMap2D's 3-D view and pictures
 * draw (CEvidentialGridMap2D::classOfCell()): a cell's motion when the
 * motion layer reports one, else its decision. */
enum class CellClass
{
	Unknown,
	Free,
	Occupied,
	Conflict,
	Appeared,
	Disappeared
};

}  // namespace mrpt_evidential
