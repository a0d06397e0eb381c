/* mrpt-evidential: internal: what CEvidentialGridMap2D keeps beside its
 * cells (see CEvidentialGridMap2D::TWorkspace). */
#pragma once

#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include <mrpt_evidential/scan/CPolarSourceGrid.h>

#include <algorithm>
#include <memory>
#include <type_traits>
#include <vector>
#include <mutex>

#include "cloud/CloudSectors.h"
#include "insert/MotionDetector.h"
#include "map/BandWorkers.h"
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
	/** The motion layer's rules at work, with its memory between scans
	 * (part of the map's value: copies and files keep it). */
	CMotionDetector motion;
	/** A band of the rows a scan informs, fused by one thread, with what it
	 * collects: its candidate motion events (taken over by `motion` in
	 * band order) and the loud cells of a free run (fuseQuietFreeRun()). */
	struct TFusionBand
	{
		int firstRow = 0, lastRow = -1;
		CMotionDetector motion;
		std::vector<std::size_t> loud;
	};
	std::vector<TFusionBand> bands;
	CBandWorkers bandWorkers;
	/** A 3-D observation's points in the robot's frame, its returns by
	 * sector, and the sorting's per-point storage. */
	std::vector<mrpt::math::TPoint3Df> cloudPoints;
	TCloudReturns cloudReturns;
	TCloudScratch cloudScratch;
	/** The likelihood field, or null until a likelihood needs it. The mutex
	 * guards the pointer: readers of the map may race to build it. */
	std::mutex likelihoodMutex;
	std::shared_ptr<const LikelihoodField> likelihood;

	/** Cells of the transform's box worth a band of their own: waking a
	 * worker costs some 20 us, the fusion of this many cells several times
	 * that. */
	static constexpr double kCellsPerBand = 40000;
	/** Visits the rows the transform informs in up to `threads` bands at
	 * once (fewer for a small scan): fuseBand(decays, band) on each, with
	 * `decays` std::true_type or std::false_type as the grid decays or not
	 * (the kernels are compiled for each), the bands in row order in
	 * `bands`; returns the number of bands used. */
	template <typename FuseBand>
	std::size_t fuseInBands(
		const GridGeometry& grid, unsigned threads, bool decays, FuseBand&& fuseBand)
	{
		const CPolarToCartesian::TRows rows = transform.prepareRows(grid);
		const int count = rows.last - rows.first + 1;
		if (count <= 0) return 0;
		const Box& box = transform.box();
		const double cells = static_cast<double>(count) *
			std::max(1.0, (box.xMax - box.xMin) / grid.resolution);
		const auto worth = static_cast<int>(std::clamp(
			cells / kCellsPerBand, 1.0, static_cast<double>(TInsertionOptions::kMaxInsertionThreads)));
		const auto n = static_cast<std::size_t>(
			std::min({static_cast<int>(threads), count, worth}));
		if (bands.size() < n) bands.resize(n);
		for (std::size_t b = 0; b < n; ++b)
		{
			bands[b].firstRow = rows.first + static_cast<int>(b) * count / static_cast<int>(n);
			bands[b].lastRow =
				rows.first + static_cast<int>(b + 1) * count / static_cast<int>(n) - 1;
		}
		bandWorkers.run(n, [&](std::size_t b) {
			if (decays)
				fuseBand(std::true_type(), bands[b]);
			else
				fuseBand(std::false_type(), bands[b]);
		});
		return n;
	}
};
}  // namespace mrpt_evidential
