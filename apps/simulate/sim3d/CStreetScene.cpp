/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The layout of the scene "street". */
#include "CStreetScene.h"

#include <cmath>

namespace mrpt_evidential::simulate
{
namespace
{
// Bodies reach this far into the ground, so that no gap shows under one
// on a slope; walls and poles stand this high.
constexpr double kBuried = 0.3, kHouseTop = 10.0, kPoleTop = 4.5;
constexpr double kWestEnd = -15.0, kEastEnd = 75.0, kThick = 0.3;
constexpr double kCarLength = 4.4, kCarWidth = 1.8;
constexpr double kCarClearance = 0.15, kCarTop = 1.5;
constexpr double kPersonRadius = 0.3, kPersonHeight = 1.7;

/** A parked car centred at (x, y) on the ground there. */
TBody parkedCar(const TGround& ground, double x, double y)
{
	const double z = ground.height(x, y);
	return {
		TRect{
			x - 0.5 * kCarLength, y - 0.5 * kCarWidth, x + 0.5 * kCarLength,
			y + 0.5 * kCarWidth},
		z + kCarClearance, z + kCarTop, EBodyKind::Obstacle};
}

/** A vertical cylinder at (x, y) rising `top` above the ground there. */
TBody pole(
	const TGround& ground, double x, double y, double radius, double top)
{
	const double z = ground.height(x, y);
	return {TDisc{x, y, radius}, z - kBuried, z + top, EBodyKind::Obstacle};
}
}  // namespace

CStreetScene::CStreetScene()
{
	TScene3D& s = m_scene;
	s.extent = {kWestEnd - 1, -kHouseY - 1, kEastEnd + 1, kHouseY + 1};
	TGround& g = s.ground;
	g.rampStartX = kRampStartX;
	g.rampEndX = kRampEndX;
	g.rampSlope = std::tan(kRampDegrees * M_PI / 180);
	// Two bumps the vehicle drives over (at 2.4 s and 18.8 s), one in the
	// other lane; none on the ramp, whose points lie on its plane.
	g.bumps = {{6.0, -2.0, 0.08, 2.0}, {11.0, 1.0, 0.05, 1.5},
		{47.0, -2.0, 0.06, 1.5}};
	const double top = g.highest();

	// House fronts on both sides and the street's two ends.
	const TRect walls[] = {
		{kWestEnd - kThick, kHouseY, kEastEnd + kThick, kHouseY + kThick},
		{kWestEnd - kThick, -kHouseY - kThick, kEastEnd + kThick, -kHouseY},
		{kWestEnd - kThick, -kHouseY, kWestEnd, kHouseY},
		{kEastEnd, -kHouseY, kEastEnd + kThick, kHouseY},
	};
	for (const TRect& w : walls)
		s.staticBodies.push_back(
			{w, -kBuried, top + kHouseTop, EBodyKind::Obstacle});

	// Kerbs along both sides of the road on the flat parts (the hill has
	// none): kKerbHeight above the ground, 0.15 m wide.
	const double hill = g.rampSlope * (kRampEndX - kRampStartX);
	const double flats[][3] = {
		{kWestEnd, kRampStartX, 0.0}, {kRampEndX, kEastEnd, hill}};
	for (const auto& [x0, x1, z] : flats)
		for (const double side : {-1.0, 1.0})
		{
			const double inner = side * kKerbY, outer = side * (kKerbY + 0.15);
			s.staticBodies.push_back(
				{TRect{x0, std::min(inner, outer), x1, std::max(inner, outer)},
				 z - 0.05, z + kKerbHeight, EBodyKind::Low});
		}

	// Parked cars in the north lane, with a gap for the crossing person.
	for (const double x : {-8.0, 2.0, 7.5, 45.0, 51.0, 62.0})
		s.staticBodies.push_back(parkedCar(g, x, 3.0));
	// Street lamps on the south pavement, the hill's too.
	for (const double x : {-10.0, 0.0, 10.0, 20.0, 30.0, 50.0, 60.0, 70.0})
		s.staticBodies.push_back(pole(g, x, -4.6, 0.08, kPoleTop));

	// The gantry over the road: two posts holding a beam the vehicle drives
	// under at 5.6 s.
	s.staticBodies.push_back(pole(g, 14.0, -4.6, 0.15, kGantryTop));
	s.staticBodies.push_back(pole(g, 14.0, 4.6, 0.15, kGantryTop));
	s.staticBodies.push_back(
		{kGantryBeam, kGantryBottom, kGantryTop, EBodyKind::Overhang});
	// A tree on the north pavement at the hill's top: trunk and crown.
	const double treeZ = g.height(47.0, 6.0);
	s.staticBodies.push_back(pole(g, 47.0, 6.0, 0.2, 3.0));
	s.staticBodies.push_back(
		{TRect{44.0, 4.5, 50.0, 7.5}, treeZ + 2.8, treeZ + 5.0,
		 EBodyKind::Overhang});

	// A person crosses the road at x = 17 at 1.2 m/s, out of the vehicle's
	// lane 2.1 s before it comes; another walks west along the south
	// pavement at 1.2 m/s; a car waits at x = 50 until 4.5 s, then comes
	// down the other lane at 6 m/s and stops at the west end. The car meets
	// the vehicle at 9.1 s, after the person crossed.
	const TDisc person{0, 0, kPersonRadius};
	s.moving.push_back(
		{person, -0.05, kPersonHeight, {{0, 17, -5.0}, {9.17, 17, 6.0}}});
	s.moving.push_back(
		{person, -0.05, kPersonHeight, {{0, 30, -6.0}, {20, 6, -6.0}}});
	s.moving.push_back(
		{TRect{
			 -0.5 * kCarLength, -0.5 * kCarWidth, 0.5 * kCarLength,
			 0.5 * kCarWidth},
		 kCarClearance, kCarTop, {{4.5, 50, 0.6}, {14.5, -10, 0.6}}});
}

mrpt::poses::CPose2D CStreetScene::vehiclePoseAt(double t)
{
	const double w = 2 * M_PI / kWeavePeriod;
	return {
		kSpeed * t, kLaneY + kWeave * std::sin(w * t),
		std::atan2(kWeave * w * std::cos(w * t), kSpeed)};
}

mrpt::poses::CPose3D CStreetScene::sensorMount()
{
	return {0, 0, kSensorHeight, 0, 0, 0};
}

}  // namespace mrpt_evidential::simulate
