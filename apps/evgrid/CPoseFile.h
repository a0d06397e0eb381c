/* evgrid: robot poses from a text file. */
#pragma once

#include <mrpt/math/TPose2D.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace evgrid
{
/** A robot path read from a text file of lines `key x y phi` (metres,
 * radians; blank lines and lines starting with '#' or '%' are skipped), in
 * one of two kinds:
 *  - Time: `key` is a time stamp in seconds (UNIX time, as in MRPT's
 *    ground-truth files). A scan takes the pose at its own time stamp,
 *    interpolated linearly (the angle along the shorter way) between the two
 *    poses around it; it has no pose if the nearer of them is more than
 *    `tolerance` seconds away, or if it lies before the first or after the
 *    last pose by more than that.
 *  - Step: `key` is a step number 0, 1, 2, ..., as in icp-slam's
 *    log_estimated_path.txt, where step k is the pose after icp-slam
 *    processed the k-th rawlog entry (an action/sensory-frame pair, or one
 *    observation of an observation-only rawlog). Every scan of step k takes
 *    pose k.
 * Auto-detection takes Step when every key is a plain integer and the keys
 * count 0, 1, 2, ... without a gap; otherwise Time. */
class CPoseFile
{
   public:
	enum class Kind
	{
		Auto,
		Time,
		Step
	};

	/** \throws std::runtime_error "<path>:<line>: ..." on a line that is not
	 *  four numbers, time stamps that go back, steps that do not increase,
	 *  or a file without any pose. */
	static CPoseFile load(const std::string& path, Kind kind);

	Kind kind() const { return m_kind; }
	std::size_t size() const { return m_keys.size(); }
	const std::string& path() const { return m_path; }
	/** Every pose, in the file's order. */
	const std::vector<mrpt::math::TPose2D>& poses() const { return m_poses; }

	/** Pose at time t (Time files); nullopt if none within tolerance. */
	std::optional<mrpt::math::TPose2D> atTime(double t, double tolerance) const;
	/** Pose of step k (Step files); nullopt if the file has no such step. */
	std::optional<mrpt::math::TPose2D> atStep(std::size_t step) const;

   private:
	std::string m_path;
	Kind m_kind = Kind::Time;
	std::vector<double> m_keys;
	std::vector<mrpt::math::TPose2D> m_poses;
};

}  // namespace evgrid
