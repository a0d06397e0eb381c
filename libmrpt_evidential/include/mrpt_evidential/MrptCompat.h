/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * What differs between the MRPT versions the project builds on: MRPT 2.5.8
 * (Debian 12, bookworm) and 2.14 (Debian 13, trixie). Every switch on
 * MRPT_VERSION is here, and nowhere else.
 *
 * MRPT_VERSION had one hex digit per part up to 2.10.1 (2.5.8 is 0x258) and
 * has two since 2.10.2 (2.14.7 is 0x020E07); MRPT_EVIDENTIAL_MRPT_VERSION is
 * the two-digit form of either, which the switches compare.
 *
 * One switch is not MRPT's: Google Benchmark's failed runs (1.7.1 on Debian
 * 12, 1.9.1 on Debian 13), told apart by the member the run has, so that this
 * header includes no benchmark header. */
#pragma once

#include <mrpt/version.h>

#include <memory>
#include <type_traits>
#include <utility>

namespace mrpt::maps
{
class CMetricMap;
}

#if MRPT_VERSION < 0x1000
#define MRPT_EVIDENTIAL_MRPT_VERSION                                        \
	((((MRPT_VERSION) >> 8) << 16) | ((((MRPT_VERSION) >> 4) & 0xF) << 8) | \
	 ((MRPT_VERSION)&0xF))
#else
#define MRPT_EVIDENTIAL_MRPT_VERSION (MRPT_VERSION)
#endif

/** MRPT 2.11.3: the map factories (MAP_DEFINITION_START's
 * CreateFromMapDefinition and internal_CreateFromMapDefinition) return shared
 * pointers, and CMetricMap::boundingBox() is a virtual. */
#define MRPT_EVIDENTIAL_MRPT_SINCE_2_11_3 (MRPT_EVIDENTIAL_MRPT_VERSION >= 0x020B03)

/** MRPT 2.11.3: a map list read from an .ini (TSetOfMetricMapInitializers::
 * loadFromConfigFile) that names a map class nobody registered throws;
 * before, the map was skipped. A stock program reads `evidentialGrid` only
 * with the plugin loaded before its configuration (LD_PRELOAD). */
#define MRPT_EVIDENTIAL_MRPT_REJECTS_UNKNOWN_MAPS MRPT_EVIDENTIAL_MRPT_SINCE_2_11_3

#if MRPT_EVIDENTIAL_MRPT_SINCE_2_11_3
/** What CEvidentialGridMap2D::boundingBox() is to CMetricMap: an override
 * since MRPT 2.11.3, a method of the map alone before. */
#define MRPT_EVIDENTIAL_OVERRIDE_SINCE_2_11_3 override
#else
#define MRPT_EVIDENTIAL_OVERRIDE_SINCE_2_11_3
#endif

namespace mrpt_evidential::compat
{
/** What a map's internal_CreateFromMapDefinition() returns to MRPT's map
 * registry: a raw pointer it takes the ownership of before 2.11.3, a
 * CMetricMap::Ptr since. */
#if MRPT_EVIDENTIAL_MRPT_SINCE_2_11_3
using MapFactoryResult = std::shared_ptr<mrpt::maps::CMetricMap>;
#else
using MapFactoryResult = mrpt::maps::CMetricMap*;
#endif

/** Hands a new map to MRPT's map registry. */
template <class Map>
MapFactoryResult toMapFactoryResult(std::unique_ptr<Map> map)
{
#if MRPT_EVIDENTIAL_MRPT_SINCE_2_11_3
	return MapFactoryResult(std::move(map));
#else
	return map.release();
#endif
}

/** Google Benchmark 1.8 replaced `Run::error_occurred` by `Run::skipped` (an
 * enum, 0 for a run that ran): true for a run that reported no time. */
template <class Run, class = void>
struct HasSkipped : std::false_type
{
};
template <class Run>
struct HasSkipped<Run, std::void_t<decltype(std::declval<const Run&>().skipped)>>
	: std::true_type
{
};
template <class Run>
bool benchmarkRunFailed(const Run& run)
{
	if constexpr (HasSkipped<Run>::value)
		return run.skipped != decltype(run.skipped){};
	else
		return run.error_occurred;
}
}  // namespace mrpt_evidential::compat
