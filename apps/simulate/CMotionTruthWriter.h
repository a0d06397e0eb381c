/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The per-scan ground truth of what moves in a scene: PREFIX.motion.gz. */
#pragma once

#include <mrpt/io/CFileGZOutputStream.h>

#include <cstdint>
#include <string>
#include <vector>

#include "CScene.h"

namespace mrpt_evidential::simulate
{
/** Writes, for each scan, the cells of a kResolution grid that the scene's
 * moving things cover at the scan's time, and the cells they stopped
 * covering since the previous scan with the time they did. The moving
 * things are sampled kSamplesPerScan times per scan period, so that a cell
 * a thing only swept between two scans is listed too. Cells of the scene's
 * static shapes are written once and never listed as moving. The format is
 * in rawlogs/README.md and evgrid-simulate --help. */
class CMotionTruthWriter
{
   public:
	static constexpr double kResolution = 0.05;
	static constexpr int kSamplesPerScan = 5;

	/** \throws std::runtime_error if the file cannot be written. */
	CMotionTruthWriter(
		const std::string& path, CScene& scene, const std::string& sceneName,
		double startTime, double scanPeriod, std::size_t scans);

	/** Samples the moving things up to scan k's time and writes scan k's
	 * record; scans must come in order from 0.
	 * \throws std::runtime_error if the file cannot be written. */
	void writeScan(std::size_t k);

	void close();

   private:
	/** Marks in `cells` what the shapes cover, static cells left out. */
	void cover(
		const std::vector<TShape>& shapes, std::vector<uint8_t>& cells) const;
	/** Moves the moving things to sample n, at n * m_samplePeriod. */
	void sample(long n);
	void write(const std::string& text);

	std::string m_path;
	mrpt::io::CFileGZOutputStream m_stream;
	CScene& m_scene;
	TGridGeometry m_grid;
	double m_samplePeriod;
	long m_lastSample = -1;
	/** One flag a cell: static; covered by a moving thing at the last
	 * sample; in m_left. */
	std::vector<uint8_t> m_static, m_covered, m_listed;
	/** When each cell was last left, seconds from the first scan. */
	std::vector<double> m_leftAt;
	/** Cells left since the previous scan's record. */
	std::vector<int> m_left;
};

}  // namespace mrpt_evidential::simulate
