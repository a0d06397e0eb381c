/* evgrid: a video of the map growing. */
#pragma once

#include <opencv2/videoio.hpp>

#include <cstddef>
#include <string>

namespace mrpt::img
{
class CImage;
}

namespace evgrid
{
/** An MJPG AVI of evidential pictures. Video frames have one size while the
 * map grows, so each picture is scaled to fit a fixed canvas (aspect kept,
 * the margin dark grey: it shows where the map ends). OpenCV's own MJPG
 * writer is used, which needs no codec library. */
class CGrowthAnimation
{
   public:
	/** \throws std::runtime_error naming `path` if the writer cannot open. */
	CGrowthAnimation(
		const std::string& path, int width, int height, double framesPerSecond);
	void add(const mrpt::img::CImage& picture);
	/** Finishes the file. \throws std::runtime_error if nothing was written. */
	void close();

   private:
	std::string m_path;
	cv::VideoWriter m_writer;
	cv::Size m_size;
	std::size_t m_frames = 0;
};

}  // namespace evgrid
