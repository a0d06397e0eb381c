/* evgrid build: pictures of the map while it grows. */
#pragma once

#include <cstddef>
#include <optional>

#include "CGrowthAnimation.h"

namespace mrpt_evidential
{
class CEvidentialGridMap2D;
}

namespace evgrid
{
class COutputFolder;

/** --every and --animation: what to record while the map grows. */
struct TGrowthOptions
{
	/** A frame picture every this many inserted scans; 0 for none. */
	int frameEvery = 0;
	bool animation = false;
	/** growth.avi: a video frame every this many inserted scans, its size in
	 * pixels and rate. */
	int animationEvery = 1, animationWidth = 720, animationHeight = 720;
	double animationFps = 25.0;
};

/** Writes, into the output folder's staging area, the map's picture (map.png,
 * with its legend) as it grows: frames/frame_NNNNNN_map.png (NNNNNN = scans
 * inserted so far) and the frames of growth.avi. */
class CGrowthRecorder
{
   public:
	/** Opens growth.avi if an animation is asked for.
	 * \throws std::runtime_error naming it if it cannot be created. */
	CGrowthRecorder(const TGrowthOptions& options, const COutputFolder& out);

	/** After an insertion, `inserted` being the count so far: records the
	 * map if a frame or a video frame is due. */
	void afterInsertion(
		const mrpt_evidential::CEvidentialGridMap2D& map, std::size_t inserted);
	/** Finishes growth.avi with the final map, `inserted` scans in, as its
	 * last frame (unless afterInsertion() just recorded it): a video always
	 * ends on the map the run writes, even with --animation-every beyond
	 * the count of scans. */
	void finish(const mrpt_evidential::CEvidentialGridMap2D& map, std::size_t inserted);

	std::size_t frames() const { return m_frames; }
	std::size_t animationFrames() const { return m_animationFrames; }
	/** Seconds spent writing pictures and video. */
	double writingSeconds() const { return m_writingSeconds; }

   private:
	void addVideoFrame(const mrpt_evidential::CEvidentialGridMap2D& map, std::size_t inserted);

	TGrowthOptions m_options;
	const COutputFolder& m_out;
	std::optional<CGrowthAnimation> m_animation;
	std::size_t m_frames = 0, m_animationFrames = 0;
	/** The insertion count of the latest video frame. */
	std::size_t m_lastVideoFrameAt = 0;
	double m_writingSeconds = 0;
};

}  // namespace evgrid
