/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The pose files of evgrid-simulate. */
#include "CPoseWriter.h"

#include <cstdio>
#include <stdexcept>
#include <utility>

namespace mrpt_evidential::simulate
{
CPoseWriter::CPoseWriter(std::string path, bool pose3D)
	: m_path(std::move(path)), m_file(m_path)
{
	if (!m_file) throw std::runtime_error("cannot write " + m_path);
	m_file << (pose3D ? "% time x y z yaw pitch roll\n" : "% time x y phi\n");
}

void CPoseWriter::write(double time, const mrpt::poses::CPose2D& pose)
{
	char line[128];
	std::snprintf(
		line, sizeof(line), "%.3f %.6f %.6f %.6f\n", time, pose.x(), pose.y(),
		pose.phi());
	m_file << line;
}

void CPoseWriter::write(double time, const mrpt::poses::CPose3D& pose)
{
	char line[160];
	std::snprintf(
		line, sizeof(line), "%.3f %.6f %.6f %.6f %.6f %.6f %.6f\n", time,
		pose.x(), pose.y(), pose.z(), pose.yaw(), pose.pitch(), pose.roll());
	m_file << line;
}

void CPoseWriter::close()
{
	m_file.close();
	if (!m_file) throw std::runtime_error("cannot write " + m_path);
}

}  // namespace mrpt_evidential::simulate
