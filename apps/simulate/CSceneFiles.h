/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The files every scene of evgrid-simulate writes, a record a scan. */
#pragma once

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <string>

#include "CMotionTruthWriter.h"
#include "CPoseWriter.h"
#include "CScene.h"
#include "CSlamError.h"

namespace mrpt_evidential::simulate
{
/** PREFIX.rawlog (gzip, actions / sensory-frame format), PREFIX.gt.txt,
 * PREFIX.slam.txt (the SLAM-like error drawn from `seed`) and
 * PREFIX.motion.gz, for scans 0 .. scans - 1 at kRate from kStartTime. */
class CSceneFiles
{
   public:
	/** \throws std::runtime_error if a file cannot be written. */
	CSceneFiles(
		const std::string& prefix, unsigned int seed, CScene& scene,
		const std::string& sceneName, std::size_t scans);

	/** Writes scan k (in order from 0): the action and the frame to the
	 * rawlog, the robot's true pose and its SLAM-like estimate, and what
	 * moves up to the scan's time.
	 * \throws std::runtime_error if a file cannot be written, or once a stop
	 *  was requested (evgrid::catchStopSignals()). */
	void writeScan(
		std::size_t k, const mrpt::poses::CPose2D& pose,
		const mrpt::obs::CActionCollection& actions,
		const mrpt::obs::CSensoryFrame& frame);

	/** \throws std::runtime_error if a file could not be written. */
	void close();

   private:
	mrpt::io::CFileGZOutputStream m_rawlog;
	std::string m_rawlogName;  //!< Its file name, for messages.
	CPoseWriter m_truth, m_slam;
	CSlamError m_slamError;
	CMotionTruthWriter m_motion;
};

}  // namespace mrpt_evidential::simulate
