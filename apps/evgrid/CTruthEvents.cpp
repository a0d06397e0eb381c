/* evgrid score-motion: what the motion truth says of each cell at a scan. */

#include "CTruthEvents.h"

#include "CObservedTruth.h"
#include "CPhysicalTruth.h"

namespace evgrid
{
std::unique_ptr<CTruthEvents> CTruthEvents::create(
	TruthTimes times, const TTruthGrid& grid, double window)
{
	if (times == TruthTimes::Physical)
		return std::make_unique<CPhysicalTruth>(grid, window);
	return std::make_unique<CObservedTruth>(grid, window);
}

}  // namespace evgrid
