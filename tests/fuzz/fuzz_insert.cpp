/* Fuzz target: scan insertion with arbitrary ranges, validity, apertures,
 * scan directions and poses (NaN, infinite and huge included), under every
 * sensor model, fusion rule, conflict handling and decay rate. Invalid scans
 * and poses may throw std::invalid_argument; anything else that escapes, an
 * invalid cell, a grid beyond its budget or a NaN likelihood is a finding. */
#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose3D.h>

#include <stdexcept>
#include <vector>

#include "FuzzSupport.h"

using namespace mrpt_evidential;

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
	fuzz::silenceMapWarnings();
	return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	fuzz::InsertCase c;
	fuzz::Reader in(data, size);
	fuzz::visit(in, c);

	// Tables cover the extremes; 1000 m at 0.05 m gives polar rows of 20,000
	// bins, which the sparse rows must not pay for.
	static const double kResolutions[] = {0.05, 0.1, 0.25};
	static const double kMaxRanges[] = {0.5, 3.0, 12.0, 1000.0};
	static const double kDecayRates[] = {0.0, 1e-9, 0.1, 10.0, 1e6, 1e300};
	CEvidentialGridMap2D map(-2, 2, -2, 2, kResolutions[c.resolution % 3]);
	map.setMaxCells(1 << 20);
	auto& o = map.insertionOptions;
	o.sensorModel = static_cast<SensorModel>(c.model % 3);
	o.fusionRule = static_cast<FusionRule>(c.rule % 5);
	o.conflictHandling = static_cast<ConflictHandling>(c.handling % 3);
	o.imprecisionProfile = static_cast<ImprecisionProfile>(c.flags & 1);
	o.invalidRangesAsFree = (c.flags & 2) != 0;
	o.muF = c.muF / 65535.0;
	o.muO = c.muO / 65535.0;
	o.imprecision = c.imprecision * 0.01;
	o.sectorWidth = c.sectorWidth * (2 * M_PI / 255);
	o.maxRange = kMaxRanges[c.maxRange % 4];
	o.decayRate = kDecayRates[c.decay % 6];
	o.horizontalTolerance = c.tolerance * (M_PI / 2 / 255);
	o.growthMargin = c.margin * 0.1;

	for (const fuzz::InsertCase::Scan& s : c.scans)
	{
		std::vector<bool> valid(s.ranges.size());
		for (std::size_t i = 0; i < valid.size(); ++i)
			valid[i] = i / 8 < s.valid.size() && ((s.valid[i / 8] >> (i % 8)) & 1);
		const auto setup =
			test::ScanSetup()
				.aperture(s.aperture)
				.rightToLeft(s.rightToLeft & 1)
				.sensorPose(mrpt::poses::CPose3D(
					s.sensorPose[0], s.sensorPose[1], s.sensorPose[2], s.sensorPose[3],
					s.sensorPose[4], s.sensorPose[5]))
				.at(mrpt::Clock::time_point(mrpt::Clock::duration(s.ticks)));
		const auto scan = test::scanFromRanges(s.ranges, valid, setup);
		const mrpt::poses::CPose3D robot(
			s.robotPose[0], s.robotPose[1], s.robotPose[2], s.robotPose[3],
			s.robotPose[4], s.robotPose[5]);
		try
		{
			map.insertObservation(scan, robot);
		}
		catch (const std::invalid_argument&)
		{
			// A non-finite pose or an aperture out of range: documented.
		}
		fuzz::checkMap(map);
		if (std::isnan(map.computeObservationLikelihood(scan, robot)))
			fuzz::fail("a NaN likelihood");
	}
	return 0;
}
