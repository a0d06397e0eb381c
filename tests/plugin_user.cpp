/* A program that knows nothing of mrpt-evidential but its name: it links MRPT
 * only, loads the plugin at run time (as stock MRPT programs do), and uses the
 * evidential map through MRPT's interfaces. Exits non-zero on a failure.
 * Usage: plugin_user <path to libmrpt_evidential.so> <scratch dir> */
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/system/os.h>

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <string>

namespace
{
int failures = 0;
void check(bool ok, const std::string& what)
{
	std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
	if (!ok) ++failures;
}

const mrpt::maps::CMetricMap* evidentialMapOf(const mrpt::maps::CMultiMetricMap& maps)
{
	for (const auto& m : maps.maps)
		if (std::string(m->GetRuntimeClass()->className) ==
			"mrpt_evidential::CEvidentialGridMap2D")
			return m.get();
	return nullptr;
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc != 3)
	{
		std::fprintf(stderr, "usage: %s <plugin.so> <scratch dir>\n", argv[0]);
		return 2;
	}
	std::string errors;
	check(mrpt::system::loadPluginModule(argv[1], errors), "plugin loads " + errors);

	mrpt::config::CConfigFileMemory ini(R"ini(
[Maps]
evidentialGrid_count=1
[Maps_evidentialGrid_00_creationOpts]
resolution=0.1
[Maps_evidentialGrid_00_insertOpts]
sensorModel=ReinforcedMultiEcho
maxRange=30
)ini");
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(ini, "Maps");
	mrpt::maps::CMultiMetricMap maps;
	maps.setListOfMaps(inits);
	const mrpt::maps::CMetricMap* map = evidentialMapOf(maps);
	check(map != nullptr, "evidentialGrid created from the .ini");
	if (!map) return 1;

	mrpt::maps::CSimpleMap simplemap;
	check(
		simplemap.loadFromFile(
			std::string(MRPT_DATASETS_DIR) + "/malaga-cs-fac-building.simplemap.gz"),
		"malaga simplemap read");
	maps.loadFromSimpleMap(simplemap);
	check(!map->isEmpty(), "scans inserted: " + map->asString());

	// Score a scan at its own pose and 0.5 m away.
	// Iterated, a keyframe has `pose` and `sf` in MRPT 2.5 (Pair) and 2.14
	// (Keyframe) alike; get() returns a tuple in 2.5, a Keyframe in 2.14.
	const auto& keyframe = *std::next(
		simplemap.begin(), static_cast<std::ptrdiff_t>(simplemap.size() / 2));
	const auto scan = keyframe.sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
	const mrpt::poses::CPose3D pose = keyframe.pose->getMeanVal();
	const double atPose = map->computeObservationLikelihood(*scan, pose);
	const double away = map->computeObservationLikelihood(
		*scan, pose + mrpt::poses::CPose3D(0.5, 0, 0, 0, 0, 0));
	check(atPose > away, "likelihood " + std::to_string(atPose) + " > " + std::to_string(away));

	const std::string prefix = std::string(argv[2]) + "/plugin_user";
	std::filesystem::create_directories(argv[2]);
	map->saveMetricMapRepresentationToFile(prefix);
	for (const char* suffix :
		 {"_evidential.png", "_betp.png", "_conflict.png", "_info.txt", ".evgrid"})
		check(
			std::filesystem::file_size(prefix + suffix) > 0,
			std::string("wrote ") + prefix + suffix);

	// A CMultiMetricMap copies its maps through an archive.
	const mrpt::maps::CMultiMetricMap copy = maps;
	const mrpt::maps::CMetricMap* copied = evidentialMapOf(copy);
	check(copied && copied != map, "copy holds its own evidential map");
	check(copied && copied->asString() == map->asString(), "copy has the same cells");
	check(
		copied && copied->computeObservationLikelihood(*scan, pose) == atPose,
		"copy scores the same");

	std::printf("%s\n", failures ? "plugin_user: FAILED" : "plugin_user: all good");
	return failures ? 1 : 0;
}
