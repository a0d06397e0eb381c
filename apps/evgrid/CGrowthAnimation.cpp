/* evgrid: a video of the map growing. */

#include "CGrowthAnimation.h"

#include <mrpt/img/CImage.h>

#include <algorithm>
#include <filesystem>
#include <opencv2/imgproc.hpp>
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

void CGrowthAnimation::add(const mrpt::img::CImage& picture)
{
	const cv::Mat& src = picture.asCvMatRef();
	cv::Mat canvas(m_size, CV_8UC3, cv::Scalar(64, 64, 64));
	const double scale = std::min(
		static_cast<double>(m_size.width) / src.cols,
		static_cast<double>(m_size.height) / src.rows);
	const cv::Size fitted(
		std::clamp(static_cast<int>(src.cols * scale), 1, m_size.width),
		std::clamp(static_cast<int>(src.rows * scale), 1, m_size.height));
	cv::Mat roi = canvas(cv::Rect(
		(m_size.width - fitted.width) / 2, (m_size.height - fitted.height) / 2,
		fitted.width, fitted.height));
	// Averaging when shrinking keeps thin walls visible; blocks when
	// enlarging keep cells sharp.
	cv::resize(
		src, roi, fitted, 0, 0, scale < 1.0 ? cv::INTER_AREA : cv::INTER_NEAREST);
	m_writer.write(canvas);
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
