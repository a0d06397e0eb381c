/* evgrid build: pictures of the map while it grows. */

#include "CGrowthRecorder.h"

#include <mrpt/img/CImage.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "COutputFolder.h"
#include "CScopedTimer.h"

namespace evgrid
{
CGrowthRecorder::CGrowthRecorder(
	const TGrowthOptions& options, const COutputFolder& out)
	: m_options(options), m_out(out)
{
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
	mrpt::img::CImage picture;
	map.getAsEvidentialImage(picture);
	if (frame)
	{
		char name[64];
		std::snprintf(
			name, sizeof(name), "frame_%06zu_%s", inserted,
			mrpt_evidential::CEvidentialGridMap2D::pictureNames()[0]);
		const std::string folder = m_out.staged("frames");
		std::filesystem::create_directories(folder);
		const std::string path = folder + "/" + name;
		if (!picture.saveToFile(path))
			throw std::runtime_error(path + ": cannot write the picture");
		++m_frames;
	}
	if (video)
	{
		m_animation->add(picture);
		++m_animationFrames;
	}
}

void CGrowthRecorder::finish()
{
	if (!m_animation) return;
	CScopedTimer t(m_writingSeconds);
	m_animation->close();
}

}  // namespace evgrid
