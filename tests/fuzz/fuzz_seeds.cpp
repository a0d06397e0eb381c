/* fuzz_seeds DIR: writes seed inputs for the fuzz targets into
 * DIR/deserialize, DIR/insert, DIR/cloud and DIR/ini, from the current code, so that
 * they follow the serialization format and the input layouts. tests/fuzz/
 * corpus/ holds a copy (plus rawlogs/evgrid.ini); run_fuzzer.sh uses both. */
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <filesystem>
#include <fstream>
#include <limits>

#include "../support/clouds.h"
#include "FuzzSupport.h"

using namespace mrpt_evidential;
namespace fs = std::filesystem;

namespace
{
void save(const fs::path& file, const std::vector<std::uint8_t>& bytes)
{
	fs::create_directories(file.parent_path());
	std::ofstream(file, std::ios::binary)
		.write(reinterpret_cast<const char*>(bytes.data()),
			   static_cast<std::streamsize>(bytes.size()));
}

/** 37 beams over 180 degrees, all at `range`, taken at `time`. */
mrpt::obs::CObservation2DRangeScan wall(double range, double time)
{
	return test::arcScan(37, range, test::ScanSetup().at(time));
}

/** A serialized map as fuzz_deserialize reads it: mode 0 and the payload
 * between MRPT's header and the checksum, or mode 1 and the whole stream. */
void saveMap(const fs::path& dir, const std::string& name, const CEvidentialGridMap2D& map)
{
	const std::vector<std::uint8_t> bytes = fuzz::serialize(map);
	const std::size_t header = fuzz::mapHeader().size();
	std::vector<std::uint8_t> framed{0};
	framed.insert(framed.end(), bytes.begin() + header, bytes.end() - 9);
	save(dir / (name + ".framed"), framed);
	std::vector<std::uint8_t> raw{1};
	raw.insert(raw.end(), bytes.begin(), bytes.end());
	save(dir / (name + ".raw"), raw);
}

void deserializeSeeds(const fs::path& dir)
{
	saveMap(dir, "empty", CEvidentialGridMap2D(-1, 1, -1, 1, 0.5));
	CEvidentialGridMap2D map(-2, 2, -2, 2, 0.5);
	map.setMaxCells(4096);
	map.insertionOptions.fusionRule = FusionRule::Yager;
	map.insertionOptions.conflictHandling = ConflictHandling::ToUnknown;
	map.insertionOptions.decayRate = 0.2;
	map.insertionOptions.maxRange = 4.0;
	map.insertionOptions.growthMargin = 0.5;
	map.likelihoodOptions.decimation = 2;
	map.insertObservation(wall(1.5, 100.0), mrpt::poses::CPose3D());
	map.insertObservation(wall(2.5, 101.0), mrpt::poses::CPose3D(0.5, 0, 0, 2.0, 0, 0));
	map.insertObservation(wall(1.0, 103.5), mrpt::poses::CPose3D(0, -0.5, 0, -1.0, 0, 0));
	saveMap(dir, "three-scans", map);
}

void insertSeeds(const fs::path& dir)
{
	const float nan = std::numeric_limits<float>::quiet_NaN();
	const float inf = std::numeric_limits<float>::infinity();
	const auto write = [&](const std::string& name, fuzz::InsertCase c) {
		fuzz::Writer out;
		fuzz::visit(out, c);
		save(dir / name, out.bytes);
	};
	const auto scan = [](std::size_t n, float aperture, float range) {
		fuzz::InsertCase::Scan s;
		s.aperture = aperture;
		s.ranges.assign(n, range);
		s.valid.assign((n + 7) / 8, 0xFF);
		s.ticks = 1'000'000'000;
		return s;
	};
	fuzz::InsertCase c;
	c.scans = {scan(181, float(M_PI), 2.0f)};
	write("wall", c);

	c.scans = {scan(181, float(M_PI), 2.0f)};
	const float odd[] = {nan, inf, -inf, -1.0f, 0.0f, 1e30f, 50.0f};
	for (std::size_t i = 0; i < 181; i += 2) c.scans[0].ranges[i] = odd[(i / 2) % 7];
	c.scans[0].valid[3] = 0x0F;
	c.flags = 2;  // invalidRangesAsFree
	write("odd-ranges", c);

	c = {};
	c.scans = {scan(1, 0.2f, 1.5f), scan(1, 0.0f, 1.0f), scan(0, 0.0f, 0.0f)};
	write("one-and-no-beams", c);

	c = {};
	c.scans = {scan(360, float(2 * M_PI), 1.8f), scan(91, 1e-3f, 1.0f)};
	c.sectorWidth = 10;
	write("full-turn-and-narrow", c);

	c = {};
	c.scans = {scan(181, float(M_PI), 2.0f), scan(181, float(M_PI), 2.0f)};
	c.scans[0].rightToLeft = 0;
	c.scans[0].sensorPose[5] = float(M_PI);  // upside down
	c.scans[1].sensorPose[4] = 0.3f;  // tilted
	c.model = 2;
	c.imprecision = 10;
	write("clockwise-upside-down-tilted", c);

	c = {};
	c.scans = {scan(91, float(M_PI), 2.0f), scan(91, float(M_PI), 2.0f),
			   scan(91, float(M_PI), 2.0f), scan(91, float(M_PI), 2.0f)};
	c.scans[0].ticks = 0;
	c.scans[1].robotPose[0] = 1e6;
	c.scans[2].robotPose[1] = std::numeric_limits<double>::quiet_NaN();
	c.scans[3].robotPose[0] = 3.0;
	c.scans[3].ticks = 1'000'000'100;
	c.decay = 4;
	c.rule = 1;
	c.handling = 2;
	write("far-nan-and-decay", c);
}

void iniSeeds(const fs::path& dir)
{
	const auto write = [&](const std::string& name, const std::string& text) {
		save(dir / name, std::vector<std::uint8_t>(text.begin(), text.end()));
	};
	write("every-key.ini",
		  "[MappingApplication_evidentialGrid_00_creationOpts]\n"
		  "min_x=-5\nmax_x=7\nmin_y=-3\nmax_y=4\nresolution=0.05\nmaxCells=2e6\n"
		  "[MappingApplication_evidentialGrid_00_insertOpts]\n"
		  "sensorModel=ImpreciseMultiEcho\nmuF=0.65\nmuO=0.85\nimprecision=0.1\n"
		  "imprecisionProfile=Gaussian\nsectorWidth=2\nmaxRange=12.5\n"
		  "invalidRangesAsFree=true\nfusionRule=Yager\ndecayRate=0.05\n"
		  "horizontalTolerance=1.5\nconflictHandling=ToUnknown\ngrowthMargin=3\n"
		  "freeMargin=0.15\nmotionWindow=3\nmotionMinConflict=0.4\nmotionClearance=0.2\n"
		  "groundRemoval=Height\nminObstacleHeight=0.3\nmaxObstacleHeight=1.8\n"
		  "groundReturns=Nothing\ninsertionThreads=2\n"
		  "[MappingApplication_evidentialGrid_00_likelihoodOpts]\n"
		  "occupiedMass=0.45\nmaxCorrsDistance=0.6\nsigma=0.2\nzHit=0.8\n"
		  "zRandom=0.2\nmaxRange=30\ndecimation=3\nunknownAsNeutral=false\n"
		  "[MappingApplication_evidentialGrid_00_renderOpts]\n"
		  "style=Masses\nfreeColor=#F0F0F0\noccupiedColor=101010\nunknownColor=#808080\n"
		  "conflictColor=#B43CC8\nappearedColor=#ff8c00\ndisappearedColor=#00AAAA\n"
		  "showFree=false\nshowOccupied=true\nshowConflict=no\nshowMotion=1\n"
		  "showUnknown=yes\nheight=0.25\n");
	write("bad-values.ini",
		  "[MappingApplication_evidentialGrid_00_creationOpts]\n"
		  "min_x=20 ; above max_x\nresolution=-1e-12\nmaxCells=1e30\n"
		  "[MappingApplication_evidentialGrid_00_insertOpts]\n"
		  "muF=nan\nsensorModel=7\ndecayRate=-1e-300\nsectorWidth=400\n");
}
}  // namespace

void cloudSeeds(const fs::path& dir)
{
	const auto write = [&](const std::string& name, fuzz::CloudCase c) {
		fuzz::Writer out;
		fuzz::visit(out, c);
		save(dir / name, out.bytes);
	};
	// A street of the test factory's lidar, coarse: ground, walls, a car.
	test::TLidar lidar;
	lidar.azimuthStep = 6.0;
	const auto street = test::lidarCloud(
		{0.0, {{-20, 20, 4, 5, 0, 6}, {-20, 20, -5, -4, 0, 6}, {2, 6, 1, 2.8, 0, 1.5}}}, lidar);
	fuzz::CloudCase::Cloud cloud;
	cloud.ticks = 1'000'000'000;
	const auto& pc = *street->pointcloud;
	for (std::size_t i = 0; i < pc.size(); ++i)
	{
		float x, y, z;
		pc.getPoint(i, x, y, z);
		cloud.xyz.insert(cloud.xyz.end(), {x, y, z});
	}
	fuzz::CloudCase c;
	c.clouds = {cloud};
	write("street", c);

	// Each observation type, one upside down, odd points.
	const float nan = std::numeric_limits<float>::quiet_NaN();
	const float inf = std::numeric_limits<float>::infinity();
	fuzz::CloudCase::Cloud odd = cloud;
	odd.xyz.resize(60);
	odd.xyz.insert(odd.xyz.end(), {nan, 0, 0, 1, inf, 0, 0, 0, 0, 0.001f, 0, 0, 1e30f, 1e30f, -1e30f});
	c.clouds = {odd, odd, odd};
	for (std::uint8_t t = 0; t < 3; ++t) c.clouds[t].type = t;
	c.clouds[1].sensorPose[5] = static_cast<float>(M_PI);
	c.removal = 0;
	write("odd-points-every-type", c);

	c = {};
	c.clouds = {cloud, {}};
	c.clouds[0].robotPose[5] = M_PI;  // the robot upside down
	c.removal = 2;
	c.returns = 1;
	write("upside-down-and-empty", c);
}

int main(int argc, char** argv)
{
	if (argc != 2)
	{
		std::fprintf(stderr, "usage: fuzz_seeds DIR\n");
		return 2;
	}
	const fs::path dir = argv[1];
	deserializeSeeds(dir / "deserialize");
	insertSeeds(dir / "insert");
	cloudSeeds(dir / "cloud");
	iniSeeds(dir / "ini");
	return 0;
}
