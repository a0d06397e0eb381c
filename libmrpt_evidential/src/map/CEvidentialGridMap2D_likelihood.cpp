/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Observation likelihood of CEvidentialGridMap2D: a likelihood field (Thrun)
 * built from the cells' occupied evidence, and its options. */
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "insert/PolarToCartesian.h"
#include "map/ConfigReading.h"
#include "map/MapWorkspace.h"

namespace mrpt_evidential
{
/** Distances to the nearest obstacle over the map and a margin of cells
 * around it, one byte per cell, and the score of a ray ending in a cell of
 * each byte value. The margin lets an end point just outside the map see the
 * obstacles inside it that are within maxCorrsDistance. */
struct CEvidentialGridMap2D::LikelihoodField
{
	/** Codes below kFarSeen: the distance to the nearest obstacle, below
	 * maxCorrsDistance. When the squared cut, in cells, is below kFarSeen
	 * (the usual case) the code is the exact squared distance in cells;
	 * otherwise c codes the distance maxCorrsDistance (c / (kFarSeen - 1))^2,
	 * rounded: fine near the obstacles, where the score changes, and 0 on
	 * them however long the cut (steps of cut / kFarSeen made a ray on an
	 * obstacle score as if half a step away, metres for a long cut).
	 * kFarSeen: no obstacle within maxCorrsDistance; kFarUnseen: none, and
	 * the cell was never seen (its largest mass is m(Omega)). Every margin
	 * cell is never seen. */
	static constexpr std::uint8_t kFarSeen = 254, kFarUnseen = 255;

	/** The options the field and its scores were built with: the fields are
	 * public and nothing tells the map of a change, so it is checked. */
	TLikelihoodOptions options;
	/** The layout() of the grid it was built for: a map moved from keeps its
	 * cache but is left an empty grid of another layout. */
	std::size_t layout = 0;
	/** Geometry of the field: the map's, grown by the margin on every side. */
	GridGeometry geometry;
	std::vector<std::uint8_t> code;
	/** Log-likelihood of a ray ending in a cell of each code. */
	std::array<double, 256> score{};

	bool builtFor(const TLikelihoodOptions& o, std::size_t gridLayout) const
	{
		return layout == gridLayout && options.occupiedMass == o.occupiedMass &&
			options.maxCorrsDistance == o.maxCorrsDistance &&
			options.sigma == o.sigma && options.zHit == o.zHit &&
			options.zRandom == o.zRandom && options.maxRange == o.maxRange &&
			options.unknownAsNeutral == o.unknownAsNeutral;
	}

	/** Score of a ray ending at world point (x, y); beyond the field, no
	 * obstacle is near and nothing was seen. */
	double scoreAt(double x, double y) const
	{
		const double fx = (x - geometry.xMin) / geometry.resolution;
		const double fy = (y - geometry.yMin) / geometry.resolution;
		// Compared as doubles: a far point must not overflow an int.
		if (!(fx >= 0.0 && fy >= 0.0 && fx < geometry.sizeX &&
			  fy < geometry.sizeY))
			return score[kFarUnseen];
		return score[code[geometry.index(static_cast<int>(fx), static_cast<int>(fy))]];
	}
};

namespace
{
/** Largest margin of the field, cells per side: a huge maxCorrsDistance must
 * not make the field dwarf the map. Points farther outside count as far from
 * every obstacle. */
constexpr int kMaxMarginCells = 1024;
/** The margin is also cut so that the field holds at most 4 times the map's
 * cells plus this many (4M cells, 20 MB): a long thin map with a wide margin
 * would otherwise need hundreds of times its own memory. */
constexpr double kMarginSpareCells = 4.0 * (1 << 20);

/** The widest margin m <= `wanted` for which the field, (sx + 2m) (sy + 2m)
 * cells, stays within the bound above. */
int fieldMargin(const GridGeometry& map, double wanted)
{
	const double sx = map.sizeX, sy = map.sizeY;
	// 4 m^2 + 2 b m - c <= 0 up to its positive root.
	const double b = sx + sy, c = 3.0 * sx * sy + kMarginSpareCells;
	const double root = (std::sqrt(b * b + 4.0 * c) - b) / 4.0;
	return static_cast<int>(
		std::min({wanted, double(kMaxMarginCells), std::floor(root)}));
}

/** The occupied mass with the conflict set aside, m(O) / (1 - m(empty)), as
 * Dempster's normalization (and betP) would read it; m(O) itself when the
 * cell holds no conflict. With ConflictHandling::Keep the surfaces of real
 * walls end up mostly in conflict (the beams that stop there meet those that
 * pass a few centimetres beyond): m(O) alone would leave only the cells
 * behind the surfaces as obstacles. 0 at total conflict. */
double occupiedShare(const Mass& m)
{
	const double k = m.free + m.occupied + m.unknown;
	return k > kTotalConflictTolerance ? m.occupied / k : 0.0;
}

/** Exact squared Euclidean distance transform (Felzenszwalb and Huttenlocher)
 * of one row: out[x] = min over q of (x - q)^2 + h[q]^2, for the q whose
 * h[q] <= reach; out[x] = +inf when there is none. h holds vertical
 * distances in cells. O(n): `sites` and `bounds` are scratch of size n and
 * n + 1. */
void rowDistanceTransform(
	const std::int32_t* h, int n, std::int32_t reach, double* out,
	std::vector<int>& sites, std::vector<double>& bounds)
{
	constexpr double kInf = std::numeric_limits<double>::infinity();
	const auto f = [h](int q) {
		return static_cast<double>(h[q]) * static_cast<double>(h[q]);
	};
	// Lower envelope of the parabolas (x - q)^2 + h[q]^2: sites[0..k] with
	// parabola sites[j] lowest over [bounds[j], bounds[j + 1]).
	int k = -1;
	for (int q = 0; q < n; ++q)
	{
		if (h[q] > reach) continue;
		double s = -kInf;
		while (k >= 0)
		{
			const int v = sites[k];
			s = ((f(q) + double(q) * q) - (f(v) + double(v) * v)) /
				(2.0 * (q - v));
			if (s > bounds[k]) break;
			--k;
		}
		++k;
		sites[k] = q;
		bounds[k] = k == 0 ? -kInf : s;
		bounds[k + 1] = kInf;
	}
	if (k < 0)
	{
		std::fill(out, out + n, kInf);
		return;
	}
	int j = 0;
	for (int x = 0; x < n; ++x)
	{
		while (bounds[j + 1] < x) ++j;
		const double dx = x - sites[j];
		out[x] = dx * dx + f(sites[j]);
	}
}

/** log(exp(a) + exp(b)) without overflow or underflow; either may be -inf.
 * Scoring in logs keeps a ray finite when its Gaussian term underflows. */
double logAddExp(double a, double b)
{
	if (a < b) std::swap(a, b);
	if (b == -std::numeric_limits<double>::infinity()) return a;
	return a + std::log1p(std::exp(b - a));
}

}  // namespace

void TEvidentialLikelihoodOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	// All or nothing: *this changes only when every value is valid.
	TEvidentialLikelihoodOptions o = *this;
	detail::readDouble(source, section, "occupiedMass", o.occupiedMass);
	detail::readDouble(source, section, "maxCorrsDistance", o.maxCorrsDistance);
	detail::readDouble(source, section, "sigma", o.sigma);
	detail::readDouble(source, section, "zHit", o.zHit);
	detail::readDouble(source, section, "zRandom", o.zRandom);
	detail::readDouble(source, section, "maxRange", o.maxRange);
	detail::readCount(source, section, "decimation", o.decimation);
	detail::readBool(source, section, "unknownAsNeutral", o.unknownAsNeutral);
	detail::throwIfInvalid(source, section, o.firstInvalid());
	*this = o;
}

std::optional<TInvalidOption> TEvidentialLikelihoodOptions::firstInvalid() const
{
	// Written as !(valid) so that NaN fails every test.
	const auto positive = [](double v) { return v > 0.0 && std::isfinite(v); };
	const auto nonNegative = [](double v) { return v >= 0.0 && std::isfinite(v); };
	if (!(occupiedMass > 0.0 && occupiedMass <= 1.0))
		return TInvalidOption{"occupiedMass", "in (0, 1]", occupiedMass};
	if (!(positive(maxCorrsDistance) && maxCorrsDistance <= kMaxCorrsDistance))
		return TInvalidOption{"maxCorrsDistance", "in (0, 1000] m", maxCorrsDistance};
	if (!positive(sigma)) return TInvalidOption{"sigma", "> 0 and finite", sigma};
	if (!nonNegative(zHit)) return TInvalidOption{"zHit", ">= 0 and finite", zHit};
	if (!nonNegative(zRandom))
		return TInvalidOption{"zRandom", ">= 0 and finite", zRandom};
	if (zHit == 0.0 && zRandom == 0.0)
		return TInvalidOption{"zHit", "above 0 when zRandom is 0 (not both 0)", zHit};
	if (!positive(maxRange)) return TInvalidOption{"maxRange", "> 0 and finite", maxRange};
	if (decimation < 1)
		return TInvalidOption{"decimation", "an integer >= 1", double(decimation)};
	return std::nullopt;
}

void TEvidentialLikelihoodOptions::validate() const
{
	if (const auto bad = firstInvalid())
		throw std::invalid_argument("likelihoodOpts: " + bad->describe());
}

void TEvidentialLikelihoodOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& target, const std::string& section) const
{
	using detail::writeValue;
	writeValue(target, section, "occupiedMass", occupiedMass,
			   "(0, 1]: obstacles have m(O) / (1 - m(empty)) >= this");
	writeValue(target, section, "maxCorrsDistance", maxCorrsDistance, "m");
	writeValue(target, section, "sigma", sigma, "m");
	writeValue(target, section, "zHit", zHit, "weight, >= 0");
	writeValue(target, section, "zRandom", zRandom, "weight, >= 0");
	writeValue(target, section, "maxRange", maxRange, "m");
	writeValue(target, section, "decimation", static_cast<double>(decimation),
			   "rays: one scored in this many");
	writeValue(target, section, "unknownAsNeutral", unknownAsNeutral,
			   "a ray ending in a never-seen cell scores as neither hit nor miss");
}

void TEvidentialLikelihoodOptions::dumpToTextStream(
	std::ostream& out) const
{
	detail::dumpAsIni(*this, "likelihoodOpts", out);
}

void CEvidentialGridMap2D::invalidateLikelihoodCache()
{
	std::lock_guard<std::mutex> lock(m_workspace->likelihoodMutex);
	m_workspace->likelihood.reset();
}

std::shared_ptr<const CEvidentialGridMap2D::LikelihoodField>
	CEvidentialGridMap2D::likelihoodField() const
{
	// The lock is held while building: threads that ask at the same time wait
	// for the one build instead of each making its own.
	std::lock_guard<std::mutex> lock(m_workspace->likelihoodMutex);
	std::shared_ptr<const LikelihoodField>& cached = m_workspace->likelihood;
	const TLikelihoodOptions& opts = likelihoodOptions;
	if (cached && cached->builtFor(opts, m_grid.layout())) return cached;
	opts.validate();

	const GridGeometry& map = m_grid.geometry();
	// No cell holds more than the ceiling (within its rounding): a
	// threshold above it would find no obstacle at all.
	const double occupiedMass =
		std::min(opts.occupiedMass, EvidentialGridStorage::kMaxCertainty - 2 * kQuantizationError);
	auto field = std::make_shared<LikelihoodField>();
	field->options = opts;
	field->layout = m_grid.layout();
	using Field = LikelihoodField;
	const double cutCells = opts.maxCorrsDistance / map.resolution;
	const bool squaredCodes = cutCells * cutCells < Field::kFarSeen;
	constexpr double kTop = Field::kFarSeen - 1;
	const auto distanceOf = [&](int c) {
		return squaredCodes ? std::sqrt(static_cast<double>(c)) * map.resolution
							: opts.maxCorrsDistance * (c / kTop) * (c / kTop);
	};
	const auto codeOf = [&](double squaredCells, double d) {
		return squaredCodes ? squaredCells
							: std::floor(kTop * std::sqrt(d / opts.maxCorrsDistance) + 0.5);
	};

	// Per ray: log(zRandom / maxRange + zHit exp(-d^2 / (2 sigma^2))), as the
	// log-sum of its two terms (a zero weight is a term of log 0), so that a
	// very small sigma still gives a finite score. Far from every obstacle d
	// is the cut, or half of it in a never-seen cell: neither hit nor miss.
	constexpr double kLogZero = -std::numeric_limits<double>::infinity();
	const double logRandom =
		opts.zRandom > 0.0 ? std::log(opts.zRandom / opts.maxRange) : kLogZero;
	const double logHit = opts.zHit > 0.0 ? std::log(opts.zHit) : kLogZero;
	// d / sigma first: d^2 and sigma^2 may each overflow (inf / inf is NaN).
	const auto scoreOf = [&](double d) {
		const double z = d / opts.sigma;
		return logAddExp(logRandom, logHit - 0.5 * z * z);
	};
	for (int c = 0; c < Field::kFarSeen; ++c) field->score[c] = scoreOf(distanceOf(c));
	field->score[Field::kFarSeen] = scoreOf(opts.maxCorrsDistance);
	field->score[Field::kFarUnseen] = scoreOf(
		opts.unknownAsNeutral ? 0.5 * opts.maxCorrsDistance : opts.maxCorrsDistance);

	// Distances are exact up to the cut: the reach (in cells) is the cut
	// rounded up, and farther sites never win below the cut.
	const double reachCells =
		std::ceil(opts.maxCorrsDistance / map.resolution);
	const int margin = fieldMargin(map, reachCells);
	GridGeometry& g = field->geometry;
	g = GridGeometry{
		map.xMin - margin * map.resolution, map.yMin - margin * map.resolution,
		map.resolution, map.sizeX + 2 * margin, map.sizeY + 2 * margin};
	// No vertical distance reaches the field's height: capping there changes
	// nothing and keeps reach + 1 from overflowing.
	const auto reach = static_cast<std::int32_t>(
		std::min<double>(reachCells, g.sizeY));
	const std::size_t cells = g.cellCount();
	field->code.assign(cells, Field::kFarUnseen);

	// Vertical distance to the nearest obstacle of the same column, in cells,
	// saturated at reach + 1 ("none within reach"): a downward and an upward
	// sweep, row by row so that memory is read in order.
	const std::int32_t none = reach + 1;
	std::vector<std::int32_t> vertical(cells, none);
	for (int fy = 0; fy < g.sizeY; ++fy)
	{
		const int cy = fy - margin;
		std::int32_t* row = vertical.data() + g.index(0, fy);
		const std::int32_t* below =
			fy > 0 ? vertical.data() + g.index(0, fy - 1) : nullptr;
		for (int fx = 0; fx < g.sizeX; ++fx)
		{
			const int cx = fx - margin;
			bool obstacle = false;
			if (map.inside(cx, cy))
			{
				const std::size_t idx = map.index(cx, cy);
				const Mass m = m_grid.read(idx);
				obstacle = m_grid.heldImpact(idx) && occupiedShare(m) >= occupiedMass;
				if (decide(m) != Decision::Unknown)
					field->code[g.index(fx, fy)] = Field::kFarSeen;
			}
			if (obstacle)
				row[fx] = 0;
			else if (below)
				row[fx] = std::min(below[fx] + 1, none);
		}
	}
	for (int fy = g.sizeY - 2; fy >= 0; --fy)
	{
		std::int32_t* row = vertical.data() + g.index(0, fy);
		const std::int32_t* above = vertical.data() + g.index(0, fy + 1);
		for (int fx = 0; fx < g.sizeX; ++fx)
			row[fx] = std::min(row[fx], std::min(above[fx] + 1, none));
	}

	// Then along each row, the exact 2-D distance from the vertical ones.
	std::vector<double> squared(static_cast<std::size_t>(g.sizeX));
	std::vector<int> sites(static_cast<std::size_t>(g.sizeX));
	std::vector<double> bounds(static_cast<std::size_t>(g.sizeX) + 1);
	for (int fy = 0; fy < g.sizeY; ++fy)
	{
		const std::size_t first = g.index(0, fy);
		rowDistanceTransform(
			vertical.data() + first, g.sizeX, reach, squared.data(), sites,
			bounds);
		for (int fx = 0; fx < g.sizeX; ++fx)
		{
			const double d = std::sqrt(squared[fx]) * g.resolution;
			if (d < opts.maxCorrsDistance)
				field->code[first + fx] = static_cast<std::uint8_t>(
					std::min<double>(codeOf(squared[fx], d), kTop));
		}
	}

	cached = field;
	return cached;
}

/* Only CObservation2DRangeScan is scored, as insertion reads it: any other
 * observation, and a scan whose sensor tilts beyond horizontalTolerance
 * (insertion ignores it), gives 0 (a log-likelihood that changes no particle
 * weight), and internal_canComputeObservationLikelihood() says so beforehand
 * as far as the scan's mounting on the robot tells. */
double CEvidentialGridMap2D::internal_computeObservationLikelihood(
	const mrpt::obs::CObservation& obs,
	const mrpt::poses::CPose3D& takenFrom) const
{
	const auto* scan =
		dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
	if (!scan) return 0.0;
	const TLikelihoodOptions& opts = likelihoodOptions;
	opts.validate();
	const std::shared_ptr<const LikelihoodField> field = likelihoodField();

	const mrpt::poses::CPose3D sensorPose = takenFrom + scan->sensorPose;
	if (!planarSensorPose(sensorPose, insertionOptions.horizontalTolerance)) return 0.0;
	const auto& R = sensorPose.getRotationMatrix();
	const std::size_t n = scan->getScanSize();
	const std::size_t decimation = opts.decimation;
	// The rays' directions turn by a fixed angle from one scored ray to the
	// next: one sin/cos every kExactEvery scored rays, not one per ray, so
	// that the rotations in between cannot drift. The angles in doubles, as
	// insertion places the beams (MRPT's getScanAngle() is a float); a scan
	// taken left to right runs the other way. A single-beam scan looks
	// straight ahead, as insertion reads it.
	const double aperture = scan->aperture;
	const double first = n > 1 ? (scan->rightToLeft ? -0.5 : 0.5) * aperture : 0.0;
	const double step = n > 1
		? (scan->rightToLeft ? aperture : -aperture) / static_cast<double>(n - 1)
		: 0.0;
	const double turn = step * static_cast<double>(decimation);
	constexpr std::size_t kExactEvery = 64;
	double c = 1.0, s = 0.0;
	const double turnC = std::cos(turn), turnS = std::sin(turn);
	double logLikelihood = 0.0;
	for (std::size_t i = 0, k = 0; i < n; i += decimation, ++k)
	{
		if (k % kExactEvery == 0)
		{
			const double angle = first + step * static_cast<double>(i);
			c = std::cos(angle), s = std::sin(angle);
		}
		const double r = scan->getScanRange(i);
		if (scan->getScanRangeValidity(i) && std::isfinite(r) && r > 0.0 &&
			r < opts.maxRange)
		{
			// The end point in the sensor's frame, then in the world.
			const double lx = r * c, ly = r * s;
			logLikelihood += field->scoreAt(
				sensorPose.x() + R(0, 0) * lx + R(0, 1) * ly,
				sensorPose.y() + R(1, 0) * lx + R(1, 1) * ly);
		}
		const double nc = c * turnC - s * turnS;
		s = s * turnC + c * turnS;
		c = nc;
	}
	return logLikelihood;
}

bool CEvidentialGridMap2D::internal_canComputeObservationLikelihood(
	const mrpt::obs::CObservation& obs) const
{
	// The robot's own pose is not known here: a level robot is assumed, as
	// MRPT's grid does.
	const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
	return scan && planarSensorPose(scan->sensorPose, insertionOptions.horizontalTolerance);
}

}  // namespace mrpt_evidential
