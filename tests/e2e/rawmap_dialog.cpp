/* mrpt-evidential end-to-end tests: RawLogViewer's "Raw-map" dialog, replayed.
 *
 * Loads the plugin at run time as RawLogViewer -l does, reads the dialog's map
 * definition (section [map]) from the given .ini, builds the maps from a
 * rawlog along its odometry as the dialog's "Map from odometry" button does,
 * saves them as its "Save map as text..." button does, then writes a rawlog
 * whose first object is the evidential map, followed by the first entries of
 * the input: the rawlog that rawlog-edit and RawLogViewer read in the tests.
 *
 * Usage: rawmap_dialog <plugin.so> <rawmap.ini> <input.rawlog>
 *                      <output.rawlog> <maps prefix> <entries to copy>
 * Exits non-zero on a failure. */
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/vector_loadsave.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/os.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>

namespace
{
constexpr const char* kEvidentialClass =
	"mrpt_evidential::CEvidentialGridMap2D";

/** Builds the maps along the odometry of an action/sensory-frame rawlog. */
void buildAlongOdometry(
	const mrpt::obs::CRawlog& rawlog, mrpt::maps::CMultiMetricMap& maps)
{
	using mrpt::obs::CActionRobotMovement2D;
	using mrpt::obs::CRawlog;
	mrpt::poses::CPose2D pose;
	for (std::size_t i = 0; i < rawlog.size(); ++i)
	{
		if (rawlog.getType(i) == CRawlog::etActionCollection)
		{
			const auto move = rawlog.getAsAction(i)
								  ->getActionByClass<CActionRobotMovement2D>();
			if (move) pose = pose + move->poseChange->getMeanVal();
		}
		else if (rawlog.getType(i) == CRawlog::etSensoryFrame)
			rawlog.getAsObservations(i)->insertObservationsInto(
				maps, mrpt::poses::CPose3D(pose));
	}
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc != 7)
	{
		std::fprintf(
			stderr,
			"usage: %s <plugin.so> <rawmap.ini> <input.rawlog> <output.rawlog> "
			"<maps prefix> <entries to copy>\n",
			argv[0]);
		return 2;
	}
	try
	{
		std::string errors;
		if (!mrpt::system::loadPluginModule(argv[1], errors))
		{
			std::fprintf(
				stderr, "FAILED: loading %s: %s\n", argv[1], errors.c_str());
			return 1;
		}

		// The dialog reads its text box as an .ini file, section [map].
		const mrpt::config::CConfigFileMemory ini(
			mrpt::io::file_get_contents(argv[2]));
		mrpt::maps::TSetOfMetricMapInitializers initializers;
		initializers.loadFromConfigFile(ini, "map");
		mrpt::maps::CMultiMetricMap maps;
		maps.setListOfMaps(initializers);

		mrpt::maps::CMetricMap::Ptr evidential;
		for (const auto& m : maps.maps)
			if (std::string(m->GetRuntimeClass()->className) ==
				kEvidentialClass)
				evidential = m;
		if (!evidential)
		{
			std::fprintf(
				stderr, "FAILED: %s defines no %s\n", argv[2],
				kEvidentialClass);
			return 1;
		}

		mrpt::obs::CRawlog rawlog;
		if (!rawlog.loadFromRawLogFile(argv[3]) || rawlog.size() == 0)
		{
			std::fprintf(stderr, "FAILED: cannot read %s\n", argv[3]);
			return 1;
		}
		buildAlongOdometry(rawlog, maps);
		const auto points = maps.mapByClass<mrpt::maps::CSimplePointsMap>();
		std::printf(
			"maps built from %zu entries: %zu maps, points map %zu points\n",
			rawlog.size(), maps.maps.size(),
			points ? points->size() : std::size_t(0));
		std::printf("evidential map: %s\n", evidential->asString().c_str());
		if (evidential->isEmpty())
		{
			std::fprintf(
				stderr, "FAILED: the evidential map received no scan\n");
			return 1;
		}
		maps.saveMetricMapRepresentationToFile(argv[5]);

		// The map first, so that a reader without the plugin fails on it.
		const std::size_t copied =
			std::min<std::size_t>(std::stoul(argv[6]), rawlog.size());
		{
			mrpt::io::CFileGZOutputStream out(argv[4]);
			auto archive = mrpt::serialization::archiveFrom(out);
			archive << *evidential;
			for (std::size_t i = 0; i < copied; ++i)
				archive << *rawlog.getAsGeneric(i);
		}
		std::printf(
			"wrote %s: the evidential map and %zu entries\n", argv[4], copied);
		return 0;
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "FAILED: %s\n", mrpt::exception_to_str(e).c_str());
		return 1;
	}
}
