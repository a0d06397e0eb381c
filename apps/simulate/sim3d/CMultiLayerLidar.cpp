/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * A multi-layer spinning lidar cast into a 3-D scene. */
#include "CMultiLayerLidar.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace mrpt_evidential::simulate
{
std::vector<double> TLidarOptions::evenLayers(
	std::size_t n, double lowestDegrees, double highestDegrees)
{
	if (n == 0) throw std::invalid_argument("a lidar needs a layer");
	std::vector<double> layers;
	for (std::size_t i = 0; i < n; ++i)
	{
		const double s = n == 1 ? 0.5 : static_cast<double>(i) / (n - 1);
		layers.push_back(
			(lowestDegrees + s * (highestDegrees - lowestDegrees)) * M_PI /
			180);
	}
	return layers;
}

std::size_t TLidarOptions::raysPerTurn() const
{
	return static_cast<std::size_t>(std::lround(2 * M_PI / azimuthStep));
}

void TLidarOptions::validate() const
{
	const auto bad = [](const std::string& what) {
		throw std::invalid_argument("lidar: " + what);
	};
	if (elevations.empty()) bad("no layer");
	for (const double e : elevations)
		if (!(std::abs(e) <= M_PI / 2))
			bad("elevation " + std::to_string(e) +
				" rad outside [-90, 90] deg");
	if (!(azimuthStep > 0 && azimuthStep <= M_PI / 2))
		bad("azimuthStep outside (0, 90] deg");
	if (!(minRange >= 0)) bad("minRange < 0");
	if (!(maxRange > minRange)) bad("maxRange <= minRange");
	if (!(rangeNoise >= 0)) bad("rangeNoise < 0");
}

CMultiLayerLidar::CMultiLayerLidar(
	const TLidarOptions& options, unsigned int seed)
	: m_options(options), m_rng(seed)
{
	m_options.validate();
	const std::size_t rays = m_options.raysPerTurn();
	for (std::size_t i = 0; i < rays; ++i)
	{
		const double azimuth = 2 * M_PI * static_cast<double>(i) / rays;
		for (const double e : m_options.elevations)
			m_directions.emplace_back(
				std::cos(e) * std::cos(azimuth),
				std::cos(e) * std::sin(azimuth), std::sin(e));
	}
}

TLidarScan CMultiLayerLidar::scan(
	const TScene3D& scene, const mrpt::poses::CPose3D& sensorPose, double t)
{
	const std::vector<TBody> bodies = scene.bodiesAt(t);
	const mrpt::math::TPoint3D origin = sensorPose.translation();
	TLidarScan out;
	out.points = mrpt::maps::CSimplePointsMap::Create();
	for (const mrpt::math::TVector3D& local : m_directions)
	{
		const auto hit = castRay(
			scene.ground, bodies, origin, sensorPose.rotateVector(local),
			m_options.maxRange);
		if (!hit) continue;
		const double range = hit->range +
			m_options.rangeNoise * m_rng.drawGaussian1D_normalized();
		if (range < m_options.minRange || range > m_options.maxRange)
			continue;
		out.points->insertPointFast(
			static_cast<float>(range * local.x),
			static_cast<float>(range * local.y),
			static_cast<float>(range * local.z));
		out.labels.push_back(hit->label);
	}
	out.points->mark_as_modified();
	return out;
}

}  // namespace mrpt_evidential::simulate
