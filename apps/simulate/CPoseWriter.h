/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The pose files of evgrid-simulate: PREFIX.gt.txt and the like. */
#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <fstream>
#include <string>

namespace mrpt_evidential::simulate
{
/** A text file of one pose a line after a "%" header: "time x y phi" for
 * 2-D poses (as evgrid build -p reads), "time x y z yaw pitch roll" for
 * 3-D ones (Unix seconds, metres, radians). */
class CPoseWriter
{
   public:
	/** \throws std::runtime_error if the file cannot be written. */
	explicit CPoseWriter(std::string path, bool pose3D = false);

	void write(double time, const mrpt::poses::CPose2D& pose);
	void write(double time, const mrpt::poses::CPose3D& pose);

	/** \throws std::runtime_error if the file could not be written. */
	void close();

   private:
	std::string m_path;
	std::ofstream m_file;
};

}  // namespace mrpt_evidential::simulate
