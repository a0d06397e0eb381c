/* Synthetic 2-D laser scans for the unit tests, the fuzz targets' seeds and
 * the benchmark: the one place where a CObservation2DRangeScan is filled in.
 *
 * A scan is described in two parts. A ScanSetup says how it is taken
 * (aperture, direction, mounting, maximum range, time stamp) and is built
 * from MRPT's defaults by modifiers that each return a changed copy, so that
 * a test can keep its usual setup as a constant and vary it per call:
 *
 *     const test::ScanSetup kSetup = test::ScanSetup().maxRange(30.0);
 *     auto a = test::arcScan(181, 4.0, kSetup);             // every beam at 4 m
 *     auto b = test::scanByAngle(181, kSetup.at(12.5),       // range = f(angle)
 *                                [](double a) { return 2.0 + std::sin(a); });
 *
 * A builder then gives the beams their ranges and validity flags. Ranges are
 * stored as MRPT stores them, as float. */
#pragma once

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace mrpt_evidential::test
{
/** How a scan is taken: everything but its ranges. A default setup is
 * MRPT's default scan: aperture pi, counterclockwise (rightToLeft), the
 * sensor at the robot's origin, MRPT's maxRange and no time stamp. */
class ScanSetup
{
   public:
	/** Field of view, rad; the beams are spread evenly over it. */
	ScanSetup aperture(double rad) const
	{
		ScanSetup s = *this;
		s.m_aperture = rad;
		return s;
	}
	/** The scan's maxRange, m (unset: MRPT's default). */
	ScanSetup maxRange(double metres) const
	{
		ScanSetup s = *this;
		s.m_maxRange = static_cast<float>(metres);
		return s;
	}
	/** Time stamp at `seconds` of data time (mrpt::Clock::fromDouble). */
	ScanSetup at(double seconds) const { return at(mrpt::Clock::fromDouble(seconds)); }
	/** Time stamp at a raw clock value. */
	ScanSetup at(mrpt::Clock::time_point t) const
	{
		ScanSetup s = *this;
		s.m_time = t;
		return s;
	}
	/** MRPT's scan direction: true (the default) sweeps counterclockwise,
	 * beam 0 at -aperture/2; false sweeps clockwise, beam 0 at +aperture/2. */
	ScanSetup rightToLeft(bool counterclockwise) const
	{
		ScanSetup s = *this;
		s.m_rightToLeft = counterclockwise;
		return s;
	}
	/** Where the sensor sits on the robot. */
	ScanSetup sensorPose(const mrpt::poses::CPose3D& pose) const
	{
		ScanSetup s = *this;
		s.m_sensorPose = pose;
		return s;
	}

	/** A scan of `n` beams taken this way, its ranges as resizeScan() leaves
	 * them; the builders below fill them in. */
	mrpt::obs::CObservation2DRangeScan make(std::size_t n) const
	{
		mrpt::obs::CObservation2DRangeScan scan;
		scan.aperture = static_cast<float>(m_aperture);
		scan.rightToLeft = m_rightToLeft;
		if (m_maxRange) scan.maxRange = *m_maxRange;
		scan.sensorPose = m_sensorPose;
		if (m_time) scan.timestamp = *m_time;
		scan.resizeScan(n);
		return scan;
	}

   private:
	double m_aperture = M_PI;
	bool m_rightToLeft = true;
	std::optional<float> m_maxRange;
	std::optional<mrpt::Clock::time_point> m_time;
	mrpt::poses::CPose3D m_sensorPose;
};

/** One beam's return, for builders whose beams are not all valid. */
struct Beam
{
	double range = 0.0;
	bool valid = true;
};

/** The angle of beam i in the sensor's frame, as MRPT gives it; the one beam
 * of a one-beam scan points straight ahead (MRPT's formula divides by
 * n - 1). */
inline double beamAngle(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t i)
{
	return scan.getScanSize() > 1 ? double(scan.getScanAngle(i)) : 0.0;
}

namespace detail
{
/** Sets beam i from what a range function returned: a number (a valid
 * beam) or a Beam. */
template <typename R>
void setBeam(mrpt::obs::CObservation2DRangeScan& scan, std::size_t i, const R& r)
{
	if constexpr (std::is_same_v<R, Beam>)
	{
		scan.setScanRange(i, static_cast<float>(r.range));
		scan.setScanRangeValidity(i, r.valid);
	}
	else
	{
		scan.setScanRange(i, static_cast<float>(r));
		scan.setScanRangeValidity(i, true);
	}
}
}  // namespace detail

/** `n` beams; beam i returns rangeAt(its angle, rad), see beamAngle().
 * rangeAt returns a range (the beam is valid) or a Beam. */
template <typename F>
mrpt::obs::CObservation2DRangeScan scanByAngle(
	std::size_t n, const ScanSetup& setup, F&& rangeAt)
{
	auto scan = setup.make(n);
	for (std::size_t i = 0; i < n; ++i) detail::setBeam(scan, i, rangeAt(beamAngle(scan, i)));
	return scan;
}

/** `n` beams; beam i returns rangeAt(i). rangeAt returns a range (the beam
 * is valid) or a Beam. */
template <typename F>
mrpt::obs::CObservation2DRangeScan scanByIndex(
	std::size_t n, const ScanSetup& setup, F&& rangeAt)
{
	auto scan = setup.make(n);
	for (std::size_t i = 0; i < n; ++i) detail::setBeam(scan, i, rangeAt(i));
	return scan;
}

/** `n` valid beams that all return at `range`: an arc of a circle around
 * the sensor. */
inline mrpt::obs::CObservation2DRangeScan arcScan(
	std::size_t n, double range, const ScanSetup& setup = {})
{
	return scanByIndex(n, setup, [range](std::size_t) { return range; });
}

/** `n` valid beams facing a straight wall at `distance` ahead of the sensor,
 * across its x axis: beam i returns at distance / cos(angle), the cosine
 * taken in float of the float angle MRPT gives. The aperture must stay below
 * pi for every beam to reach the wall. */
inline mrpt::obs::CObservation2DRangeScan flatWallScan(
	std::size_t n, double distance, const ScanSetup& setup = {})
{
	return scanByAngle(n, setup, [distance](double a) {
		return distance / std::cos(static_cast<float>(a));
	});
}

/** One beam per range, with the given validity flags (as many as ranges). */
inline mrpt::obs::CObservation2DRangeScan scanFromRanges(
	const std::vector<float>& ranges, const std::vector<bool>& valid,
	const ScanSetup& setup = {})
{
	auto scan = setup.make(ranges.size());
	for (std::size_t i = 0; i < ranges.size(); ++i)
	{
		scan.setScanRange(i, ranges[i]);
		scan.setScanRangeValidity(i, valid.at(i));
	}
	return scan;
}
}  // namespace mrpt_evidential::test
