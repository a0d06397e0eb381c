/* Shared by the map tests and the fuzz targets: a map to and from the bytes
 * of its MRPT serialization, and the checksum the map writes over them. */
#pragma once

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mrpt_evidential::test
{
inline std::vector<std::uint8_t> serialize(const CEvidentialGridMap2D& map)
{
	mrpt::io::CMemoryStream buf;
	mrpt::serialization::archiveFrom(buf) << map;
	const auto* p = static_cast<const std::uint8_t*>(buf.getRawBufferData());
	return {p, p + buf.getTotalBytesCount()};
}

/** The checksum the map writes after its payload (the bytes between MRPT's
 * object header and the checksum): FNV-1a, 64 bit. */
inline std::uint64_t payloadChecksum(const std::uint8_t* payload, std::size_t size)
{
	std::uint64_t h = 0xcbf29ce484222325ULL;
	for (std::size_t i = 0; i < size; ++i) h = (h ^ payload[i]) * 0x100000001b3ULL;
	return h;
}

/** Reads a map from bytes into `map`; throws as the archive does. */
inline void deserialize(
	const std::vector<std::uint8_t>& bytes, CEvidentialGridMap2D& map)
{
	mrpt::io::CMemoryStream buf;
	if (!bytes.empty()) buf.assignMemoryNotOwn(bytes.data(), bytes.size());
	mrpt::serialization::archiveFrom(buf) >> map;
}
}  // namespace mrpt_evidential::test
