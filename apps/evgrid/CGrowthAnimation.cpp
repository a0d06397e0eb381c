/* evgrid: a video of the map growing. */

#include "CGrowthAnimation.h"

#include <mrpt/img/CImage.h>

#include <filesystem>
#include <stdexcept>

namespace evgrid
{
CGrowthAnimation::CGrowthAnimation(
	const std::string& path, int width, int height, double framesPerSecond)
	: m_path(path), m_size(width, height)
{
	m_writer.open(
		path, cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
		framesPerSecond, m_size, true);
	if (!m_writer.isOpened())
		throw std::runtime_error(
			path + ": OpenCV's MJPG writer cannot create the animation");
}

void CGrowthAnimation::add(const mrpt::img::CImage& frame)
{
	const cv::Mat& src = frame.asCvMatRef();
	if (src.cols != m_size.width || src.rows != m_size.height || src.type() != CV_8UC3)
		throw std::logic_error("CGrowthAnimation: a frame of the wrong size or type");
	m_writer.write(src);
	++m_frames;
}

void CGrowthAnimation::close()
{
	m_writer.release();
	std::error_code ec;
	if (m_frames == 0 || std::filesystem::file_size(m_path, ec) == 0 || ec)
		throw std::runtime_error(m_path + ": the animation could not be written");
}

}  // namespace evgrid
