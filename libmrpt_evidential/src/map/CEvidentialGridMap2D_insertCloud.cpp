/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: inserting 3-D observations (point clouds, Velodyne
 * scans, depth cameras): their points in the robot's frame, told apart and
 * grouped by azimuth (cloud/CloudSectors.h), then fused as a scan's sectors
 * are. */

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include <mrpt_evidential/support/CpuClones.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>

#include "cloud/CloudSectors.h"
#include "map/MapWorkspace.h"

using namespace mrpt_evidential;

namespace
{
/** Writes the n points (xs[i], ys[i], zs[i]) of a cloud given in the
 * sensor's frame into `out`, in the robot's. In place, not appended one by
 * one: the loop then vectorizes. `out` is resized, not cleared first: a
 * cloud of the size of the one before (a lidar's usual case) is written over
 * without a pass that sets it to zeros. */
MRPT_EVIDENTIAL_CPU_CLONES void inRobotFrame(
	const mrpt::poses::CPose3D& sensorPose, std::size_t n, const float* xs, const float* ys,
	const float* zs, std::vector<mrpt::math::TPoint3Df>& out)
{
	// The pose's rotation and translation once, not a library call a point.
	const auto& R = sensorPose.getRotationMatrix();
	const double r00 = R(0, 0), r01 = R(0, 1), r02 = R(0, 2), r10 = R(1, 0), r11 = R(1, 1),
				 r12 = R(1, 2), r20 = R(2, 0), r21 = R(2, 1), r22 = R(2, 2);
	const double tx = sensorPose.x(), ty = sensorPose.y(), tz = sensorPose.z();
	out.resize(n);
	if (n == 0) return;
	float* to = &out[0].x;
	static_assert(sizeof(mrpt::math::TPoint3Df) == 3 * sizeof(float), "packed points");
	for (std::size_t i = 0; i < n; ++i)
	{
		const double x = xs[i], y = ys[i], z = zs[i];
		to[3 * i] = static_cast<float>(tx + r00 * x + r01 * y + r02 * z);
		to[3 * i + 1] = static_cast<float>(ty + r10 * x + r11 * y + r12 * z);
		to[3 * i + 2] = static_cast<float>(tz + r20 * x + r21 * y + r22 * z);
	}
}

/** The points of a cloud held as three coordinate arrays; a cloud whose
 * arrays differ in length (a corrupted file) gives the points all three
 * hold. */
template <typename Coordinates>
void pointsOf(
	const Coordinates& xs, const Coordinates& ys, const Coordinates& zs,
	const mrpt::poses::CPose3D& sensorPose, std::vector<mrpt::math::TPoint3Df>& out)
{
	const std::size_t n = std::min({xs.size(), ys.size(), zs.size()});
	inRobotFrame(sensorPose, n, xs.data(), ys.data(), zs.data(), out);
}

void pointsOf(
	const mrpt::maps::CPointsMap& cloud, const mrpt::poses::CPose3D& sensorPose,
	std::vector<mrpt::math::TPoint3Df>& out)
{
	pointsOf(
		cloud.getPointsBufferRef_x(), cloud.getPointsBufferRef_y(), cloud.getPointsBufferRef_z(),
		sensorPose, out);
}
}  // namespace

std::optional<mrpt::poses::CPose3D> CEvidentialGridMap2D::cloudInRobotFrame(
	const mrpt::obs::CObservation& obs, std::vector<mrpt::math::TPoint3Df>& points) const
{
	// Each kind's points written over the last cloud's (pointsOf()); none
	// when the observation holds none.
	if (const auto* o = dynamic_cast<const mrpt::obs::CObservationPointCloud*>(&obs))
	{
		if (o->pointcloud)
			pointsOf(*o->pointcloud, o->sensorPose, points);
		else
			points.clear();
		return o->sensorPose;
	}
	if (const auto* o = dynamic_cast<const mrpt::obs::CObservationVelodyneScan*>(&obs))
	{
		if (o->point_cloud.size() > 0 || o->scan_packets.empty())
			pointsOf(o->point_cloud.x, o->point_cloud.y, o->point_cloud.z, o->sensorPose, points);
		else
		{
			// Raw packets only: decode them with the scan's calibration, on
			// a copy (decoding writes the observation). MRPT asserts on
			// packets its calibration has no laser for.
			if (o->calibration.empty())
				throw std::invalid_argument(
					"a Velodyne scan of raw packets without the calibration that "
					"decodes them (and no point_cloud)");
			mrpt::obs::CObservationVelodyneScan decoded(*o);
			try
			{
				decoded.generatePointCloud();
			}
			catch (const std::exception&)
			{
				throw std::invalid_argument(
					"a Velodyne scan whose raw packets its calibration (" +
					std::to_string(o->calibration.laser_corrections.size()) +
					" lasers) cannot decode");
			}
			pointsOf(
				decoded.point_cloud.x, decoded.point_cloud.y, decoded.point_cloud.z, o->sensorPose,
				points);
		}
		return o->sensorPose;
	}
	if (const auto* o = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obs))
	{
		if (o->hasRangeImage)
		{
			// Unprojecting loads an externally stored image: a copy.
			mrpt::obs::CObservation3DRangeScan copy(*o);
			mrpt::maps::CSimplePointsMap cloud;
			mrpt::obs::T3DPointsProjectionParams projection;
			projection.takeIntoAccountSensorPoseOnRobot = false;
			// MRPT asserts that the image fits the camera's parameters.
			try
			{
				copy.unprojectInto(cloud, projection);
			}
			catch (const std::exception&)
			{
				if (o->rangeImage_isExternallyStored() && copy.rangeImage.cols() == 0)
					throw std::invalid_argument(
						"a depth frame whose range image, stored apart in '" +
						o->rangeImage_getExternalStorageFileAbsolutePath("") +
						"', cannot be read (a rawlog's external files are looked "
						"for where mrpt::img::CImage::setImagesPathBase() says)");
				throw std::invalid_argument(
					"a depth frame that cannot be unprojected: its range image (" +
					std::to_string(copy.rangeImage.cols()) + " x " +
					std::to_string(copy.rangeImage.rows()) +
					") does not fit its camera parameters (" +
					std::to_string(o->cameraParams.ncols) + " x " +
					std::to_string(o->cameraParams.nrows) + ")");
			}
			pointsOf(cloud, o->sensorPose, points);
		}
		else if (o->hasPoints3D)
			pointsOf(o->points3D_x, o->points3D_y, o->points3D_z, o->sensorPose, points);
		else
			points.clear();
		return o->sensorPose;
	}
	return std::nullopt;
}

bool CEvidentialGridMap2D::insertCloud(
	const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& robotPose)
{
	const TInsertionOptions& io = insertionOptions;
	if (const auto bad = io.firstInvalidOfTheMap())
		throw std::invalid_argument(bad->describe());
	std::vector<mrpt::math::TPoint3Df>& points = m_workspace->cloudPoints;
	const auto sensorPose = cloudInRobotFrame(obs, points);
	if (!sensorPose) return false;
	const mrpt::poses::CPose3D sensorInWorld = robotPose + *sensorPose;
	requireFinitePose(sensorInWorld, "cloud");
	// Heights are measured along the robot's z axis: a robot upside down
	// has no ground under it.
	if (!(robotPose.getRotationMatrix()(2, 2) > 0.0))
	{
		if (!m_upsideDownNoticeShown)
			std::cerr << "[CEvidentialGridMap2D] note: clouds taken by a robot "
						 "whose z axis points down are ignored (shown once)\n";
		m_upsideDownNoticeShown = true;
		return false;
	}

	TCloudRules rules;
	rules.groundRemoval = io.groundRemoval;
	rules.minObstacleHeight = io.minObstacleHeight;
	rules.maxObstacleHeight = io.maxObstacleHeight;
	rules.groundReturns = io.groundReturns;
	rules.sectorWidth = io.sectorWidth > 0.0 ? io.sectorWidth : kDefaultCloudSectorWidth;
	TCloudReturns& returns = m_workspace->cloudReturns;
	sortCloudIntoSectors(
		points, sensorPose->translation(), robotPose, rules, returns, m_workspace->cloudScratch);

	CPolarSourceGrid& polar = m_workspace->sourceGrid;
	polar.build(returns, io.sourceGridOptions(getResolution()));
	// The returns' azimuths are the world's: the polar grid's sectors start
	// at the world's -pi, around the sensor's place.
	PlanarSensorPose sensor;
	sensor.x = sensorInWorld.x();
	sensor.y = sensorInWorld.y();
	fusePolarGrid(sensor, obs.timestamp);
	return true;
}
