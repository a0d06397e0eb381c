/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include <mrpt/poses/CPose3D.h>
#include "insert/PolarToCartesian.h"
#include "insert/GapOutline.h"

namespace mrpt_evidential
{
std::optional<PlanarSensorPose> planarSensorPose(
	const mrpt::poses::CPose3D& sensor, double tolerance)
{
	// Planar when the sensor's x and y axes both lie within `tolerance` of
	// the horizontal plane; a negative determinant of their horizontal parts
	// means the sensor is upside down.
	const auto& R = sensor.getRotationMatrix();
	const double maxTilt = std::sin(tolerance) + 1e-9;
	if (std::abs(R(2, 0)) > maxTilt || std::abs(R(2, 1)) > maxTilt)
		return std::nullopt;
	return PlanarSensorPose{
		sensor.x(), sensor.y(), std::atan2(R(1, 0), R(0, 0)),
		R(0, 0) * R(1, 1) - R(0, 1) * R(1, 0) < 0.0};
}

using detail::forEachGap;
using detail::kCentreLineSlack;
using detail::outline;
using detail::TGapRadius;

namespace
{
/** Sectors on either side whose nearest impacts give the slope of the
 * surface a sector's nearest impact lies on: one sector apart, range noise
 * makes a head-on wall look oblique. */
constexpr long kIncidenceSpan = 2;
/** The free margin along a beam is at most this many times `freeMargin`:
 * past 70 degrees of incidence (and at a depth edge, where the slope is no
 * surface) it stops growing. */
constexpr double kMaxMarginStretch = 3.0;
/** The vacuous bands are outlined and left out of the visit when they hold
 * at least this many cells: below it, long thin bands (far beams beside near
 * ones) cost more in their two outlines' row spans than their cells found
 * vacuous one by one (doc/performance-history.md). */
constexpr double kMinVacuousCells = 20000.0;
/** The free margin along sector s's beam, given each sector's nearest
 * impact (`nearest`, +inf without one): `margin` across the surface that
 * impact lies on. A beam that meets a wall at incidence a crosses a band
 * of depth d in front of it over d / cos(a), so a margin measured along the
 * beam would protect a grazed wall by only its cosine. The surface's slope
 * is taken on the flatter side (the nearest impacts kIncidenceSpan sectors
 * away), so that a wall's end beside a depth edge keeps the wall's own
 * slope. A beam without return (an impact at infinity) hit no surface. */
double marginAlongBeam(
	const std::vector<double>& nearest, bool fullTurn, double spacing, double margin,
	std::size_t s)
{
	const auto n = static_cast<long>(nearest.size());
	const auto rangeOf = [&](long t) {
		if (t < 0 || t >= n)
		{
			if (!fullTurn) return HUGE_VAL;
			t = (t + n) % n;
		}
		return nearest[static_cast<std::size_t>(t)];
	};
	const double r = nearest[s];
	if (margin == 0.0 || !(r > 0.0 && r < HUGE_VAL)) return margin;
	// tan(incidence) = (dr / dtheta) / r, on the side of the smaller dr.
	double dr = HUGE_VAL;
	for (const long side : {-kIncidenceSpan, kIncidenceSpan})
		if (const double other = rangeOf(static_cast<long>(s) + side); other < HUGE_VAL)
			dr = std::min(dr, std::abs(other - r));
	if (dr == HUGE_VAL) return margin;
	const double arc = r * static_cast<double>(kIncidenceSpan) * spacing;
	const double tan2 = (dr * dr) / (arc * arc);
	return tan2 >= kMaxMarginStretch * kMaxMarginStretch - 1.0
		? margin * kMaxMarginStretch
		: margin * std::sqrt(1.0 + tan2);
}

}  // namespace

void CPolarToCartesian::setup(
	const CPolarSourceGrid& polar, const PlanarSensorPose& sensor)
{
	m_polar = &polar;
	m_sensor = sensor;
	m_box = Box{};
	m_vacuousArea = 0.0;
	m_polygon.clear();
	m_uniformPolygon.clear();
	const std::size_t n = polar.sectorCount();
	if (n == 0 || polar.maxTransformBins() == 0) return;

	const double bin = polar.binSize(), spacing = polar.sectorSpacing();
	m_invSpacing = 1.0 / spacing;
	m_bandSlack = kCentreLineSlack * m_invSpacing;
	m_span = static_cast<double>(n) * spacing;
	m_invBin = 1.0 / bin;
	m_dir = sensor.mirrored ? -1.0 : 1.0;
	const double spanStart = polar.firstSectorAngle() - 0.5 * spacing;
	m_yawOffset = std::fmod(sensor.yaw + m_dir * spanStart, 2 * M_PI);
	if (m_yawOffset < 0.0) m_yawOffset += 2 * M_PI;

	// World directions of the outline's corners: the start of sector 0's
	// span, each centre (by turning the first one, no sin/cos per sector),
	// and the end of the last span (for a full turn, centre 0 again).
	m_directions.resize(2 * (n + 2));
	const auto setDirection = [&](std::size_t i, double sensorAngle) {
		const double world = sensor.yaw + m_dir * sensorAngle;
		m_directions[2 * i] = std::cos(world);
		m_directions[2 * i + 1] = std::sin(world);
	};
	setDirection(0, polar.firstSectorAngle() - 0.5 * spacing);
	setDirection(1, polar.firstSectorAngle());
	const double turnC = std::cos(m_dir * spacing), turnS = std::sin(m_dir * spacing);
	for (std::size_t i = 2; i <= n; ++i)
	{
		const double px = m_directions[2 * i - 2], py = m_directions[2 * i - 1];
		m_directions[2 * i] = turnC * px - turnS * py;
		m_directions[2 * i + 1] = turnS * px + turnC * py;
	}
	if (polar.fullTurn())
		setDirection(n + 1, polar.firstSectorAngle());
	else
		setDirection(n + 1, polar.sectorAngle(n - 1) + 0.5 * spacing);

	m_sectorSpans.resize(n);
	m_nearest.resize(n);
	m_reach.resize(n);
	m_freeEnd.resize(n);
	for (std::size_t s = 0; s < n; ++s)
	{
		const TImpactRanges impacts = polar.impacts(s);
		m_nearest[s] = impacts.empty() ? HUGE_VAL : impacts.front();
	}
	// Each sector's spans, and in the same pass what the box and the
	// uniform region below need of its row: the free masses most sectors
	// start with (the votes), a cloud's impacts past the polygon.
	auto& votes = m_freeMassVotes;
	votes.clear();
	for (std::size_t s = 0; s < n; ++s)
	{
		const std::size_t transformBins = polar.transformBins(s),
						  freeBins = polar.freeBins(s);
		const double freeMass = polar.freeMass(s);
		const double reach =
			transformBins == 0 ? 0.0 : (static_cast<double>(transformBins) + 0.5) * bin;
		const double freeEnd = (static_cast<double>(freeBins) - 0.5) * bin;
		const double nearest = m_nearest[s];
		const double margin =
			marginAlongBeam(m_nearest, polar.fullTurn(), spacing, polar.freeMargin(), s);
		const double limit = nearest < static_cast<double>(polar.binCount()) * bin
			? std::max(0.0, nearest - std::max(0.5 * bin, margin))
			: HUGE_VAL;
		m_sectorSpans[s] = {
			reach * reach, freeBins == 0 ? -1.0 : freeEnd * freeEnd, freeMass, limit};
		// The square roots of the squares above, exactly (in base 2 the root
		// of a rounded square is the number itself).
		m_reach[s] = reach;
		m_freeEnd[s] = freeBins == 0 ? 0.0 : freeEnd;

		if (freeBins > 0)
		{
			const auto it = std::find_if(votes.begin(), votes.end(), [freeMass](const auto& v) {
				return v.first == freeMass;
			});
			if (it == votes.end())
				votes.emplace_back(freeMass, 1);
			else
				++it->second;
		}
		// A cloud's farther impacts lie beyond the polygon; the grid must
		// grow to hold them all the same (the box holds the polygon too,
		// which outline() adds below).
		if (const std::size_t informed = polar.informedBins(s); informed > transformBins)
		{
			const double r = (static_cast<double>(informed) + 0.5) * bin;
			const auto [c, sn] = sectorDirection(s);
			m_box.add(sensor.x + r * c, sensor.y + r * sn);
		}
	}
	// The uniform region: the free mass most sectors start with (none when
	// no sector starts free). Between two sectors that both start with mass
	// w, the mix is w itself short of both free runs' ends and of both free
	// limits (past the nearer limit the mixed path cuts the free evidence):
	// mixAt()'s own bounds, worked out once per sector (each bounds the two
	// gaps beside it). A hair less, so that a corner of the outline, which
	// lies on the arc, holds no cell that mixAt() finds past the bound.
	const auto best = std::max_element(
		votes.begin(), votes.end(),
		[](const auto& a, const auto& b) { return a.second < b.second; });
	const bool uniform = best != votes.end() && best->first > 0.0;
	const double w = uniform ? best->first : 0.0;
	if (uniform)
	{
		m_uniformMass = Mass::simpleFree(w);
		m_uniformReach.resize(n);
		for (std::size_t s = 0; s < n; ++s)
		{
			const SectorSpan& span = m_sectorSpans[s];
			m_uniformReach[s] = span.freeEnd2 > 0.0 && polar.freeMass(s) == w
				? (1.0 - 1e-9) * std::min(m_freeEnd[s], span.freeLimit)
				: 0.0;
		}
	}
	// A sector without evidence holds nothing at every range; one with a
	// free run, its free mass up to the run's end.
	const auto constantTo2 = [](const SectorSpan& span) {
		return span.reach2 <= 0.0 ? HUGE_VAL : std::max(span.freeEnd2, 0.0);
	};
	const auto constantFree = [](const SectorSpan& span) {
		return span.reach2 <= 0.0 ? 0.0 : span.freeMass;
	};
	// Each gap's mix, and the radii of the two outlines over it, in one walk.
	// Between a sector whose impact is near and one that reaches far (a
	// pole, a car's edge, a tree before an open street), a gap holds nothing
	// from the nearer one's free limit to the farther one's impacts: the
	// area of those bands is added up as they are found.
	m_gapMixes.assign(n + 1, GapMix{0.0, 0.0, 0.0, VacuousBand{}, false, 0.0, 0.0});
	m_informedRadii.resize(n + 1, TGapRadius(0.0));
	m_uniformRadii.resize(n + 1, TGapRadius(0.0));
	forEachGap(polar, [&](std::size_t lo, std::size_t hi, std::size_t i, double width) {
		GapMix& gap = m_gapMixes[i];
		gap.vacuous = vacuousBand(lo, hi);
		gap.nearestOnly = nearestOnly(lo, hi);
		// Beside a sector without evidence, the band lies on the other half.
		m_vacuousArea += (gap.nearestOnly ? 0.25 : 0.5) * width *
			(gap.vacuous.to2 - gap.vacuous.from2);
		// Between two sector centres the mix reaches as far as the longer
		// sector; before the first and after the last centre, and on the
		// half of a gap beside a sector without evidence, the sector alone
		// (the silent half as far as the bridge, which stops short of the
		// other's reach). In the uniform region the silent half holds,
		// within the bridge, what the other does (the hair less as for every
		// sector's reach above).
		const double bridge = bridgeRadius(lo, hi);
		if (!gap.nearestOnly)
		{
			m_informedRadii[i] = TGapRadius(std::max(m_reach[lo], m_reach[hi]));
			if (uniform)
				m_uniformRadii[i] =
					TGapRadius(std::min(m_uniformReach[lo], m_uniformReach[hi]));
		}
		else
		{
			m_informedRadii[i] =
				TGapRadius(std::max(m_reach[lo], bridge), std::max(m_reach[hi], bridge));
			if (uniform)
			{
				const bool held = std::max(m_uniformReach[lo], m_uniformReach[hi]) > 0.0;
				const double bridged = held ? (1.0 - 1e-9) * bridge : 0.0;
				m_uniformRadii[i] = TGapRadius(
					std::max(m_uniformReach[lo], bridged), std::max(m_uniformReach[hi], bridged));
			}
		}
		if (lo == hi) return;  // a half gap: the sector alone, no mix
		const SectorSpan &a = m_sectorSpans[lo], &b = m_sectorSpans[hi];
		const double limit = std::min(a.freeLimit, b.freeLimit);
		gap.simpleEnd2 = std::min({constantTo2(a), constantTo2(b), limit * limit});
		gap.loFree = constantFree(a), gap.hiFree = constantFree(b);
		gap.bridge2 = bridge * bridge;
		gap.bridgeWeight = a.reach2 <= 0.0 ? 1.0 : 0.0;
	});
	// A full turn's gap from the last centre to the first, reached from
	// either end of the position range.
	if (polar.fullTurn()) m_gapMixes[0] = m_gapMixes[n];

	const auto radiusFrom = [](const std::vector<TGapRadius>& radii) {
		return [&radii](std::size_t, std::size_t, std::size_t i) { return radii[i]; };
	};
	outline(
		m_polygon, &m_box, polar, sensor, m_directions, true, radiusFrom(m_informedRadii));
	if (uniform)
		outline(
			m_uniformPolygon, nullptr, polar, sensor, m_directions, false,
			radiusFrom(m_uniformRadii));
}

double CPolarToCartesian::bridgeRadius(std::size_t lo, std::size_t hi) const
{
	if (!nearestOnly(lo, hi)) return 0.0;
	const std::size_t other = m_sectorSpans[lo].reach2 > 0.0 ? lo : hi;
	const SectorSpan& span = m_sectorSpans[other];
	if (!(span.freeEnd2 > 0.0)) return 0.0;
	return std::min({m_polar->binSize() * m_invSpacing, m_freeEnd[other], span.freeLimit});
}

CPolarToCartesian::VacuousBand CPolarToCartesian::vacuousBand(
	std::size_t lo, std::size_t hi) const
{
	// mixAt() finds a cell vacuous past the nearer free limit where each
	// sector is within its free run or past its reach: the gap's ranges from
	// that limit on, less each sector's zone [free run's end, reach). The
	// longest piece is the band.
	const SectorSpan &a = m_sectorSpans[lo], &b = m_sectorSpans[hi];
	const double limit = std::min(a.freeLimit, b.freeLimit);
	if (!(limit < HUGE_VAL)) return {};
	const double end2 = std::max(a.reach2, b.reach2);
	std::pair<double, double> zones[2] = {
		{std::max(a.freeEnd2, 0.0), a.reach2}, {std::max(b.freeEnd2, 0.0), b.reach2}};
	if (zones[1].first < zones[0].first) std::swap(zones[0], zones[1]);
	VacuousBand best;
	const auto consider = [&](double from2, double to2) {
		if (to2 - from2 > best.to2 - best.from2) best = {from2, to2};
	};
	double at = limit * limit;
	for (const auto& [from2, to2] : zones)
	{
		if (!(from2 < to2)) continue;
		if (from2 > at) consider(at, std::min(from2, end2));
		at = std::max(at, to2);
	}
	if (at < end2) consider(at, end2);
	return best;
}

bool CPolarToCartesian::crossedWithoutFreeEvidence(double x, double y) const
{
	if (!m_polar || m_box.empty()) return false;
	// Outside the informed region's box no beam passes: most of a spinning
	// sensor's past arrivals, found without the polar conversion.
	if (!(x >= m_box.xMin && x <= m_box.xMax && y >= m_box.yMin && y <= m_box.yMax))
		return false;
	const double dx = x - m_sensor.x, dy = y - m_sensor.y;
	const double angle = angleFrom(dx, dy), range2 = dx * dx + dy * dy;
	if (angle >= m_span) return false;
	// Both sectors around the point, as the bilinear mix takes them: a beam
	// that passes beside a thing standing in part of the cell is not a
	// crossing of the cell, but one that stopped well short of it, at
	// something else, says nothing of the cell either way.
	const double position = angle * m_invSpacing - 0.5;
	const auto ns =
		detail::neighbours(position, m_polar->sectorCount(), m_polar->fullTurn());
	// Beside a sector without evidence, the nearer sector alone.
	const std::size_t sectors[2] = {ns.lo, ns.hi};
	const GapMix& gap = m_gapMixes[static_cast<std::size_t>(position + 1.0)];
	// Within the bridge, the sector with evidence (as the mix takes it).
	const std::size_t nearer = range2 < gap.bridge2 ? static_cast<std::size_t>(gap.bridgeWeight)
												 : (ns.wHi >= 0.5 ? 1 : 0);
	const std::size_t first = gap.nearestOnly ? nearer : 0;
	const std::size_t end = gap.nearestOnly ? first + 1 : 2;
	const double range = std::sqrt(range2), bin = m_polar->binSize();
	bool crossed = false, withheld = false;
	for (std::size_t k = first; k < end; ++k)
	{
		const std::size_t s = sectors[k];
		const TImpactRanges impacts = m_polar->impacts(s);
		if (impacts.empty()) return false;
		// A bin short of the impact the beam has crossed the point: a thing
		// whose face stood there has moved back by a cell (the cell holding
		// the impact is the one seen occupied).
		const double nearest = impacts.front();
		if (range < nearest - bin)
			crossed = true;
		else if (!(nearest < range - std::max(kOccluderGap, bin)))
			return false;
		withheld = withheld || range >= m_sectorSpans[s].freeLimit;
	}
	return crossed && withheld;
}

CPolarToCartesian::TRows CPolarToCartesian::prepareRows(const GridGeometry& grid)
{
	m_rows = TRows();
	m_skipsVacuous = false;
	if (!m_polar || m_box.empty()) return m_rows;
	const double res = grid.resolution;
	const int first = detail::clampToInt(
		std::ceil((m_box.yMin - grid.yMin) / res - 0.5), 0, grid.sizeY);
	const int last = detail::clampToInt(
		std::floor((m_box.yMax - grid.yMin) / res - 0.5), -1, grid.sizeY - 1);
	if (first > last) return m_rows;
	m_spans.fill(m_polygon, grid, first, last);
	m_uniformSpans.fill(m_uniformPolygon, grid, first, last);
	const double worthArea = kMinVacuousCells * res * res;
	m_skipsVacuous =
		m_polar->sectorSpacing() > 4 * kCentreLineSlack && m_vacuousArea >= worthArea;
	if (m_skipsVacuous)
	{
		// The bands as the region inside their far ends (an outline that
		// stays inside the arcs) and outside their near ends (one that holds
		// them): only cells surely within a band are left out. A gap without
		// a band takes one radius in both, its free limit (or its reach): the
		// outlines' corners then stay near the bands' near ends, instead of
		// running to the sensor and crossing every row near it.
		const auto bandEnd = [this](bool far) {
			return [this, far](std::size_t lo, std::size_t hi, std::size_t i) {
				// setup() found each gap's band for its mix.
				const VacuousBand& band = m_gapMixes[i].vacuous;
				if (band.to2 > band.from2) return std::sqrt(far ? band.to2 : band.from2);
				const SectorSpan &a = m_sectorSpans[lo], &b = m_sectorSpans[hi];
				const double limit = std::min(a.freeLimit, b.freeLimit);
				return limit < HUGE_VAL ? limit : std::max(m_reach[lo], m_reach[hi]);
			};
		};
		// A cell within the arctangent's slack of a centre line may be mixed
		// as either gap's: the outlines' steps there are turned off the line
		// (as a split is), so that beside it only the ranges both gaps' bands
		// hold are left out (the farther near end to the nearer far end).
		outline<true>(
			m_vacuousOuter, nullptr, *m_polar, m_sensor, m_directions, false, bandEnd(true),
			&m_bandRadii);
		outline<true>(
			m_vacuousInner, nullptr, *m_polar, m_sensor, m_directions, true, bandEnd(false),
			&m_bandRadii);
		m_vacuousOuterSpans.fill(m_vacuousOuter, grid, first, last);
		m_vacuousInnerSpans.fill(m_vacuousInner, grid, first, last);
		m_vacuousSpans.assignDifference(m_vacuousOuterSpans, m_vacuousInnerSpans);
	}
	m_rows = {first, last};
	return m_rows;
}

}  // namespace mrpt_evidential
