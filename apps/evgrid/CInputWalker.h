/* evgrid build: the 2-D scans and 3-D clouds of a rawlog or a simplemap,
 * with their poses. */
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CSerializable.h>

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "CObjectFileReader.h"
#include "CPoseSource.h"

namespace mrpt::maps
{
class CSimpleMap;
}
namespace mrpt::obs
{
class CObservation2DRangeScan;
}

namespace evgrid
{
/** What the input held, for the summary. */
struct TInputCounts
{
	bool simplemap = false, compressed = false;
	/** Rawlog entries, or simplemap keyframes. */
	std::size_t entries = 0;
	std::size_t actions = 0, sensoryFrames = 0, observations = 0;
	/** 3-D observations handed on as clouds (when the walk takes them), by
	 * class name. */
	std::map<std::string, std::size_t> cloudObservations;
	/** Other observations, by class name. */
	std::map<std::string, std::size_t> otherObservations;
	/** The rawlog ends with an action that has no sensory frame after it. */
	bool trailingAction = false;
};

/** "; not inserted: 1 CObservationRotatingScan, 2 CObservationImage" for
 * the other observations of `counts`, or "" when there are none: what a
 * message that nothing was inserted adds, so that the user sees what the
 * input held instead. */
std::string notInsertedAccount(const TInputCounts& counts);

/** The names of the observation classes build reads, for its help and its
 * messages: 2-D scans, and the 3-D observations isCloud() takes. */
inline constexpr char kScanClassName[] = "CObservation2DRangeScan";
inline constexpr char kCloudClassNames[] =
	"CObservationPointCloud, CObservationVelodyneScan, CObservation3DRangeScan";

/** Whether the map reads `obs` as a 3-D cloud: the classes kCloudClassNames
 * names (CObservationRotatingScan has no elevations in MRPT 2.5.8). */
bool isCloud(const mrpt::obs::CObservation& obs);

/** Walks the entries of a rawlog (action/sensory-frame pairs, single
 * observations, or both) or the keyframes of a simplemap, and hands on each
 * 2-D scan with the pose the pose source gives it. The file is read one
 * entry at a time. */
class CInputWalker
{
   public:
	struct THandlers
	{
		/** Before each entry or keyframe: may throw to stop the walk. */
		std::function<void()> beforeEntry;
		/** Each 2-D scan; no pose when the pose source has none for it. */
		std::function<void(
			const mrpt::obs::CObservation2DRangeScan&,
			const std::optional<mrpt::poses::CPose3D>&)>
			onScan;
		/** After an entry or keyframe: the share of the input walked. */
		std::function<void(double fraction)> afterEntry;
		/** Each 3-D observation the map reads as a cloud (isCloud()), if
		 * set; else they count as other observations. */
		std::function<void(
			const mrpt::obs::CObservation&, const std::optional<mrpt::poses::CPose3D>&)>
			onCloud;
	};

	/** Opens `path` and reads its first object.
	 * \throws std::runtime_error naming `path` if it cannot be read or is
	 *  empty. */
	CInputWalker(const std::string& path, CPoseSource& poses);

	/** \throws std::runtime_error naming the entry that does not belong in
	 *  the input, and whatever the handlers or the pose source throw. */
	void walk(const THandlers& handlers);

	const TInputCounts& counts() const { return m_counts; }
	/** "<file>: entry K" or "<file>: keyframe K": the one being walked, for
	 * error messages. */
	std::string place() const { return m_path + ": " + m_where; }
	/** Seconds spent reading the file's objects. */
	double readingSeconds() const { return m_readingSeconds; }

   private:
	void walkSimplemap(
		const mrpt::maps::CSimpleMap& simplemap, const THandlers& handlers);
	void walkRawlog(const THandlers& handlers);
	void readNext();
	void handOn(
		const mrpt::obs::CObservation::Ptr& obs, CPoseSource::Holder holder,
		std::optional<std::size_t> step, const THandlers& handlers);

	std::string m_path;
	CPoseSource& m_poses;
	CObjectFileReader m_reader;
	mrpt::serialization::CSerializable::Ptr m_object;
	TInputCounts m_counts;
	std::string m_where;
	double m_readingSeconds = 0;
};

}  // namespace evgrid
