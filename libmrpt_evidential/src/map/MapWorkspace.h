/* mrpt-evidential: internal: what CEvidentialGridMap2D keeps beside its
 * cells (see CEvidentialGridMap2D::TWorkspace). */
#pragma once

#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include <mrpt_evidential/scan/CPolarSourceGrid.h>

#include <memory>
#include <vector>
#include <mutex>

#include "insert/MotionDetector.h"
#include "insert/PolarToCartesian.h"
#include "insert/ScanImpacts.h"

namespace mrpt_evidential
{
struct CEvidentialGridMap2D::TWorkspace
{
	/** Insertion's scratch space, kept to avoid allocations. */
	CPolarSourceGrid sourceGrid;
	CPolarToCartesian transform;
	CScanImpacts impacts;
	CMotionDetector motion;
	/** The loud cells of a free run (see fuseQuietFreeRun()). */
	std::vector<std::size_t> loudCells;
	/** A 3-D observation's points in the robot's frame, and its returns by
	 * sector. */
	std::vector<mrpt::math::TPoint3Df> cloudPoints;
	TCloudReturns cloudReturns;
	/** The likelihood field, or null until a likelihood needs it. The mutex
	 * guards the pointer: readers of the map may race to build it. */
	std::mutex likelihoodMutex;
	std::shared_ptr<const LikelihoodField> likelihood;
};
}  // namespace mrpt_evidential
