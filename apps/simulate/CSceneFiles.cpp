/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The files every scene of evgrid-simulate writes. */
#include "CSceneFiles.h"

#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <stdexcept>

#include "SimulationClock.h"
#include "StopSignal.h"

namespace mrpt_evidential::simulate
{
CSceneFiles::CSceneFiles(
	const std::string& prefix, unsigned int seed, CScene& scene,
	const std::string& sceneName, std::size_t scans)
	: m_truth(prefix + ".gt.txt"),
	  m_slam(prefix + ".slam.txt"),
	  m_slamError(seed),
	  m_motion(
		  prefix + ".motion.gz", scene, sceneName, kStartTime, 1.0 / kRate,
		  scans)
{
	const std::string path = prefix + ".rawlog";
	m_rawlogName = std::filesystem::path(path).filename().string();
	if (std::string error; !m_rawlog.open(path, 9, error))
		throw std::runtime_error("cannot write " + path + ": " + error);
}

void CSceneFiles::writeScan(
	std::size_t k, const mrpt::poses::CPose2D& pose,
	const mrpt::obs::CActionCollection& actions,
	const mrpt::obs::CSensoryFrame& frame)
{
	evgrid::throwIfStopRequested("no file was written");
	const double time = kStartTime + static_cast<double>(k) / kRate;
	try
	{
		mrpt::serialization::archiveFrom(m_rawlog) << actions << frame;
	}
	catch (const std::exception&)
	{
		// MRPT's message names no file.
		throw std::runtime_error(
			"cannot write " + m_rawlogName + " (is the disk full?); no file was written");
	}
	m_truth.write(time, pose);
	m_slam.write(time, m_slamError.estimate(pose));
	m_motion.writeScan(k);
}

void CSceneFiles::close()
{
	m_rawlog.close();
	m_truth.close();
	m_slam.close();
	m_motion.close();
}

}  // namespace mrpt_evidential::simulate
