/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * How the map's 3-D view and pictures colour its cells. */
#pragma once

namespace mrpt_evidential
{
/** The colouring of CEvidentialGridMap2D::getVisualizationInto()
 * (TRenderingOptions::style). */
enum class RenderStyle
{
	/** One flat colour per class of cell: free, occupied, conflict, unknown,
	 * appeared, disappeared (what a user reads at a glance). */
	Classes,
	/** The masses themselves: red m(O), green m(F), blue m(Omega), conflict
	 * towards white (getAsEvidentialImage()). */
	Masses
};

}  // namespace mrpt_evidential
