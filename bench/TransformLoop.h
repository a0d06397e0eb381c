/* evgrid-bench: the polar-to-Cartesian transform alone, for the 2-D scans'
 * and the clouds' cases. */
#pragma once

#include <benchmark/benchmark.h>
#include <mrpt_evidential/grid/EvidentialGridStorage.h>

#include "insert/PolarToCartesian.h"

namespace bench
{
/** Times the transform of `polar` placed at `sensor` onto a grid of
 * `halfSize` metres each side of the origin at `resolution` (setup and the
 * visit of every informed cell, no fusion). Its counters give the cells a
 * transform visits on each path, to read the time per cell. */
inline void transformLoop(
	benchmark::State& state, const mrpt_evidential::CPolarSourceGrid& polar,
	const mrpt_evidential::PlanarSensorPose& sensor, double halfSize, double resolution)
{
	using namespace mrpt_evidential;
	EvidentialGridStorage grid;
	grid.reset(-halfSize, halfSize, -halfSize, halfSize, resolution, 100'000'000);
	CPolarToCartesian transform;
	// Sums that cost next to nothing: an integer count for the uniform
	// cells (a chain of double additions would cost more than the visit).
	double mixedSink = 0.0;
	std::size_t uniformSink = 0, mixedCells = 0, uniformCells = 0;
	for (auto _ : state)
	{
		transform.setup(polar, sensor);
		transform.forEachInformedCell(
			grid.geometry(),
			[&](std::size_t, const Mass& m) {
				mixedSink += m.free;
				++mixedCells;
			},
			[&](std::size_t first, std::size_t count) {
				for (std::size_t idx = first; idx < first + count; ++idx) uniformSink += idx;
				uniformCells += count;
			});
		benchmark::DoNotOptimize(mixedSink);
		benchmark::DoNotOptimize(uniformSink);
	}
	const auto perRun = [&](std::size_t n) {
		return benchmark::Counter(static_cast<double>(n), benchmark::Counter::kAvgIterations);
	};
	state.counters["mixed"] = perRun(mixedCells);
	state.counters["uniform"] = perRun(uniformCells);
}
}  // namespace bench
