/* evgrid build: the 2-D scans and 3-D clouds of a rawlog or a simplemap,
 * with their poses. */

#include "CInputWalker.h"

#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/img/CImage.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDF.h>

#include <filesystem>
#include <optional>
#include <stdexcept>

#include "CScopedTimer.h"

namespace evgrid
{
using Holder = CPoseSource::Holder;

namespace
{
/** Where depth frames and images of a rawlog keep their external files:
 * `NAME_Images` beside `NAME.rawlog` (also for `NAME.rawlog.gz`), else an
 * `Images` folder beside it, as rawlog-grabber writes them. MRPT 2.5.8's
 * CRawlog::detectImagesDirectory() misses the first. */
std::optional<std::string> externalFilesFolder(const std::string& input)
{
	namespace fs = std::filesystem;
	const fs::path file(input);
	std::error_code error;
	for (fs::path stem = file.stem();; stem = stem.stem())
	{
		const fs::path candidate =
			file.parent_path() / fs::path(stem.string() + "_Images");
		if (fs::is_directory(candidate, error)) return candidate.string();
		if (!stem.has_extension()) break;
	}
	const fs::path shared = file.parent_path() / "Images";
	if (fs::is_directory(shared, error)) return shared.string();
	return std::nullopt;
}
}  // namespace

CInputWalker::CInputWalker(const std::string& path, CPoseSource& poses)
	: m_path(path), m_poses(poses), m_reader(path)
{
	if (const auto folder = externalFilesFolder(path))
		mrpt::img::CImage::setImagesPathBase(*folder);
	readNext();
	if (!m_object) throw std::runtime_error(m_path + ": the file is empty");
	m_counts.compressed = m_reader.isCompressed();
}

void CInputWalker::readNext()
{
	CScopedTimer t(m_readingSeconds);
	m_object = m_reader.next();
}

void CInputWalker::walk(const THandlers& handlers)
{
	if (const auto simplemap =
			std::dynamic_pointer_cast<mrpt::maps::CSimpleMap>(m_object))
		walkSimplemap(*simplemap, handlers);
	else
		walkRawlog(handlers);
}

void CInputWalker::walkSimplemap(
	const mrpt::maps::CSimpleMap& simplemap, const THandlers& handlers)
{
	m_counts.simplemap = true;
	m_counts.entries = simplemap.size();
	m_poses.startSimplemap();
	std::size_t done = 0;
	for (const auto& keyframe : simplemap)
	{
		handlers.beforeEntry();
		m_where = "keyframe " + std::to_string(done);
		++done;
		if (!keyframe.sf) continue;
		std::optional<mrpt::poses::CPose3D> pose;
		if (keyframe.pose) pose = keyframe.pose->getMeanVal();
		m_poses.setKeyframePose(pose);
		for (const auto& obs : *keyframe.sf)
			handOn(obs, Holder::Keyframe, std::nullopt, handlers);
		handlers.afterEntry(
			static_cast<double>(done) / static_cast<double>(simplemap.size()));
	}
}

void CInputWalker::walkRawlog(const THandlers& handlers)
{
	using namespace mrpt::obs;
	// icp-slam numbers the (action, sensory frame) pairs and the single
	// observations it reads; a sensory frame not preceded by an action is
	// skipped by MRPT's reader and gets no step number.
	std::size_t nextStep = 0;
	bool actionPending = false;
	while (m_object)
	{
		handlers.beforeEntry();
		m_where = "entry " + std::to_string(m_reader.entryIndex());
		++m_counts.entries;
		if (const auto actions =
				std::dynamic_pointer_cast<CActionCollection>(m_object))
		{
			++m_counts.actions;
			m_poses.addMovement(*actions);
			actionPending = true;
		}
		else if (const auto frame =
					 std::dynamic_pointer_cast<CSensoryFrame>(m_object))
		{
			++m_counts.sensoryFrames;
			std::optional<std::size_t> step;
			if (actionPending) step = nextStep++;
			actionPending = false;
			for (const auto& obs : *frame)
				handOn(obs, Holder::SensoryFrame, step, handlers);
		}
		else if (const auto obs =
					 std::dynamic_pointer_cast<CObservation>(m_object))
		{
			++m_counts.observations;
			if (const auto reading =
					std::dynamic_pointer_cast<CObservationOdometry>(obs))
				m_poses.addOdometryReading(*reading);
			handOn(obs, Holder::Observation, nextStep++, handlers);
		}
		else
			throw std::runtime_error(
				place() + " is a " + m_object->GetRuntimeClass()->className +
				", which has no place in a rawlog");

		handlers.afterEntry(m_reader.fractionRead());
		readNext();
	}
	// Some of MRPT's own datasets end so (simul.rawlog): not an error.
	m_counts.trailingAction = actionPending;
}

void CInputWalker::handOn(
	const mrpt::obs::CObservation::Ptr& obs, CPoseSource::Holder holder,
	std::optional<std::size_t> step, const THandlers& handlers)
{
	if (!obs) return;
	const auto* scan =
		dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(obs.get());
	if (scan)
		handlers.onScan(*scan, m_poses.poseOf(*scan, holder, step));
	else if (handlers.onCloud && isCloud(*obs))
	{
		++m_counts.cloudObservations[obs->GetRuntimeClass()->className];
		handlers.onCloud(*obs, m_poses.poseOf(*obs, holder, step));
	}
	else
		++m_counts.otherObservations[obs->GetRuntimeClass()->className];
}

std::string notInsertedAccount(const TInputCounts& counts)
{
	std::string account;
	for (const auto& [cls, n] : counts.otherObservations)
		account += (account.empty() ? "; not inserted: " : ", ") + std::to_string(n) + " " + cls;
	return account;
}

bool isCloud(const mrpt::obs::CObservation& obs)
{
	return dynamic_cast<const mrpt::obs::CObservationPointCloud*>(&obs) ||
		dynamic_cast<const mrpt::obs::CObservationVelodyneScan*>(&obs) ||
		dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obs);
}

}  // namespace evgrid
