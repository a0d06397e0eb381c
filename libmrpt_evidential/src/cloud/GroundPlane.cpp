/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "cloud/GroundPlane.h"

#include <mrpt_evidential/support/CpuClones.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <random>

namespace mrpt_evidential
{
namespace
{
/** RANSAC draws from the lowest candidate of each column: mostly ground,
 * even where the ground is a small share of the points (walls and crowns
 * stand on it). */
constexpr double kColumn = kGroundColumn, kColumnReach = kGroundReach;
/** RANSAC's tries at most: with ground in 40 % of the columns and more, the
 * chance that no try draws three ground points is below kMissRisk. The
 * search stops sooner once the best plane's share of the columns makes that
 * chance as small (most clouds have ground in most columns). */
constexpr int kTries = 200;
constexpr double kMissRisk = 1e-5;
/** Marks of columnsOf(). */
constexpr int kNotGround = -1, kOutsideColumns = -2;

/** The tries after which a plane holding `share` of the sample has been
 * drawn at least once but with a chance below kMissRisk. */
int triesFor(double share)
{
	const double allThree = share * share * share;
	if (!(allThree > 0.0)) return kTries;
	if (allThree >= 1.0) return 1;
	return static_cast<int>(std::min<double>(
		kTries, std::ceil(std::log(kMissRisk) / std::log1p(-allThree))));
}

/** RANSAC's sample, one array per coordinate: counting the inliers of a
 * plane is then one loop the compiler vectorizes. */
struct TSample
{
	std::vector<float> x, y, z;
	void add(const mrpt::math::TPoint3Df& p) { x.push_back(p.x), y.push_back(p.y), z.push_back(p.z); }
	std::size_t size() const { return x.size(); }
	mrpt::math::TPoint3Df operator[](std::size_t i) const { return {x[i], y[i], z[i]}; }
	/** How many points lie within `distance` of `plane`, along z. */
	std::size_t inliersOf(const TGroundPlane& plane, double distance) const
	{
		const auto a = static_cast<float>(plane.a), b = static_cast<float>(plane.b),
				   c = static_cast<float>(plane.c), d = static_cast<float>(distance);
		std::size_t count = 0;
		for (std::size_t i = 0, n = size(); i < n; ++i)
			count += std::abs(z[i] - (a * x[i] + b * y[i] + c)) <= d;
		return count;
	}
};

/** The plane through three points, if they span one that is not steeper
 * than the rules allow. */
std::optional<TGroundPlane> planeThrough(
	const mrpt::math::TPoint3Df& p, const mrpt::math::TPoint3Df& q,
	const mrpt::math::TPoint3Df& r, double maxSlope)
{
	const double ux = q.x - p.x, uy = q.y - p.y, uz = q.z - p.z;
	const double vx = r.x - p.x, vy = r.y - p.y, vz = r.z - p.z;
	const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
	const double norm = std::sqrt(nx * nx + ny * ny + nz * nz);
	if (!(norm > 1e-9) || std::abs(nz) < std::cos(maxSlope) * norm) return std::nullopt;
	TGroundPlane plane;
	plane.a = -nx / nz;
	plane.b = -ny / nz;
	plane.c = p.z - plane.a * p.x - plane.b * p.y;
	return plane;
}

/** Where ground can lie: below the sensor by the mounting heights, give or
 * take the steepest slope's rise at a point's distance. */
struct TGroundBand
{
	double slope, top, bottom;
	/** Whether a point at (x, y, z) may be ground: finite (float coordinates
	 * cannot overflow r2) and within the heights; NaN fails every test.
	 * Without a branch, so that the loop that asks it vectorizes. */
	bool admits(double x, double y, double z) const
	{
		// Not std::hypot: its care for overflow cost most of the fit.
		const double r2 = x * x + y * y;
		const double rise = slope * std::sqrt(r2);
		return (z <= top + rise) & (z >= bottom - rise) & (r2 <= DBL_MAX);
	}
};

/** Least squares of z = a x + b y + c over the candidates (candidate[i]
 * set) within inlierDistance of `plane`; the plane itself when they do not
 * fix one. */
TGroundPlane refine(
	const std::vector<mrpt::math::TPoint3Df>& points, const std::uint8_t* candidate,
	const TGroundPlane& plane, double inlierDistance, std::size_t& inliers)
{
	double sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0, n = 0, sxz = 0, syz = 0, sz = 0;
	// Block by block, the inliers first, without a branch (whether a point
	// is one follows no pattern); then their sums, one chain in the points'
	// order, while the block is still in the level-1 cache.
	int in[kPointBlock];
	forEachPointBlock(points.size(), [&](std::size_t first, std::size_t m) {
		const mrpt::math::TPoint3Df* block = &points[first];
		std::size_t count = 0;
		for (std::size_t j = 0; j < m; ++j)
		{
			in[count] = static_cast<int>(j);
			count += candidate[first + j] & (std::abs(plane.heightOf(block[j])) <= inlierDistance);
		}
		for (std::size_t k = 0; k < count; ++k)
		{
			const auto& p = block[in[k]];
			const double x = p.x, y = p.y, z = p.z;
			sxx += x * x, sxy += x * y, syy += y * y, sx += x, sy += y, n += 1.0;
			sxz += x * z, syz += y * z, sz += z;
		}
	});
	inliers = static_cast<std::size_t>(n);
	// Cramer's rule on the normal equations.
	const double det = sxx * (syy * n - sy * sy) - sxy * (sxy * n - sy * sx) +
		sx * (sxy * sy - syy * sx);
	if (!(std::abs(det) > 1e-9 * std::max(1.0, n * n * n))) return plane;
	TGroundPlane out;
	out.a = (sxz * (syy * n - sy * sy) - sxy * (syz * n - sy * sz) +
			 sx * (syz * sy - syy * sz)) / det;
	out.b = (sxx * (syz * n - sz * sy) - sxz * (sxy * n - sy * sx) +
			 sx * (sxy * sz - syz * sx)) / det;
	out.c = (sxx * (syy * sz - sy * syz) - sxy * (sxy * sz - syz * sx) +
			 sxz * (sxy * sy - syy * sx)) / det;
	return out;
}

/** Each point's column (x + side * y), kOutsideColumns for a candidate
 * outside them, or kNotGround for a point band.admits() rejects; and in
 * `candidates` whether each point is one. Returns their count. One loop
 * without branches: it vectorizes. */
std::size_t columnsOf(
	const float* xyz, std::size_t n, const TGroundBand& band, int* columns,
	std::uint8_t* candidates)
{
	constexpr double side = 2 * kColumnReach / kColumn;
	std::size_t count = 0;
	for (std::size_t i = 0; i < n; ++i)
	{
		const double x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
		const bool candidate = band.admits(x, y, z);
		const double fx = (x + kColumnReach) / kColumn, fy = (y + kColumnReach) / kColumn;
		const bool inside = (fx >= 0) & (fy >= 0) & (fx < side) & (fy < side);
		// The offsets being >= 0, truncation is the floor.
		const int column = static_cast<int>(inside ? fx : 0.0) +
			static_cast<int>(side) * static_cast<int>(inside ? fy : 0.0);
		columns[i] = !candidate ? kNotGround : inside ? column : kOutsideColumns;
		candidates[i] = candidate;
		count += candidate;
	}
	return count;
}
}  // namespace

MRPT_EVIDENTIAL_CPU_CLONES std::optional<TGroundPlane> fitGroundPlane(
	const std::vector<mrpt::math::TPoint3Df>& points, const TGroundFit& fit,
	std::vector<std::uint8_t>& candidate, std::vector<int>& lowest)
{
	TGroundBand band;
	band.slope = std::tan(fit.maxSlope);
	band.top = fit.sensorZ - fit.minSensorHeight;
	band.bottom = fit.sensorZ - fit.maxSensorHeight;
	static_assert(sizeof(mrpt::math::TPoint3Df) == 3 * sizeof(float), "packed points");
	constexpr auto side = static_cast<std::size_t>(2 * kColumnReach / kColumn);
	// Each column's lowest height beside its point: no lookup through the
	// points. A block's columns are found in one loop that vectorizes and
	// read back in one that cannot while they, and the block's points, are
	// still in the level-1 cache: the cloud is read once.
	lowest.assign(side * side, -1);
	std::vector<float> lowestZ(side * side, HUGE_VALF);
	std::size_t candidates = 0;
	int columns[kPointBlock];
	candidate.resize(points.size());
	forEachPointBlock(points.size(), [&](std::size_t first, std::size_t m) {
		candidates += columnsOf(&points[first].x, m, band, columns, &candidate[first]);
		for (std::size_t j = 0; j < m; ++j)
		{
			if (columns[j] < 0) continue;
			const auto c = static_cast<std::size_t>(columns[j]);
			const float z = points[first + j].z;
			if (z < lowestZ[c]) lowestZ[c] = z, lowest[c] = static_cast<int>(first + j);
		}
	});
	if (candidates < std::max<std::size_t>(fit.minInliers, 3))
	{
		lowest.clear();
		return std::nullopt;
	}
	TSample sample;
	for (const int i : lowest)
		if (i >= 0) sample.add(points[static_cast<std::size_t>(i)]);
	if (sample.size() < 3) return std::nullopt;

	std::minstd_rand rng(1);
	std::uniform_int_distribution<std::size_t> pick(0, sample.size() - 1);
	std::optional<TGroundPlane> best;
	std::size_t bestCount = 0;
	for (int t = 0, tries = kTries; t < tries; ++t)
	{
		const auto plane = planeThrough(
			sample[pick(rng)], sample[pick(rng)], sample[pick(rng)], fit.maxSlope);
		if (!plane || !(plane->c <= band.top && plane->c >= band.bottom)) continue;
		const std::size_t count = sample.inliersOf(*plane, fit.inlierDistance);
		if (count <= bestCount) continue;
		bestCount = count, best = plane;
		tries = triesFor(static_cast<double>(count) / static_cast<double>(sample.size()));
	}
	if (!best) return std::nullopt;
	std::size_t inliers = 0;
	const TGroundPlane refined =
		refine(points, candidate.data(), *best, fit.inlierDistance, inliers);
	const double share = static_cast<double>(inliers) / static_cast<double>(candidates);
	if (inliers < fit.minInliers || share < fit.minInlierShare) return std::nullopt;
	// The refined plane must still obey the rules; else keep RANSAC's.
	const double tilt = std::atan(std::hypot(refined.a, refined.b));
	if (!(tilt <= fit.maxSlope && refined.c <= band.top && refined.c >= band.bottom)) return best;
	return refined;
}

}  // namespace mrpt_evidential
