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
	using Map = mrpt_evidential::CEvidentialGridMap2D;
	mrpt::img::CImage evidential, motion;
	map.getAsEvidentialImage(evidential);
	map.getAsMotionImage(motion);
	if (frame)
	{
		const std::string folder = m_out.staged("frames");
		std::filesystem::create_directories(folder);
		for (const auto& [picture, name] :
			 {std::pair{&evidential, Map::pictureNames()[0]},
			  std::pair{&motion, Map::pictureNames()[3]}})
		{
			char file[64];
			std::snprintf(file, sizeof(file), "frame_%06zu_%s", inserted, name);
			const std::string path = folder + "/" + file;
			if (!picture->saveToFile(path))
				throw std::runtime_error(path + ": cannot write the picture");
		}
		++m_frames;
	}
	if (video)
	{
		// Moving things as they move; a map that keeps conflict has no motion
		// layer, and its conflict shows in the evidential colours.
		m_animation->add(map.storage().keepsConflict() ? evidential : motion);
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
