/* Fuzz target: the map's .ini options, as CMultiMetricMap reads them
 * (creation, insertion, likelihood, rendering and MRPT's generic sections of
 * [MappingApplication_evidentialGrid_00_*]). Loading may throw; options it
 * accepts must be valid, write themselves back and read back identically,
 * and create a map. */
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>

#include "FuzzSupport.h"

using namespace mrpt_evidential;

namespace
{
const std::string kPrefix = "MappingApplication_evidentialGrid_00";

/** Insertion options equal, angles within the rounding of their trip
 * through degrees. */
bool sameOptions(
	const CEvidentialGridMap2D::TInsertionOptions& a,
	const CEvidentialGridMap2D::TInsertionOptions& b)
{
	const auto near = [](double x, double y) {
		return std::abs(x - y) <= 1e-15 * std::max(1.0, std::abs(x));
	};
	return a.sensorModel == b.sensorModel && a.muF == b.muF && a.muO == b.muO &&
		a.imprecision == b.imprecision && a.imprecisionProfile == b.imprecisionProfile &&
		near(a.sectorWidth, b.sectorWidth) && a.maxRange == b.maxRange &&
		a.invalidRangesAsFree == b.invalidRangesAsFree && a.fusionRule == b.fusionRule &&
		a.decayRate == b.decayRate &&
		near(a.horizontalTolerance, b.horizontalTolerance) &&
		a.conflictHandling == b.conflictHandling && a.growthMargin == b.growthMargin;
}

bool sameOptions(
	const CEvidentialGridMap2D::TLikelihoodOptions& a,
	const CEvidentialGridMap2D::TLikelihoodOptions& b)
{
	return a.occupiedMass == b.occupiedMass && a.maxCorrsDistance == b.maxCorrsDistance &&
		a.sigma == b.sigma && a.zHit == b.zHit && a.zRandom == b.zRandom &&
		a.maxRange == b.maxRange && a.decimation == b.decimation &&
		a.unknownAsNeutral == b.unknownAsNeutral;
}
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
	fuzz::silenceMapWarnings();
	return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	CEvidentialGridMap2D::TMapDefinition def;
	try
	{
		// MRPT's parser throws too (e.g. on an unclosed $env{...}).
		const mrpt::config::CConfigFileMemory ini(
			std::string(reinterpret_cast<const char*>(data), size));
		def.loadFromConfigFile(ini, kPrefix);
	}
	catch (const std::exception&)
	{
		return 0;
	}

	try
	{
		def.insertionOpts.validate();
		def.likelihoodOpts.validate();
		def.renderingOpts.validate();
	}
	catch (const std::exception& e)
	{
		fuzz::fail(std::string("accepted options are invalid: ") + e.what());
	}

	// What was accepted writes back and reads back the same.
	mrpt::config::CConfigFileMemory written;
	def.insertionOpts.saveToConfigFile(written, "insertOpts");
	def.likelihoodOpts.saveToConfigFile(written, "likelihoodOpts");
	CEvidentialGridMap2D::TInsertionOptions insertion;
	CEvidentialGridMap2D::TLikelihoodOptions likelihood;
	insertion.loadFromConfigFile(written, "insertOpts");
	likelihood.loadFromConfigFile(written, "likelihoodOpts");
	if (!sameOptions(insertion, def.insertionOpts) ||
		!sameOptions(likelihood, def.likelihoodOpts))
		fuzz::fail("options changed through the .ini round trip");
	// The rendering options compare through their own text: every field is
	// written exactly.
	def.renderingOpts.saveToConfigFile(written, "renderOpts");
	CEvidentialGridMap2D::TRenderingOptions rendering;
	rendering.loadFromConfigFile(written, "renderOpts");
	std::ostringstream before, after;
	def.renderingOpts.dumpToTextStream(before);
	rendering.dumpToTextStream(after);
	if (before.str() != after.str()) fuzz::fail("rendering options changed through the .ini round trip");

	// Accepted geometry and budget create the map (small ones only: a big
	// grid is allowed, but slow to fuzz).
	const double cells = GridGeometry::cellsToCover(def.max_x - def.min_x, def.resolution) *
		GridGeometry::cellsToCover(def.max_y - def.min_y, def.resolution);
	if (cells > double(def.maxCells)) fuzz::fail("a grid beyond its budget was accepted");
	if (cells > 1 << 20) return 0;
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.push_back(def);
	mrpt::maps::CMultiMetricMap maps(inits);
	const auto map = maps.mapByClass<CEvidentialGridMap2D>();
	if (!map) fuzz::fail("no map created");
	fuzz::checkMap(*map);
	if (map->maxCells() != def.maxCells || map->getResolution() != def.resolution)
		fuzz::fail("the map differs from its definition");
	return 0;
}
