/* evgrid score-motion: the cells of the truth's grid that a scan observed. */
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>
#include <vector>

#include "CMotionTruth.h"

namespace evgrid
{
/** Traces a scan's beams through the truth's grid:
 * - hit cells: those holding the end point of a valid beam (valid, finite,
 *   > 0 and below maxRange);
 * - crossed cells: those a beam crosses before its end point, sampled every
 *   quarter of a cell, the end cell excluded; a valid beam at or beyond
 *   maxRange is traced up to maxRange and has no end point.
 * Invalid beams are skipped. A cell may be both (one beam crosses it, another
 * ends in it). The beams leave the sensor at robotPose + sensorPose, planar,
 * at the sensor's yaw plus getScanAngle(). */
class CObservedCells
{
   public:
	explicit CObservedCells(const TTruthGrid& grid);

	/** Replaces the cells with those of `scan` at `robotPose`. */
	void trace(
		const mrpt::obs::CObservation2DRangeScan& scan,
		const mrpt::poses::CPose3D& robotPose, double maxRange);

	const std::vector<int>& hit() const { return m_hit; }
	const std::vector<int>& crossed() const { return m_crossed; }
	/** Hit and crossed cells, each once. */
	const std::vector<int>& observed() const { return m_observed; }

   private:
	static constexpr std::uint8_t kHit = 1, kCrossed = 2;
	void mark(int cell, std::uint8_t flag);

	const TTruthGrid& m_grid;
	std::vector<std::uint8_t> m_flags;
	std::vector<int> m_hit, m_crossed, m_observed;
};

}  // namespace evgrid
