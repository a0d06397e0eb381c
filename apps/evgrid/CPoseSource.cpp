/* evgrid build: the pose each scan is inserted at. */

#include "CPoseSource.h"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <sstream>
#include <stdexcept>
#include <utility>

using mrpt::poses::CPose2D;
using mrpt::poses::CPose3D;

namespace evgrid
{
CPoseSource::CPoseSource(std::optional<CPoseFile> file, double tolerance)
	: m_file(std::move(file)), m_tolerance(tolerance)
{
}

void CPoseSource::startSimplemap()
{
	m_simplemap = true;
	if (m_file && m_file->kind() == CPoseFile::Kind::Step)
		throw std::runtime_error(
			m_file->path() +
			": holds poses by step number (as icp-slam writes them), "
			"which count rawlog entries; a simplemap needs time stamps");
}

void CPoseSource::addMovement(const mrpt::obs::CActionCollection& actions)
{
	m_actionsSeen = true;
	if (const auto move = actions.getBestMovementEstimation();
		move && move->poseChange)
		m_movementSum = m_movementSum + move->poseChange->getMeanVal();
}

void CPoseSource::addOdometryReading(
	const mrpt::obs::CObservationOdometry& reading)
{
	m_odometryReading = reading.odometry;
}

void CPoseSource::setKeyframePose(const std::optional<CPose3D>& pose)
{
	m_keyframePose = pose;
}

std::optional<CPose3D> CPoseSource::poseOf(
	const mrpt::obs::CObservation& scan, Holder holder,
	std::optional<std::size_t> step) const
{
	if (m_file) return fromFile(scan, step);
	switch (holder)
	{
		case Holder::SensoryFrame: return CPose3D(m_movementSum);
		case Holder::Observation:
			// Before any odometry (a rawlog without: one scan, a sensor that
			// stood still), the origin.
			if (!m_odometryReading) return CPose3D();
			return CPose3D(*m_odometryReading);
		case Holder::Keyframe: break;
	}
	return m_keyframePose;
}

std::optional<CPose3D> CPoseSource::fromFile(
	const mrpt::obs::CObservation& scan, std::optional<std::size_t> step) const
{
	std::optional<mrpt::math::TPose2D> pose;
	if (m_file->kind() == CPoseFile::Kind::Step)
	{
		if (step) pose = m_file->atStep(*step);
	}
	else if (scan.timestamp != INVALID_TIMESTAMP)
		pose = m_file->atTime(
			mrpt::Clock::toDouble(scan.timestamp), m_tolerance);
	if (!pose) return std::nullopt;
	return CPose3D(CPose2D(*pose));
}

std::string CPoseSource::description() const
{
	if (m_file)
	{
		std::ostringstream s;
		s << m_file->path() << ", " << m_file->size() << " poses, ";
		if (m_file->kind() == CPoseFile::Kind::Step)
			s << "by step number (icp-slam path)";
		else
			s << "by time stamp (interpolated, tolerance " << m_tolerance
			  << " s)";
		return s.str();
	}
	if (m_simplemap) return "the simplemap's (mean of each keyframe)";
	if (m_actionsSeen)
		return "odometry (sum of the actions' movement increments)";
	if (m_odometryReading) return "odometry (latest CObservationOdometry reading)";
	return "the origin (the rawlog has no odometry)";
}

}  // namespace evgrid
