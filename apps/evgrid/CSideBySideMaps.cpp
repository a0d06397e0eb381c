/* evgrid compare: our map and MRPT's occupancy grid, built side by side from
 * the same scans at the same poses, every N-th scan held out of both. */

#include "CSideBySideMaps.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "CInputWalker.h"
#include "ScanInsertion.h"

using mrpt::poses::CPose3D;
using mrpt_evidential::CEvidentialGridMap2D;

namespace evgrid
{
CSideBySideMaps::CSideBySideMaps(
	std::unique_ptr<CEvidentialGridMap2D> ours,
	const std::optional<mrpt::maps::COccupancyGridMap2D::TMapDefinition>& mrptOptions,
	int holdout, const CInputWalker& input)
	: m_ours(std::move(ours)),
	  m_mrpt(
		  static_cast<float>(m_ours->getXMin()),
		  static_cast<float>(m_ours->getXMax()),
		  static_cast<float>(m_ours->getYMin()),
		  static_cast<float>(m_ours->getYMax()),
		  static_cast<float>(m_ours->getResolution())),
	  m_holdout(holdout),
	  m_input(input)
{
	if (mrptOptions)
	{
		m_mrpt.insertionOptions = mrptOptions->insertionOpts;
		m_mrpt.likelihoodOptions = mrptOptions->likelihoodOpts;
	}
}

void CSideBySideMaps::offer(
	const mrpt::obs::CObservation2DRangeScan& scan,
	const std::optional<CPose3D>& pose)
{
	++m_counts.total;
	if (!pose)
	{
		++m_counts.withoutPose;
		return;
	}
	if (++m_withPose % static_cast<std::size_t>(m_holdout) == 0)
	{
		++m_counts.heldOut;
		m_heldOut.push_back({scan, *pose});
		return;
	}
	++m_counts.offered;
	const std::size_t partlyBefore = m_ours->partlyInsertedCount();
	if (insertScan(*m_ours, scan, *pose, m_input.place(), "our map"))
		++m_counts.oursInserted;
	// MRPT's grid grows to any scan, without a budget: far poses (kilometres
	// from the grid) end it in std::bad_alloc or a crash inside MRPT.
	if (m_ours->partlyInsertedCount() != partlyBefore)
		throw std::runtime_error(
			m_input.place() + ": the scan lies beyond the grid that maxCells (" +
			std::to_string(m_ours->maxCells()) +
			" cells) lets our map grow to, and MRPT's grid has no such limit: compare stops "
			"(poses far from the grid's place?)");
	if (insertScan(m_mrpt, scan, *pose, m_input.place(), "MRPT's grid"))
		++m_counts.mrptInserted;
}

void CSideBySideMaps::finish()
{
	// resizeGrid only ever grows the grid, keeping every cell; no margin, so
	// that MRPT's extent is exactly the union (snapped to its cells).
	m_mrpt.resizeGrid(
		std::min(m_mrpt.getXMin(), static_cast<float>(m_ours->getXMin())),
		std::max(m_mrpt.getXMax(), static_cast<float>(m_ours->getXMax())),
		std::min(m_mrpt.getYMin(), static_cast<float>(m_ours->getYMin())),
		std::max(m_mrpt.getYMax(), static_cast<float>(m_ours->getYMax())),
		0.5f, false);
}

}  // namespace evgrid
