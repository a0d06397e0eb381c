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
/** An MJPG AVI of the map's pictures. Video frames have one size while the
 * map grows: the map makes each at that size
 * (CEvidentialGridMap2D::getAsPicture). OpenCV's own MJPG writer is used,
 * which needs no codec library. */
class CGrowthAnimation
{
   public:
	/** \throws std::runtime_error naming `path` if the writer cannot open. */
	CGrowthAnimation(
		const std::string& path, int width, int height, double framesPerSecond);
	/** \throws std::logic_error if the frame is not width x height RGB. */
	void add(const mrpt::img::CImage& frame);
	int width() const { return m_size.width; }
	int height() const { return m_size.height; }
	/** Finishes the file. \throws std::runtime_error if nothing was written. */
	void close();

   private:
	std::string m_path;
	cv::VideoWriter m_writer;
	cv::Size m_size;
	std::size_t m_frames = 0;
};

}  // namespace evgrid
