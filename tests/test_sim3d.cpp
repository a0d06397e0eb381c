/* The 3-D simulator of evgrid-simulate's scene "street" (issue 12): rays
 * against the ground, the ramp and the bodies land where the geometry says,
 * the lidar keeps its ranges and its seed, the vehicle stands on the ground,
 * and the footprint truth tells obstacles, kerbs and overhangs apart. */
#include <gtest/gtest.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "CMultiLayerLidar.h"
#include "CStreetScene.h"
#include "TFootprintGrid.h"
#include "TScene3D.h"
#include "VehicleOnGround.h"

using namespace mrpt_evidential::simulate;
using mrpt::math::TPoint3D;
using mrpt::math::TVector3D;
using mrpt::poses::CPose2D;
using mrpt::poses::CPose3D;

namespace
{
constexpr double kDeg = M_PI / 180;
const double kRampSlope = std::tan(CStreetScene::kRampDegrees * kDeg);

const CStreetScene& street()
{
	static const CStreetScene s;
	return s;
}

/** The lidar's pose on the vehicle standing at `pose` on the street. */
CPose3D sensorAt(const CPose2D& pose)
{
	return vehicleOnGround(street().scene().ground, pose) +
		CStreetScene::sensorMount();
}

TLidarOptions noiseless()
{
	TLidarOptions o;
	o.rangeNoise = 0;
	return o;
}

/** The range of the return of the ray at azimuth 0 (ahead) and elevation
 * e, or -1 if that ray gave none. */
double rangeAhead(const TLidarScan& scan, double e, EPointLabel& label)
{
	const auto& xs = scan.points->getPointsBufferRef_x();
	const auto& ys = scan.points->getPointsBufferRef_y();
	const auto& zs = scan.points->getPointsBufferRef_z();
	for (std::size_t i = 0; i < xs.size(); ++i)
		if (xs[i] > 0 && std::abs(ys[i]) < 1e-4 &&
			std::abs(std::atan2(zs[i], xs[i]) - e) < 1e-5)
		{
			label = scan.labels[i];
			return std::sqrt(xs[i] * xs[i] + zs[i] * zs[i]);
		}
	return -1;
}

/** The points of a scan in the world frame. */
std::vector<TPoint3D> inWorld(const TLidarScan& scan, const CPose3D& sensor)
{
	std::vector<TPoint3D> points;
	for (std::size_t i = 0; i < scan.points->size(); ++i)
	{
		float x, y, z;
		scan.points->getPoint(i, x, y, z);
		points.push_back(sensor.composePoint(TPoint3D(x, y, z)));
	}
	return points;
}
}  // namespace

TEST(Rays, StraightDownHitsTheGroundRampBumpBeamKerbAndCar)
{
	const TScene3D& s = street().scene();
	const std::vector<TBody> bodies = s.bodiesAt(0);
	const TVector3D down(0, 0, -1);
	struct TCase
	{
		TPoint3D origin;
		double range;
		EPointLabel label;
	};
	const TCase cases[] = {
		// Flat road.
		{{-3, 0, 1.8}, 1.8, EPointLabel::Ground},
		// The ramp, 10 m up it.
		{{30, 0, 3.0}, 3.0 - 10 * kRampSlope, EPointLabel::Ground},
		// The top of the 0.08 m bump at (6, -2).
		{{6, -2, 1.8}, 1.72, EPointLabel::Ground},
		// The top of the gantry's beam, 3.2 m up.
		{{14, 0, 5.0}, 1.8, EPointLabel::Overhang},
		// The kerb's top, 0.10 m up.
		{{-3, -4.1, 1.8}, 1.7, EPointLabel::Low},
		// A parked car's roof, 1.5 m up.
		{{2, 3, 1.8}, 0.3, EPointLabel::Obstacle},
	};
	for (const TCase& c : cases)
	{
		const auto hit = castRay(s.ground, bodies, c.origin, down, 100);
		ASSERT_TRUE(hit) << c.origin;
		EXPECT_NEAR(hit->range, c.range, 2e-6) << c.origin;
		EXPECT_EQ(hit->label, c.label) << c.origin;
	}
	// Straight up from the road: sky.
	EXPECT_FALSE(castRay(s.ground, bodies, {-3, 0, 1.8}, {0, 0, 1}, 100));
	// A ray that starts under the ground hits it at once.
	const auto under = s.ground.rayHit({30, 0, 0.5}, {1, 0, 0}, 100);
	ASSERT_TRUE(under);
	EXPECT_EQ(*under, 0.0);
}

TEST(Rays, AGrazingRayMeetsTheRampWhereTheLinesCross)
{
	// Level along the road at 1 m, it meets the ramp where
	// tan(5 deg) (x - 20) = 1.
	const TGround& g = street().scene().ground;
	const auto t = g.rayHit({0, 0, 1.0}, {1, 0, 0}, 100);
	ASSERT_TRUE(t);
	EXPECT_NEAR(*t, 20 + 1 / kRampSlope, 2e-6);
	EXPECT_FALSE(g.rayHit({0, 0, 1.0}, {1, 0, 0}, 30));
}

TEST(Rays, TheMarcherAgreesWithADenseMarch)
{
	// Rays down onto the bumps, the ramp's kinks and the slope from all
	// sides, against 2 mm steps: the marcher's long steps skip no ground.
	const TGround& g = street().scene().ground;
	std::size_t hits = 0;
	for (int i = 0; i < 400; ++i)
	{
		const double azimuth = 0.7 * i, elevation = -(0.5 + (i % 40)) * kDeg;
		const double x = -5 + 0.15 * i, y = -3 + 0.013 * i;
		const TPoint3D origin(x, y, g.height(x, y) + 0.1 + (i % 7) * 0.4);
		const TVector3D dir(
			std::cos(elevation) * std::cos(azimuth),
			std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
		const auto above = [&](double t) {
			return origin.z + t * dir.z - g.height(origin.x + t * dir.x, origin.y + t * dir.y);
		};
		double dense = -1;
		for (double t = 0; t <= 60; t += 0.002)
			if (above(t) <= 0)
			{
				dense = t;
				break;
			}
		const auto t = g.rayHit(origin, dir, 60);
		ASSERT_EQ(t.has_value(), dense >= 0) << i;
		if (!t) continue;
		++hits;
		EXPECT_LE(*t, dense + 1e-6) << i;
		EXPECT_GT(*t, dense - 0.002 - 1e-6) << i;
		EXPECT_NEAR(above(*t), 0, 1e-6) << i;
	}
	EXPECT_GT(hits, 300u);
}

TEST(Lidar, LayersHitTheHouseFrontsAndTheGroundWhereTheGeometrySays)
{
	// At x = -3, looking north across the road: nothing between the lidar
	// (1.8 m up) and the house front at y = 8, 8 m away.
	CMultiLayerLidar lidar(noiseless(), 1);
	ASSERT_EQ(lidar.options().elevations.size(), 16u);
	EXPECT_NEAR(lidar.options().elevations[0], -15 * kDeg, 1e-12);
	EXPECT_NEAR(lidar.options().elevations[8], 1 * kDeg, 1e-12);
	EXPECT_EQ(lidar.options().raysPerTurn(), 1800u);

	const CPose3D sensor = sensorAt(CPose2D(-3, 0, M_PI / 2));
	EXPECT_NEAR(sensor.z(), 1.8, 1e-12);
	const TLidarScan scan = lidar.scan(street().scene(), sensor, 0);
	EPointLabel label;
	for (const double e : {1.0, -1.0, 3.0})
	{
		EXPECT_NEAR(
			rangeAhead(scan, e * kDeg, label), CStreetScene::kHouseY / std::cos(e * kDeg),
			1e-4)
			<< e;
		EXPECT_EQ(label, EPointLabel::Obstacle) << e;
	}
	// The lowest layer clears the kerb and meets the pavement 6.72 m out.
	EXPECT_NEAR(rangeAhead(scan, -15 * kDeg, label), 1.8 / std::sin(15 * kDeg), 1e-4);
	EXPECT_EQ(label, EPointLabel::Ground);
	// A VLP-16 turn in the street: most rays return, the sky's do not.
	EXPECT_GT(scan.points->size(), 20000u);
	EXPECT_LT(scan.points->size(), 28800u);
	EXPECT_EQ(scan.labels.size(), scan.points->size());
}

TEST(Lidar, OverhangPointsAreAboveTheVehicle)
{
	// 5 m before the gantry: its beam is seen by the upper layers.
	CMultiLayerLidar lidar(TLidarOptions(), 3);
	const double t = 3.4;
	const CPose3D sensor = sensorAt(CStreetScene::vehiclePoseAt(t));
	const TLidarScan scan = lidar.scan(street().scene(), sensor, t);
	const std::vector<TPoint3D> world = inWorld(scan, sensor);
	const TGround& g = street().scene().ground;
	std::size_t overhang = 0;
	for (std::size_t i = 0; i < world.size(); ++i)
	{
		const double above = world[i].z - g.height(world[i].x, world[i].y);
		if (scan.labels[i] == EPointLabel::Overhang)
		{
			++overhang;
			EXPECT_GT(above, 2.5) << world[i];
			EXPECT_GT(world[i].x, 13.5 - 0.1) << world[i];
		}
		if (scan.labels[i] == EPointLabel::Ground)
		{
			EXPECT_NEAR(above, 0, 0.1) << world[i];
		}
	}
	EXPECT_GT(overhang, 100u);
}

TEST(Lidar, RampPointsLieOnItsPlaneAndTheVehiclePitchesWithIt)
{
	// At 12.5 s the vehicle heads due east (its weave's crest) with all its
	// wheels on the ramp.
	const double t = 12.5;
	const CPose2D pose = CStreetScene::vehiclePoseAt(t);
	ASSERT_NEAR(pose.phi(), 0, 1e-12);
	ASSERT_GT(pose.x() - 1.35, CStreetScene::kRampStartX);
	const CPose3D vehicle = vehicleOnGround(street().scene().ground, pose);
	// MRPT's pitch is positive nose down.
	EXPECT_NEAR(vehicle.pitch(), -CStreetScene::kRampDegrees * kDeg, 1e-12);
	EXPECT_NEAR(vehicle.roll(), 0, 1e-12);
	EXPECT_NEAR(vehicle.z(), kRampSlope * (pose.x() - 20), 1e-12);

	CMultiLayerLidar lidar(noiseless(), 1);
	const CPose3D sensor = vehicle + CStreetScene::sensorMount();
	const TLidarScan scan = lidar.scan(street().scene(), sensor, t);
	const std::vector<TPoint3D> world = inWorld(scan, sensor);
	std::size_t onRamp = 0;
	for (std::size_t i = 0; i < world.size(); ++i)
	{
		const TPoint3D& p = world[i];
		if (scan.labels[i] != EPointLabel::Ground || p.x < 20.5 || p.x > 39.5)
			continue;
		++onRamp;
		EXPECT_NEAR(p.z, kRampSlope * (p.x - 20), 1e-4) << p;
	}
	EXPECT_GT(onRamp, 3000u);
}

TEST(Lidar, NoPointNearerThanTheMinimumRange)
{
	// 0.3 m from a house front, facing it: the rays that meet it within
	// 0.5 m give nothing, whatever the noise.
	CMultiLayerLidar lidar(TLidarOptions(), 5);
	const CPose3D sensor(-3, CStreetScene::kHouseY - 0.3, 1.8, M_PI / 2, 0, 0);
	const TLidarScan scan = lidar.scan(street().scene(), sensor, 0);
	std::size_t behind = 0;
	for (std::size_t i = 0; i < scan.points->size(); ++i)
	{
		float x, y, z;
		scan.points->getPoint(i, x, y, z);
		const double range = std::sqrt(x * x + y * y + z * z);
		EXPECT_GE(range, 0.5 - 1e-5);
		// Rays within 41 degrees of the wall's normal meet it within 0.4 m.
		EXPECT_LT(x, 0.75 * range) << x << " " << y << " " << z;
		if (x < 0) ++behind;
	}
	EXPECT_GT(behind, 10000u);
}

TEST(Lidar, TheSeedFixesTheNoiseAndTheNoiseHasItsSpread)
{
	const CPose3D sensor = sensorAt(CPose2D(-3, 0, 0));
	const TScene3D& s = street().scene();
	const auto ranges = [&](const TLidarScan& scan) {
		std::vector<double> r;
		for (std::size_t i = 0; i < scan.points->size(); ++i)
		{
			float x, y, z;
			scan.points->getPoint(i, x, y, z);
			r.push_back(std::sqrt(double(x) * x + double(y) * y + double(z) * z));
		}
		return r;
	};
	CMultiLayerLidar a(TLidarOptions(), 7), b(TLidarOptions(), 7),
		c(TLidarOptions(), 8), exact(noiseless(), 7);
	const std::vector<double> ra = ranges(a.scan(s, sensor, 0)),
							  rb = ranges(b.scan(s, sensor, 0)),
							  rc = ranges(c.scan(s, sensor, 0)),
							  rExact = ranges(exact.scan(s, sensor, 0));
	EXPECT_EQ(ra, rb);
	ASSERT_EQ(ra.size(), rc.size());
	EXPECT_NE(ra, rc);
	// A second turn draws new noise.
	EXPECT_NE(ranges(a.scan(s, sensor, 0)), ra);

	// Every hit lies within range here, so the noisy turns keep the same
	// rays as the exact one.
	ASSERT_EQ(ra.size(), rExact.size());
	double sum = 0, sum2 = 0;
	for (std::size_t i = 0; i < ra.size(); ++i)
	{
		const double e = ra[i] - rExact[i];
		sum += e;
		sum2 += e * e;
	}
	const double n = static_cast<double>(ra.size());
	EXPECT_NEAR(sum / n, 0, 0.001);
	EXPECT_NEAR(std::sqrt(sum2 / n), 0.02, 0.001);
}

TEST(Lidar, BadOptionsAreRefused)
{
	TLidarOptions o;
	o.elevations.clear();
	EXPECT_THROW(CMultiLayerLidar(o, 1), std::invalid_argument);
	o = {};
	o.azimuthStep = 0;
	EXPECT_THROW(CMultiLayerLidar(o, 1), std::invalid_argument);
	o = {};
	o.maxRange = o.minRange;
	EXPECT_THROW(CMultiLayerLidar(o, 1), std::invalid_argument);
	o = {};
	o.elevations = {100 * kDeg};
	EXPECT_THROW(CMultiLayerLidar(o, 1), std::invalid_argument);
	EXPECT_THROW(TLidarOptions::evenLayers(0, -15, 15), std::invalid_argument);
	const std::vector<double> one = TLidarOptions::evenLayers(1, -15, 15);
	ASSERT_EQ(one.size(), 1u);
	EXPECT_EQ(one[0], 0.0);
}

TEST(Lidar, MovingThingsAreLabelledWhereTheyAre)
{
	// At 2 s the crossing person is at (17, -2.6), 12 m ahead.
	const double t = 2.0;
	CMultiLayerLidar lidar(TLidarOptions(), 9);
	const CPose3D sensor = sensorAt(CStreetScene::vehiclePoseAt(t));
	const TLidarScan scan = lidar.scan(street().scene(), sensor, t);
	const std::vector<TPoint3D> world = inWorld(scan, sensor);
	std::size_t onPerson = 0;
	for (std::size_t i = 0; i < world.size(); ++i)
	{
		if (scan.labels[i] != EPointLabel::Moving) continue;
		const TPoint3D& p = world[i];
		if (std::hypot(p.x - 17, p.y + 2.6) > 0.4) continue;
		++onPerson;
		EXPECT_LT(p.z, 1.7 + 0.05) << p;
	}
	EXPECT_GT(onPerson, 50u);
}

TEST(Footprint, ObstaclesKerbsAndOverhangsOfTheStreet)
{
	const TScene3D& s = street().scene();
	const TGridGeometry geometry{
		s.extent.xMin, s.extent.yMin, 0.05,
		static_cast<int>(std::lround((s.extent.xMax - s.extent.xMin) / 0.05)),
		static_cast<int>(std::lround((s.extent.yMax - s.extent.yMin) / 0.05))};
	EXPECT_EQ(geometry.sizeX, 1840);
	EXPECT_EQ(geometry.sizeY, 360);
	const TFootprintGrid still = footprintOf(s.ground, s.staticBodies, geometry);
	const TFootprintGrid atStart = footprintOf(s.ground, s.bodiesAt(0), geometry);
	struct TCase
	{
		double x, y;
		EFootprint still, atStart;
	};
	const TCase cases[] = {
		{2.0, 3.0, EFootprint::Obstacle, EFootprint::Obstacle},	 // parked car
		{-3.0, 8.15, EFootprint::Obstacle, EFootprint::Obstacle},  // house
		{0.0, -4.6, EFootprint::Obstacle, EFootprint::Obstacle},  // lamp
		{30.0, -4.6, EFootprint::Obstacle, EFootprint::Obstacle},  // on the hill
		{14.0, 4.6, EFootprint::Obstacle, EFootprint::Obstacle},  // gantry post
		{47.0, 6.0, EFootprint::Obstacle, EFootprint::Obstacle},  // tree trunk
		{-3.0, -4.075, EFootprint::Low, EFootprint::Low},  // kerb
		{60.0, 4.075, EFootprint::Low, EFootprint::Low},  // kerb, hill top
		{14.0, 0.0, EFootprint::Overhang, EFootprint::Overhang},	 // beam
		{45.0, 7.0, EFootprint::Overhang, EFootprint::Overhang},	 // crown
		{-3.0, 0.0, EFootprint::Ground, EFootprint::Ground},	// road
		{30.0, 0.0, EFootprint::Ground, EFootprint::Ground},	// ramp
		{17.0, -5.0, EFootprint::Ground, EFootprint::Obstacle},  // person
		{50.0, 0.6, EFootprint::Ground, EFootprint::Obstacle},  // waiting car
	};
	for (const TCase& c : cases)
	{
		EXPECT_EQ(still.at(c.x, c.y), c.still) << c.x << " " << c.y;
		EXPECT_EQ(atStart.at(c.x, c.y), c.atStart) << c.x << " " << c.y;
	}
	EXPECT_THROW(still.at(80, 0), std::out_of_range);
	EXPECT_THROW(footprintOf(s.ground, {}, {0, 0, 0.05, 0, 10}), std::invalid_argument);
}

TEST(Footprint, HeightsAboveTheLocalGroundDecide)
{
	// One 1 x 1 m body on the ramp at x in [30, 31]: its class from its
	// heights above the ground at each cell's centre.
	const TGround& g = street().scene().ground;
	const TGridGeometry geometry{29.5, -0.5, 0.1, 20, 10};
	struct TCase
	{
		double bottom, top;  // above the ground at x = 30.5
		EFootprint expected;
	};
	const TCase cases[] = {
		{-0.5, -0.1, EFootprint::Ground},	 {-0.05, 0.1, EFootprint::Low},
		{-0.05, 0.15, EFootprint::Low},	  {0.1, 0.3, EFootprint::Obstacle},
		{1.9, 3.0, EFootprint::Obstacle}, {2.1, 3.0, EFootprint::Overhang},
	};
	const double z = g.height(30.5, 0);
	for (const TCase& c : cases)
	{
		const TFootprintGrid grid = footprintOf(
			g, {{TRect{30, -0.2, 31, 0.2}, z + c.bottom, z + c.top, EBodyKind::Obstacle}},
			geometry);
		// The cell at x = 30.55, 0.004 m above x = 30.5: same class.
		EXPECT_EQ(grid.at(30.55, 0), c.expected) << c.bottom << " " << c.top;
		EXPECT_EQ(grid.at(29.95, 0), EFootprint::Ground);
	}
	// The ground rises 0.08 m along the body: a top 0.22 m above the ground
	// at its middle is 0.26 m above it at its downhill end (in the way) and
	// 0.18 m at its uphill end (low).
	const TFootprintGrid grid = footprintOf(
		g, {{TRect{30, -0.2, 31, 0.2}, z - 0.5, z + 0.22, EBodyKind::Low}},
		geometry);
	EXPECT_EQ(grid.at(30.05, 0), EFootprint::Obstacle);
	EXPECT_EQ(grid.at(30.95, 0), EFootprint::Low);
}
