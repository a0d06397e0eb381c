/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * How a vehicle stands on uneven ground. */
#include "VehicleOnGround.h"

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/CVectorFixed.h>
#include <mrpt/math/TPoint3D.h>

#include <cmath>

namespace mrpt_evidential::simulate
{
mrpt::poses::CPose3D vehicleOnGround(
	const TGround& ground, const mrpt::poses::CPose2D& pose,
	const TWheelBase& wheels)
{
	const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
	const double halfBase = 0.5 * wheels.wheelBase,
				 halfTrack = 0.5 * wheels.track;
	// The ground under the wheel at (along, across) in the vehicle's frame.
	const auto wheel = [&](double along, double across) {
		return ground.height(
			pose.x() + c * along - s * across,
			pose.y() + s * along + c * across);
	};
	const double frontLeft = wheel(halfBase, halfTrack),
				 frontRight = wheel(halfBase, -halfTrack),
				 rearLeft = wheel(-halfBase, halfTrack),
				 rearRight = wheel(-halfBase, -halfTrack);
	const double z = 0.25 * (frontLeft + frontRight + rearLeft + rearRight);
	const double rise = (frontLeft + frontRight - rearLeft - rearRight) /
		(2 * wheels.wheelBase);
	const double bank = (frontLeft + rearLeft - frontRight - rearRight) /
		(2 * wheels.track);

	// The vehicle's axes in the world: x along the heading with the rise,
	// y across it with the bank, made orthonormal (x kept, y corrected).
	mrpt::math::TVector3D x(c, s, rise), y(-s, c, bank);
	x *= 1.0 / x.norm();
	y -= x * (x.x * y.x + x.y * y.y + x.z * y.z);
	y *= 1.0 / y.norm();
	const mrpt::math::TVector3D zAxis(
		x.y * y.z - x.z * y.y, x.z * y.x - x.x * y.z, x.x * y.y - x.y * y.x);

	mrpt::math::CMatrixDouble33 rotation;
	const mrpt::math::TVector3D axes[3] = {x, y, zAxis};
	for (int col = 0; col < 3; ++col)
	{
		rotation(0, col) = axes[col].x;
		rotation(1, col) = axes[col].y;
		rotation(2, col) = axes[col].z;
	}
	mrpt::math::CVectorFixedDouble<3> origin;
	origin[0] = pose.x();
	origin[1] = pose.y();
	origin[2] = z;
	return mrpt::poses::CPose3D::FromRotationAndTranslation(rotation, origin);
}

}  // namespace mrpt_evidential::simulate
