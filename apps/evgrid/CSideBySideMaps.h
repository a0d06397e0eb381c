/* evgrid compare: our map and MRPT's occupancy grid, built side by side from
 * the same scans at the same poses, every N-th scan held out of both. */
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace evgrid
{
class CInputWalker;

/** A scan left out of both maps, with the pose the input or the pose file
 * gives it: the reference ("true") pose of the localization test. */
struct THeldOutScan
{
	mrpt::obs::CObservation2DRangeScan scan;
	mrpt::poses::CPose3D pose;
};

/** What became of the input's 2-D scans. */
struct TSideBySideCounts
{
	/** Every 2-D scan of the input = withoutPose + heldOut + offered. */
	std::size_t total = 0, withoutPose = 0, heldOut = 0;
	/** Scans given to both maps, and those each map took (a map may refuse
	 * a scan, e.g. a tilted sensor). */
	std::size_t offered = 0, oursInserted = 0, mrptInserted = 0;
};

class CSideBySideMaps
{
   public:
	/** MRPT's grid starts with the extent and resolution of `ours`, and the
	 * insertion and likelihood options of `mrptOptions` (its resolution
	 * aside: the cells are compared one to one), or MRPT's defaults without
	 * it; both grow as scans reach beyond them. `holdout` >= 2. `input`
	 * names the scan in errors. */
	CSideBySideMaps(
		std::unique_ptr<mrpt_evidential::CEvidentialGridMap2D> ours,
		const std::optional<mrpt::maps::COccupancyGridMap2D::TMapDefinition>& mrptOptions,
		int holdout, const CInputWalker& input);

	/** Holds the scan out if it is the N-th with a pose, else inserts it into
	 * both maps. \throws std::runtime_error naming the scan if a map throws
	 *  on it. */
	void offer(
		const mrpt::obs::CObservation2DRangeScan& scan,
		const std::optional<mrpt::poses::CPose3D>& pose);

	/** After the last scan: grows MRPT's grid (with unknown cells) to cover
	 * our map's extent as well as its own. */
	void finish();

	const mrpt_evidential::CEvidentialGridMap2D& ours() const { return *m_ours; }
	const mrpt::maps::COccupancyGridMap2D& mrpt() const { return m_mrpt; }
	const std::vector<THeldOutScan>& heldOut() const { return m_heldOut; }
	const TSideBySideCounts& counts() const { return m_counts; }

   private:
	std::unique_ptr<mrpt_evidential::CEvidentialGridMap2D> m_ours;
	mrpt::maps::COccupancyGridMap2D m_mrpt;
	int m_holdout;
	const CInputWalker& m_input;
	std::size_t m_withPose = 0;
	std::vector<THeldOutScan> m_heldOut;
	TSideBySideCounts m_counts;
};

}  // namespace evgrid
