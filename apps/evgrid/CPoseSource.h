/* evgrid build: the pose each scan is inserted at. */
#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <cstddef>
#include <optional>
#include <string>

#include "CPoseFile.h"

namespace mrpt::obs
{
class CActionCollection;
class CObservation;
class CObservationOdometry;
}  // namespace mrpt::obs

namespace evgrid
{
/** Gives each scan its robot pose: without a pose file, the one the input
 * carries (a rawlog's odometry, a simplemap's keyframe poses); with one, the
 * file's (ground truth by time stamp, or icp-slam's path by step number).
 * The input walker tells it the odometry and keyframes as it meets them. */
class CPoseSource
{
   public:
	/** Where a scan was found, which decides the input's own pose for it. */
	enum class Holder
	{
		/** A rawlog's sensory frame: the sum of the actions' movements. */
		SensoryFrame,
		/** An observation-only rawlog: the latest odometry reading; the
		 * origin before the first. */
		Observation,
		/** A simplemap keyframe: its pose. */
		Keyframe
	};

	/** `tolerance`: seconds, for pose files by time stamp. */
	CPoseSource(std::optional<CPoseFile> file, double tolerance);

	/** The input is a simplemap. \throws std::runtime_error if the pose file
	 *  is by step number: steps count rawlog entries, not keyframes. */
	void startSimplemap();
	void addMovement(const mrpt::obs::CActionCollection& actions);
	void addOdometryReading(const mrpt::obs::CObservationOdometry& reading);
	/** The pose of the keyframe whose scans follow; none if it has none. */
	void setKeyframePose(const std::optional<mrpt::poses::CPose3D>& pose);

	/** `step`: icp-slam's number of the scan's entry, if it has one.
	 * \return nothing if the scan gets no pose (and is not inserted). */
	std::optional<mrpt::poses::CPose3D> poseOf(
		const mrpt::obs::CObservation& scan, Holder holder,
		std::optional<std::size_t> step) const;

	/** What the summary says about the poses. */
	std::string description() const;

   private:
	std::optional<mrpt::poses::CPose3D> fromFile(
		const mrpt::obs::CObservation& scan,
		std::optional<std::size_t> step) const;

	std::optional<CPoseFile> m_file;
	double m_tolerance;
	bool m_simplemap = false, m_actionsSeen = false;
	mrpt::poses::CPose2D m_movementSum;
	std::optional<mrpt::poses::CPose2D> m_odometryReading;
	std::optional<mrpt::poses::CPose3D> m_keyframePose;
};

}  // namespace evgrid
