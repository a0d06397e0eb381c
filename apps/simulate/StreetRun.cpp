/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * evgrid-simulate --scene street. */
#include "StreetRun.h"

#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <cstdio>

#include "CMotionTruthWriter.h"
#include "CMultiLayerLidar.h"
#include "CPoseWriter.h"
#include "CSceneFiles.h"
#include "CStreetPlanView.h"
#include "FootprintFile.h"
#include "Odometry.h"
#include "SimulationClock.h"
#include "VehicleOnGround.h"

namespace mrpt_evidential::simulate
{
namespace
{
constexpr const char* kSceneName = "street";
// Other streams than the SLAM error's (CSceneFiles) for the same seed.
constexpr unsigned int kOdometryStream = 0x0d0du, kLidarStream = 0x3d1du;
}  // namespace

std::string simulateStreet(const TStreetRunOptions& options)
{
	TLidarOptions lidarOptions;
	lidarOptions.elevations =
		TLidarOptions::evenLayers(options.layers, -15.0, 15.0);
	lidarOptions.azimuthStep = options.azimuthStepDegrees * M_PI / 180;
	CMultiLayerLidar lidar(lidarOptions, options.seed ^ kLidarStream);
	mrpt::random::CRandomGenerator odometryNoise(
		options.seed ^ kOdometryStream);

	const CStreetScene street;
	const TScene3D& scene = street.scene();
	const mrpt::poses::CPose3D mount = CStreetScene::sensorMount();
	const auto steps =
		static_cast<std::size_t>(std::lround(options.duration * kRate));

	const std::string& prefix = options.prefix;
	CStreetPlanView plan(street, options.duration);
	CSceneFiles files(prefix, options.seed, plan, kSceneName, steps);
	CPoseWriter truth3D(prefix + ".gt3d.txt", true);
	writeFootprint(
		prefix + ".footprint.gz",
		footprintOf(
			scene.ground, scene.staticBodies,
			gridOver(scene.extent, CMotionTruthWriter::kResolution)),
		kSceneName);

	std::size_t points = 0;
	mrpt::poses::CPose2D previousPose = CStreetScene::vehiclePoseAt(0.0);
	for (std::size_t k = 0; k < steps; ++k)
	{
		const double t = static_cast<double>(k) / kRate;
		const auto stamp = mrpt::Clock::fromDouble(kStartTime + t);
		const mrpt::poses::CPose2D pose = CStreetScene::vehiclePoseAt(t);
		const mrpt::poses::CPose3D vehicle =
			vehicleOnGround(scene.ground, pose);

		const auto actions =
			odometryAction(pose - previousPose, stamp, odometryNoise);
		previousPose = pose;

		const TLidarScan scan = lidar.scan(scene, vehicle + mount, t);
		points += scan.points->size();
		auto cloud = mrpt::obs::CObservationPointCloud::Create();
		cloud->sensorLabel = "VELODYNE";
		cloud->timestamp = stamp;
		cloud->sensorPose = mount;
		cloud->pointcloud = scan.points;
		mrpt::obs::CSensoryFrame frame;
		frame.insert(cloud);

		files.writeScan(k, pose, actions, frame);
		truth3D.write(kStartTime + t, vehicle);
	}
	files.close();
	truth3D.close();
	char what[160];
	std::snprintf(
		what, sizeof(what), "scene %s, %zu scans, %g s, %zu points a scan on average",
		kSceneName, steps, static_cast<double>(steps) / kRate, steps ? points / steps : 0);
	return what;
}

}  // namespace mrpt_evidential::simulate
