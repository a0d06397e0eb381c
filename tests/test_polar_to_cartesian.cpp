/* The polar-to-Cartesian transform against a brute-force reference that looks
 * at every cell of the grid with std::atan2. */
#include <mrpt/obs/CObservation2DRangeScan.h>
#include "insert/PolarToCartesian.h"

#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt::obs::CObservation2DRangeScan;

namespace
{
/** The transform of a scan of `beams` beams over `aperture` (rad) whose
 * ranges `rangeAt` gives by angle, seen by the precise model (5 cm bins,
 * 20 m, free margin `margin`) from the origin facing +x; `polar` holds the
 * rows the transform reads. */
template <typename F>
void setUpPreciseScan(
	CPolarSourceGrid& polar, CPolarToCartesian& transform, std::size_t beams, double aperture,
	double margin, F&& rangeAt)
{
	TSourceGridOptions options;
	options.sensorModel.model = SensorModel::MultiEcho;
	options.binSize = 0.05;
	options.maxRange = 20.0;
	options.freeMargin = margin;
	polar.build(
		test::scanByAngle(beams, test::ScanSetup().aperture(aperture), std::forward<F>(rangeAt)),
		options);
	transform.setup(polar, PlanarSensorPose{0, 0, 0, false});
}

/** The free mass of each cell that `transform` informs in `grid`. */
std::map<std::size_t, double> freeMassOfInformedCells(
	CPolarToCartesian& transform, const GridGeometry& grid)
{
	std::map<std::size_t, double> freeMass;
	transform.forEachInformedCell(
		grid, [&](std::size_t idx, const Mass& m) { freeMass[idx] = m.free; },
		[&](std::size_t first, std::size_t count) {
			for (std::size_t idx = first; idx < first + count; ++idx)
				freeMass[idx] = transform.uniformMass().free;
		});
	return freeMass;
}

/** The free margin along sector s's beam, from the definition: freeMargin
 * across the surface its nearest impact lies on, the surface's slope taken
 * from the nearest impacts two sectors away on the flatter side, the
 * stretch 1 / cos(incidence) at most 3. */
double referenceMargin(const CPolarSourceGrid& polar, std::size_t s)
{
	const long n = static_cast<long>(polar.sectorCount());
	const auto nearest = [&](long t) {
		if (polar.fullTurn()) t = ((t % n) + n) % n;
		// A beam without return (an impact at infinity) hit no surface.
		if (t < 0 || t >= n || polar.impacts(static_cast<std::size_t>(t)).empty() ||
			!std::isfinite(polar.impacts(static_cast<std::size_t>(t)).front()))
			return std::optional<double>();
		return std::optional<double>(polar.impacts(static_cast<std::size_t>(t)).front());
	};
	const auto r = nearest(static_cast<long>(s));
	if (!r || polar.freeMargin() == 0.0) return polar.freeMargin();
	std::optional<double> flattest;
	for (const long t : {static_cast<long>(s) - 2, static_cast<long>(s) + 2})
		if (const auto other = nearest(t))
		{
			const double incidence = std::atan(std::abs(*other - *r) / (*r * 2 * polar.sectorSpacing()));
			if (!flattest || incidence < *flattest) flattest = incidence;
		}
	if (!flattest) return polar.freeMargin();
	return polar.freeMargin() * std::min(3.0, 1.0 / std::cos(*flattest));
}

/** A precise scan of beams to a ring, the one straight ahead without a
 * return, and the free mass of each cell it informs in a grid of 0.025 m. */
struct TSilentRing
{
	CPolarSourceGrid polar;
	CPolarToCartesian transform;
	EvidentialGridStorage grid;
	std::map<std::size_t, double> freeMass;
};
void setUpSilentRing(
	TSilentRing& out, std::size_t beams, double aperture, double ring, double xMax,
	double yHalf)
{
	setUpPreciseScan(out.polar, out.transform, beams, aperture, 0.0, [ring](double a) {
		return std::abs(a) < 1e-6 ? 0.0 : ring;
	});
	ASSERT_FALSE(out.polar.sectorObserved(beams / 2));
	out.grid.reset(-1, xMax, -yHalf, yHalf, 0.025, 1'000'000);
	out.freeMass = freeMassOfInformedCells(out.transform, out.grid.geometry());
	ASSERT_GT(out.transform.uniformMass().free, 0.5);
}

/** Free evidence stops at a sector's nearest impact, less half a bin or the
 * sector's free margin. */
double freeLimitOf(const CPolarSourceGrid& polar, std::size_t s)
{
	const auto& impacts = polar.impacts(s);
	if (impacts.empty() || !(impacts.front() < polar.binCount() * polar.binSize()))
		return HUGE_VAL;
	return std::max(0.0, impacts.front() - std::max(0.5 * polar.binSize(), referenceMargin(polar, s)));
}

/** The bilinear mix at a point of the sensor's frame, straight from the
 * definition; vacuous outside the field of view and beyond reach. */
Mass referenceMix(
	const CPolarSourceGrid& polar, double lx, double ly, bool* onCentreLine = nullptr,
	bool* onMiddle = nullptr)
{
	const std::size_t n = polar.sectorCount(), nBins = polar.binCount();
	const double spacing = polar.sectorSpacing();
	const double span = static_cast<double>(n) * spacing;
	const bool fullTurn = polar.fullTurn();
	double angle = std::atan2(ly, lx) - (polar.firstSectorAngle() - 0.5 * spacing);
	angle = std::fmod(std::fmod(angle, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
	if (angle >= span) return Mass::vacuous();
	const double sp = angle / spacing - 0.5;
	std::size_t s0, s1;
	double ws;
	if (sp < 0)
		fullTurn ? (s0 = n - 1, s1 = 0, ws = sp + 1) : (s0 = s1 = 0, ws = 0);
	else if (std::floor(sp) + 1 >= n)
		fullTurn ? (s0 = n - 1, s1 = 0, ws = sp - std::floor(sp))
				 : (s0 = s1 = n - 1, ws = 0);
	else
		s0 = static_cast<std::size_t>(sp), s1 = s0 + 1, ws = sp - std::floor(sp);
	// A sector without evidence is mixed with nothing: each sector holds its
	// own half of the gap whole.
	const bool nearestOnly =
		s0 != s1 && (polar.informedBins(s0) == 0) != (polar.informedBins(s1) == 0);
	const double wsBefore = ws;
	if (nearestOnly) ws = ws < 0.5 ? 0.0 : 1.0;
	const double r = std::hypot(lx, ly);
	// Where the silent span is narrower than a cell (a bin), the informed
	// sector holds the whole gap, as far as its free run holds its free mass.
	if (nearestOnly)
	{
		const std::size_t other = polar.informedBins(s0) > 0 ? s0 : s1;
		const double freeEnd = (static_cast<double>(polar.freeBins(other)) - 0.5) * polar.binSize();
		const double bridge = std::min({polar.binSize() / spacing, freeEnd, freeLimitOf(polar, other)});
		if (polar.freeBins(other) > 0 && r < bridge) ws = other == s0 ? 0.0 : 1.0;
	}
	const double reach = (static_cast<double>(std::max(
							  polar.informedBins(s0), polar.informedBins(s1))) + 0.5) *
		polar.binSize();
	if (r >= reach) return Mass::vacuous();
	const double bp = r / polar.binSize() - 0.5;
	std::size_t b0, b1;
	double wb;
	if (bp < 0)
		b0 = b1 = 0, wb = 0;
	else if (std::floor(bp) + 1 >= nBins)
		b0 = b1 = nBins - 1, wb = 0;
	else
		b0 = static_cast<std::size_t>(bp), b1 = b0 + 1, wb = bp - std::floor(bp);
	Mass m{0, 0, 0, 0};
	bool touchesImpact = false;
	for (const auto& [s, b, w] :
		 {std::tuple{s0, b0, (1 - ws) * (1 - wb)}, std::tuple{s0, b1, (1 - ws) * wb},
		  std::tuple{s1, b0, ws * (1 - wb)}, std::tuple{s1, b1, ws * wb}})
	{
		const Mass p = polar.at(s, b);
		m.conflict += w * p.conflict;
		m.free += w * p.free;
		m.occupied += w * p.occupied;
		m.unknown += w * p.unknown;
		touchesImpact |= p.occupied > 0;
	}
	if (r >= std::min(freeLimitOf(polar, s0), freeLimitOf(polar, s1))) touchesImpact = true;
	// Within a hair of a centre line (the transform's angles are within
	// 2e-6 rad) the neighbour of almost no weight may be either side's.
	if (onCentreLine) *onCentreLine = std::min(wsBefore, 1 - wsBefore) < 1e-3;
	// A cell within a hair of the middle of a gap beside a sector without
	// evidence may take either sector.
	if (onMiddle) *onMiddle = nearestOnly && std::abs(wsBefore - 0.5) < 1e-3;
	if (touchesImpact) m.unknown += m.free, m.free = 0;
	return m;
}

CObservation2DRangeScan randomScan(std::mt19937& rng, std::size_t beams, double aperture)
{
	std::uniform_real_distribution<double> u(0.0, 1.0);
	const bool rightToLeft = u(rng) < 0.8;
	std::vector<float> ranges;
	std::vector<bool> valid;
	double r = 1 + 4 * u(rng);
	for (std::size_t i = 0; i < beams; ++i)
	{
		// Walls with jumps, and now and then no return.
		if (u(rng) < 0.1) r = 0.5 + 7 * u(rng);
		r = std::max(0.2, r + 0.05 * (u(rng) - 0.5));
		ranges.push_back(static_cast<float>(r));
		valid.push_back(u(rng) > 0.05);
	}
	return test::scanFromRanges(
		ranges, valid, test::ScanSetup().aperture(aperture).rightToLeft(rightToLeft));
}

/** What a transform visited: cells in all, those of the uniform path, and
 * those of the mixed path whose mix is the uniform mass all the same (off
 * the centre lines). */
struct TVisitCounts
{
	std::size_t visited = 0, uniform = 0, mixedOfUniformMass = 0;
};

/** Visits the cells of a grid of 16 x 16 m at 0.05 m with `transform` (set up
 * for `polar` at `sensor`) and checks each cell against referenceMix(): every
 * cell with evidence visited once, with its mix, and no other. */
void expectMatchesReference(
	const CPolarSourceGrid& polar, const PlanarSensorPose& sensor,
	CPolarToCartesian& transform, TVisitCounts& counts)
{
	EvidentialGridStorage grid;
	grid.reset(-8, 8, -8, 8, 0.05, 1'000'000);
	const GridGeometry& g = grid.geometry();
	std::map<std::size_t, Mass> seen;
	std::vector<bool> viaUniform(g.cellCount(), false);
	std::size_t& uniform = counts.uniform;
	transform.forEachInformedCell(
		g,
		[&](std::size_t idx, const Mass& m) {
			ASSERT_TRUE(seen.emplace(idx, m).second) << "visited twice";
		},
		[&](std::size_t first, std::size_t count) {
			ASSERT_GT(count, 0u);
			for (std::size_t idx = first; idx < first + count; ++idx)
			{
				ASSERT_TRUE(seen.emplace(idx, transform.uniformMass()).second)
					<< "visited twice";
				viaUniform[idx] = true;
				++uniform;
			}
		});

	std::size_t informed = 0;
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (int cx = 0; cx < g.sizeX; ++cx)
		{
			const double dx = g.cellCenterX(cx) - sensor.x;
			const double dy = g.cellCenterY(cy) - sensor.y;
			const double lx = std::cos(sensor.yaw) * dx + std::sin(sensor.yaw) * dy;
			double ly = -std::sin(sensor.yaw) * dx + std::cos(sensor.yaw) * dy;
			if (sensor.mirrored) ly = -ly;
			bool onCentreLine = false, onMiddle = false;
			const Mass expected = referenceMix(polar, lx, ly, &onCentreLine, &onMiddle);
			const auto it = seen.find(g.index(cx, cy));
			if (onMiddle)
			{
				informed += it != seen.end();
				continue;
			}
			// fastAtan2 is within 2e-6 rad: cells on an edge of the
			// field of view or of reach may fall either way, with a
			// mix too small to matter.
			// On a sector's centre line, the free limit of the
			// neighbour across it may count or not: only the masses
			// other than free are checked there.
			if (onCentreLine)
			{
				if (it != seen.end())
				{
					++informed;
					ASSERT_NEAR(it->second.occupied, expected.occupied, 1e-3);
				}
				continue;
			}
			if (it == seen.end())
			{
				ASSERT_GT(expected.unknown, 1 - 1e-3)
					<< "missed cell (" << cx << ", " << cy << ") " << expected;
				continue;
			}
			++informed;
			if (!viaUniform[it->first] && test::massNear(expected, transform.uniformMass(), 1e-9))
				++counts.mixedOfUniformMass;
			ASSERT_TRUE(test::massNear(it->second, expected, 1e-3))
				<< "cell (" << cx << ", " << cy << ") uniform "
				<< (it->second == transform.uniformMass());
		}
	EXPECT_EQ(informed, seen.size());
	counts.visited = seen.size();
}
}  // namespace

TEST(PolarToCartesian, VisitsExactlyTheInformedCellsWithTheirMix)
{
	std::mt19937 rng(42);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	CPolarToCartesian transform;
	CPolarSourceGrid polar;
	const struct
	{
		std::size_t beams;
		double aperture, sectorWidth;
		SensorModel model;
	} cases[] = {
		{181, M_PI, 0, SensorModel::ReinforcedMultiEcho},
		{361, M_PI, 2 * M_PI / 180, SensorModel::ReinforcedMultiEcho},
		{541, 1.5 * M_PI, 0, SensorModel::MultiEcho},
		{400, 2 * M_PI, 0, SensorModel::ImpreciseMultiEcho},
		{7, 0.5, 0, SensorModel::ReinforcedMultiEcho},
		{1, 0.3, 0, SensorModel::ReinforcedMultiEcho},
	};
	for (const auto& c : cases)
		for (int trial = 0; trial < 4; ++trial)
		{
			TSourceGridOptions options;
			options.sensorModel.model = c.model;
			options.sensorModel.imprecision = 0.1;
			options.sectorWidth = c.sectorWidth;
			options.binSize = 0.05;
			options.maxRange = 6.0;
			options.invalidRangesAsFree = trial % 2 == 1;
			options.freeMargin = trial >= 2 ? 0.15 : 0.0;
			polar.build(randomScan(rng, c.beams, c.aperture), options);
			const PlanarSensorPose sensor{
				-1 + 2 * u(rng), -1 + 2 * u(rng), -M_PI + 2 * M_PI * u(rng),
				trial == 3};
			transform.setup(polar, sensor);
			SCOPED_TRACE(testing::Message() << c.beams << " beams, trial " << trial);
			TVisitCounts counts;
			expectMatchesReference(polar, sensor, transform, counts);
			// One beam per sector: most sectors share the free mass muF, so
			// the bulk of the cells take the uniform path.
			if (c.beams > 100 && c.sectorWidth == 0)
			{
				EXPECT_GT(counts.uniform, counts.visited / 3) << "the uniform region is used";
			}
			// The uniform region reaches the free limits: few cells of the
			// uniform mass are left to the mixed path (with a region that
			// stopped a margin's bins short of the free runs' ends, 4 to 10 %
			// of the uniform cells with a free margin).
			EXPECT_LE(counts.mixedOfUniformMass, counts.uniform / 50)
				<< counts.uniform << " cells on the uniform path";
		}
}

TEST(PolarToCartesian, AnnouncesEachRowsCellsRowsBeforeItVisitsThem)
{
	std::mt19937 rng(7);
	CPolarSourceGrid polar;
	TSourceGridOptions options;
	options.binSize = 0.05;
	options.maxRange = 6.0;
	polar.build(randomScan(rng, 361, M_PI), options);
	CPolarToCartesian transform;
	transform.setup(polar, PlanarSensorPose{0.3, -0.2, 0.4, false});
	EvidentialGridStorage grid;
	grid.reset(-8, 8, -8, 8, 0.05, 1'000'000);
	const GridGeometry& g = grid.geometry();
	const CPolarToCartesian::TRows rows = transform.prepareRows(g);
	ASSERT_GT(rows.last - rows.first, 2 * CPolarToCartesian::kRowsAhead);
	// Two bands, as two threads would take them: a band announces only its
	// own rows.
	const int split = (rows.first + rows.last) / 2;
	for (const auto& band : {std::pair{rows.first, split}, {split + 1, rows.last}})
	{
		const int first = band.first, last = band.second;
		std::vector<bool> announced(g.cellCount(), false);
		std::size_t visited = 0;
		const auto visit = [&](std::size_t idx) {
			const int row = g.rowOf(idx);
			// A band's first rows come before anything is announced.
			if (row < first + CPolarToCartesian::kRowsAhead) return;
			EXPECT_TRUE(announced[idx]) << "row " << row << " visited unannounced";
			++visited;
		};
		transform.visitRows(
			g, first, last, [&](std::size_t idx, const Mass&) { visit(idx); },
			[&](std::size_t from, std::size_t count) {
				for (std::size_t idx = from; idx < from + count; ++idx) visit(idx);
			},
			[&](std::size_t from, std::size_t count) {
				ASSERT_GT(count, 0u);
				const int row = g.rowOf(from);
				EXPECT_EQ(row, g.rowOf(from + count - 1)) << "a span within one row";
				EXPECT_GE(row, first + CPolarToCartesian::kRowsAhead);
				EXPECT_LE(row, last) << "only the band's own rows";
				for (std::size_t idx = from; idx < from + count; ++idx) announced[idx] = true;
			});
		EXPECT_GT(visited, 1000u);
	}
}

TEST(PolarToCartesian, LeavesOutOnlyVacuousCellsBetweenNearAndFarSectors)
{
	// Poles close by before an open street, one beam in two: between each
	// pole's sector and the far one beside it lies a band the transform
	// leaves out without looking at its cells. The cells it does visit, and
	// those it leaves out, must be what the definition gives.
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	CPolarToCartesian transform;
	CPolarSourceGrid polar;
	for (int trial = 0; trial < 4; ++trial)
	{
		std::vector<float> ranges;
		std::vector<bool> valid;
		for (std::size_t i = 0; i < 720; ++i)
		{
			ranges.push_back(static_cast<float>(i % 2 == 0 ? 0.8 + u(rng) : 4.5 + u(rng)));
			valid.push_back(u(rng) > 0.03);
		}
		TSourceGridOptions options;
		options.sensorModel.model =
			trial % 2 == 0 ? SensorModel::ReinforcedMultiEcho : SensorModel::ImpreciseMultiEcho;
		options.sensorModel.imprecision = 0.1;
		options.binSize = 0.05;
		options.maxRange = 6.0;
		options.freeMargin = trial >= 2 ? 0.1 : 0.0;
		polar.build(
			test::scanFromRanges(ranges, valid, test::ScanSetup().aperture(2 * M_PI)),
			options);
		const PlanarSensorPose sensor{
			-1 + 2 * u(rng), -1 + 2 * u(rng), -M_PI + 2 * M_PI * u(rng), trial == 3};
		transform.setup(polar, sensor);
		SCOPED_TRACE(testing::Message() << "trial " << trial);
		TVisitCounts counts;
		expectMatchesReference(polar, sensor, transform, counts);
		EXPECT_TRUE(transform.leavesOutVacuousBands()) << "the bands are in use";
	}
}

TEST(PolarToCartesian, ABeamWithoutAReturnIsMixedWithNothing)
{
	// Beams every 5 degrees to a ring 3 m away, the one straight ahead
	// without a return: each informed sector holds its own span whole, out
	// to the middle of the gap, and the silent beam's span stays unknown. A
	// mix would have given 3.5 degrees 0.7 of the free mass and 1.5 degrees
	// 0.3 of it.
	TSilentRing ring;
	ASSERT_NO_FATAL_FAILURE(setUpSilentRing(ring, 37, M_PI, 3.0, 4.0, 4.0));
	const GridGeometry& g = ring.grid.geometry();
	auto& freeMass = ring.freeMass;
	const double free = ring.transform.uniformMass().free;
	for (const double range : {1.0, 2.0})
		for (const double side : {1.0, -1.0})
		{
			const auto cellAt = [&](double degrees) {
				const double a = side * degrees * M_PI / 180;
				return g.index(g.cellX(range * std::cos(a)), g.cellY(range * std::sin(a)));
			};
			SCOPED_TRACE(testing::Message() << range << " m, side " << side);
			EXPECT_EQ(freeMass.count(cellAt(1.5)), 0u) << "the silent beam's span";
			ASSERT_EQ(freeMass.count(cellAt(3.5)), 1u);
			EXPECT_DOUBLE_EQ(freeMass[cellAt(3.5)], free) << "the informed span, whole";
		}
	// Nor does the silent span count as crossed (the motion layer's test).
	EXPECT_FALSE(ring.transform.crossedWithoutFreeEvidence(2.0, 0.02));
}

TEST(PolarToCartesian, ASilentSpanNarrowerThanACellTakesItsNeighbours)
{
	// Beams every half degree to a ring 10 m away, the one straight ahead
	// without a return. Nearer than a bin over the spacing (0.05 m / 0.5
	// degrees = 5.7 m) the silent span is narrower than a cell: its
	// neighbours' free mass covers it. Farther, it holds whole cells that no
	// beam saw, and they stay unknown.
	// Cell centres on the silent beam's line (y = 0).
	TSilentRing ring;
	ASSERT_NO_FATAL_FAILURE(setUpSilentRing(ring, 121, M_PI / 3, 10.0, 11.0, 3.0125));
	const GridGeometry& g = ring.grid.geometry();
	auto& freeMass = ring.freeMass;
	const double free = ring.transform.uniformMass().free;
	const auto cellAt = [&](double range, double degrees) {
		const double a = degrees * M_PI / 180;
		return g.index(g.cellX(range * std::cos(a)), g.cellY(range * std::sin(a)));
	};
	for (const double range : {1.0, 3.0, 5.0})
	{
		SCOPED_TRACE(testing::Message() << range << " m");
		ASSERT_EQ(freeMass.count(cellAt(range, 0.0)), 1u) << "the silent line, bridged";
		EXPECT_DOUBLE_EQ(freeMass[cellAt(range, 0.0)], free);
	}
	for (const double range : {6.5, 8.0})
	{
		SCOPED_TRACE(testing::Message() << range << " m");
		EXPECT_EQ(freeMass.count(cellAt(range, 0.0)), 0u) << "the silent line, a cell wide";
		ASSERT_EQ(freeMass.count(cellAt(range, 0.6)), 1u) << "the informed span";
		EXPECT_DOUBLE_EQ(freeMass[cellAt(range, 0.6)], free);
	}
}

TEST(PolarToCartesian, FreeMarginHoldsAcrossAWallAtAnyIncidence)
{
	// A straight wall 3 m ahead, beams every half degree: the cells within
	// the margin's depth in front of the wall get no free evidence whatever
	// the incidence up to 60 degrees (a margin along the beam would protect
	// only its cosine there), and the margin does not grow on a head-on wall.
	const double margin = 0.2;
	CPolarSourceGrid polar;
	CPolarToCartesian transform;
	setUpPreciseScan(
		polar, transform, 301, 150 * M_PI / 180, margin, [](double a) { return 3.0 / std::cos(a); });
	EvidentialGridStorage grid;
	grid.reset(-1, 4, -6, 6, 0.025, 1'000'000);
	const GridGeometry& g = grid.geometry();
	std::map<std::size_t, double> freeMass = freeMassOfInformedCells(transform, g);
	const auto freeAt = [&](double x, double y) {
		const auto it = freeMass.find(g.index(g.cellX(x), g.cellY(y)));
		return it == freeMass.end() ? 0.0 : it->second;
	};
	for (const double incidence : {0.0, 30.0, 45.0, 60.0})
	{
		const double y = 3.0 * std::tan(incidence * M_PI / 180);
		EXPECT_EQ(freeAt(3.0 - 0.75 * margin, y), 0.0) << incidence << " degrees";
	}
	EXPECT_GT(freeAt(3.0 - 1.5 * margin, 0.0), 0.5);
}

TEST(PolarToCartesian, FreeMarginHoldsWhatBeamsCrossedShortOfTheirImpact)
{
	// A wall 3 m ahead, head on, a margin of 0.2 m: between the free limit
	// and a bin short of the impact the beams crossed the point but gave it
	// no free evidence (the motion layer's test of an arrival that left);
	// before the limit the point got free evidence, and within a bin of the
	// impact it is the impact's.
	CPolarSourceGrid polar;
	CPolarToCartesian transform;
	setUpPreciseScan(polar, transform, 181, M_PI / 2, 0.2, [](double a) { return 3.0 / std::cos(a); });
	EXPECT_TRUE(transform.crossedWithoutFreeEvidence(3.0 - 0.06, 0.0));
	EXPECT_TRUE(transform.crossedWithoutFreeEvidence(3.0 - 0.15, 0.0));
	EXPECT_FALSE(transform.crossedWithoutFreeEvidence(3.0 - 0.04, 0.0));
	EXPECT_FALSE(transform.crossedWithoutFreeEvidence(3.0 - 0.3, 0.0));
	EXPECT_FALSE(transform.crossedWithoutFreeEvidence(3.0 + 0.5, 0.0));  // behind the wall
}

TEST(PolarToCartesian, BeamPastAThingCrossesThePointsInItsShadowsEdge)
{
	// A thing 1.5 m ahead on the left of the view (beams at 0 degrees and
	// more), a wall 4 m ahead on the right. Between the last beam that
	// passes the thing and the first that hits it, past the thing's range,
	// one beam crossed a point and the other stopped at the thing in front
	// of it: free evidence stops there at the nearer sector's limit, but
	// the point was crossed (where a thing that walked on had stood). Within
	// kOccluderGap of the thing's face the point may be the thing's own (a
	// side seen at a slant): not crossed.
	CPolarSourceGrid polar;
	CPolarToCartesian transform;
	setUpPreciseScan(polar, transform, 181, M_PI / 2, 0.1, [](double a) {
		return a >= -1e-9 ? 1.5 / std::cos(a) : 4.0 / std::cos(a);
	});
	const double edge = -0.25 * M_PI / 180.0;  // between the two beams
	const auto at = [&](double range) {
		return transform.crossedWithoutFreeEvidence(
			range * std::cos(edge), range * std::sin(edge));
	};
	EXPECT_TRUE(at(2.5));
	EXPECT_TRUE(at(1.5 + CPolarToCartesian::kOccluderGap + 0.06));
	EXPECT_FALSE(at(1.5 + CPolarToCartesian::kOccluderGap - 0.06)) << "the thing's own";
	EXPECT_FALSE(at(1.0)) << "free evidence from both";
	EXPECT_FALSE(at(4.0 + 0.5)) << "behind the wall";
	const double behindThing = 1.0 * M_PI / 180.0;
	EXPECT_FALSE(transform.crossedWithoutFreeEvidence(
		2.5 * std::cos(behindThing), 2.5 * std::sin(behindThing)))
		<< "no beam crossed it";
}
