/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The paths of the scene "people". */
#include "CPeopleScene.h"

namespace mrpt_evidential::simulate
{
namespace
{
struct TPerson
{
	double radius;
	TPath path;
};

// Times from the first scan. The robot's ellipse keeps to the ring around
// the room's middle: people stay inside it or cross it while the robot is
// on the far side.
const TPerson kPeople[] = {
	// Crosses the room south-west to north-east at 0.95 m/s, passing
	// (-0.2, 0) at 6 s, waits, and walks back to the south-west at 0.87 m/s.
	{0.35, {{4, -2.0, -0.6}, {8, 1.6, 0.6}, {20, 1.6, 0.6}, {24, -1.6, -0.8}}},
	// Walks north at 0.8 m/s, crossing (-0.2, 0) at 7.6 s, 1.6 s after the
	// first, stops at (-0.2, 1.3) from 9.25 to 14.25 s and walks on west.
	{0.40,
	 {{6, -0.2, -1.3},
	  {9.25, -0.2, 1.3},
	  {14.25, -0.2, 1.3},
	  {16.3, -1.8, 1.0}}},
	// Stands until 24 s, walks to the door at 1.1 to 1.35 m/s, goes through
	// it at 27.5 s and up the corridor, where it stays out of the room.
	{0.30,
	 {{24, 1.2, -1.0},
	  {27, 4.4, 0.0},
	  {28, 5.6, 0.0},
	  {28.8, 6.5, 0.3},
	  {31.1, 6.5, 3.4}}},
	// Walks along the north wall, between the robot's path and the desk and
	// pillar, at 0.6 m/s.
	{0.45, {{30, 1.0, 3.2}, {35.33, -2.2, 3.2}}},
};
// Pushed once at 0.33 m/s.
const TPath kBoxPath = {{45, -1.0, -1.5}, {50, 0.6, -1.2}};
// Parked in the south-east corner until 52 s, then rolled north at
// 0.825 m/s, out through the door and down the corridor.
const TPath kCartPath = {
	{52, 3.8, -3.3}, {56, 3.8, 0.0}, {58.6, 5.95, 0.0}, {62, 5.95, -2.8}};

}  // namespace

std::vector<TShape> CPeopleScene::movingAt(double t) const
{
	std::vector<TShape> shapes = {
		t < kDoorOpensAt ? kDoorClosed : kDoorOpen,
		rectOnPath(kBoxPath, t, kBoxSize, kBoxSize),
		rectOnPath(kCartPath, t, kCartSizeX, kCartSizeY)};
	for (const TPerson& person : kPeople)
	{
		double x, y;
		pointOnPath(person.path, t, x, y);
		shapes.push_back(TDisc{x, y, person.radius});
	}
	return shapes;
}

}  // namespace mrpt_evidential::simulate
