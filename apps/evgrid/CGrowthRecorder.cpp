/* evgrid build: pictures of the map while it grows. */

#include "CGrowthRecorder.h"

#include <mrpt/img/CImage.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "COutputFolder.h"
#include "CScopedTimer.h"

namespace evgrid
{
namespace
{
/** map.png: the static map with what moved (or the conflict of a map that
 * keeps it), as the 3-D view draws it; the frames and the video show it. */
constexpr std::size_t kMapPicture = 0;
}  // namespace

CGrowthRecorder::CGrowthRecorder(
	const TGrowthOptions& options, const COutputFolder& out)
	: m_options(options), m_out(out)
{
	// Made now, even if no frame falls due: frames/ replaces an earlier
	// run's as a whole, also when this run writes none.
	if (options.frameEvery > 0) std::filesystem::create_directories(out.staged("frames"));
	if (options.animation)
		m_animation.emplace(
			out.staged("growth.avi"), options.animationWidth,
			options.animationHeight, options.animationFps);
}

void CGrowthRecorder::afterInsertion(
	const mrpt_evidential::CEvidentialGridMap2D& map, std::size_t inserted)
{
	const bool frame = m_options.frameEvery > 0 &&
		inserted % static_cast<std::size_t>(m_options.frameEvery) == 0;
	const bool video = m_animation &&
		inserted % static_cast<std::size_t>(m_options.animationEvery) == 0;
	if (!frame && !video) return;

	CScopedTimer t(m_writingSeconds);
	using Map = mrpt_evidential::CEvidentialGridMap2D;
	if (frame)
	{
		mrpt::img::CImage picture;
		const std::string folder = m_out.staged("frames");
		map.getAsPicture(kMapPicture, picture);
		char file[64];
		std::snprintf(
			file, sizeof(file), "frame_%06zu_%s", inserted, Map::pictureNames()[kMapPicture]);
		const std::string path = folder + "/" + file;
		if (!picture.saveToFile(path))
			throw std::runtime_error(path + ": cannot write the picture");
		++m_frames;
	}
	if (video) addVideoFrame(map, inserted);
}

void CGrowthRecorder::addVideoFrame(
	const mrpt_evidential::CEvidentialGridMap2D& map, std::size_t inserted)
{
	mrpt::img::CImage picture;
	map.getAsPicture(kMapPicture, picture, true, m_animation->width(), m_animation->height());
	m_animation->add(picture);
	++m_animationFrames;
	m_lastVideoFrameAt = inserted;
}

void CGrowthRecorder::finish(
	const mrpt_evidential::CEvidentialGridMap2D& map, std::size_t inserted)
{
	if (!m_animation) return;
	CScopedTimer t(m_writingSeconds);
	if (m_animationFrames == 0 || m_lastVideoFrameAt != inserted) addVideoFrame(map, inserted);
	m_animation->close();
}

}  // namespace evgrid
