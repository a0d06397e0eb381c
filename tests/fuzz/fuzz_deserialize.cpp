/* Fuzz target: reading a serialized map. The first byte picks the mode:
 * even, the rest is the payload of a map of the current version, framed here with MRPT's
 * header, the checksum it should have and the end marker, so that mutations
 * reach the checks behind the checksum; odd, the rest is the raw stream.
 * A read may throw (std::exception); when it succeeds the map must be valid,
 * write itself back identically, take a scan and score one. Anything else,
 * or an allocation far beyond the input's size, is a finding. */
#include <mrpt/poses/CPose3D.h>

#include <exception>

#include "FuzzSupport.h"

using namespace mrpt_evidential;
using mrpt::serialization::archiveFrom;

namespace
{
/** Reads `bytes` into `map`; false when the read throws. */
bool read(const std::vector<std::uint8_t>& bytes, CEvidentialGridMap2D& map)
{
	mrpt::io::CMemoryStream in;
	if (!bytes.empty()) in.assignMemoryNotOwn(bytes.data(), bytes.size());
	try
	{
		archiveFrom(in) >> map;
	}
	catch (const std::exception&)
	{
		return false;
	}
	return true;
}
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
	fuzz::silenceMapWarnings();
	return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	if (size == 0) return 0;
	const std::vector<std::uint8_t> bytes = (data[0] & 1)
		? std::vector<std::uint8_t>(data + 1, data + size)
		: fuzz::frame(data + 1, size - 1);

	CEvidentialGridMap2D map(-1, 1, -1, 1, 0.5);
	if (!read(bytes, map)) return 0;
	fuzz::checkMap(map);

	// What was read writes back byte for byte.
	const std::vector<std::uint8_t> again = fuzz::serialize(map);
	CEvidentialGridMap2D copy;
	if (!read(again, copy)) fuzz::fail("a map that was read cannot be read back");
	if (fuzz::serialize(copy) != again) fuzz::fail("the round trip changed the map");

	// The map keeps working: one scan in its middle, at a time of today
	// (times read from a file may lie anywhere). A budget read from a file
	// is trusted as the user's setting; here it is
	// cut so that growth stays small.
	const GridGeometry& g = map.geometry();
	map.setMaxCells(std::max(g.cellCount(), std::min<std::size_t>(map.maxCells(), 1 << 20)));
	const auto scan = test::arcScan(
		91, map.insertionOptions.maxRange / 2, test::ScanSetup().at(1.7e9));
	const mrpt::poses::CPose3D pose(
		g.xMin + 0.5 * g.sizeX * g.resolution, g.yMin + 0.5 * g.sizeY * g.resolution,
		0, 0, 0, 0);
	map.insertObservation(scan, pose);
	fuzz::checkMap(map);
	if (std::isnan(map.computeObservationLikelihood(scan, pose)))
		fuzz::fail("a NaN likelihood");
	return 0;
}
