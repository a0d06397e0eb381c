/* Shared by the map tests and the fuzz targets: a map to and from the bytes
 * of its MRPT serialization. */
#pragma once

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

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

/** Reads a map from bytes into `map`; throws as the archive does. */
inline void deserialize(
	const std::vector<std::uint8_t>& bytes, CEvidentialGridMap2D& map)
{
	mrpt::io::CMemoryStream buf;
	if (!bytes.empty()) buf.assignMemoryNotOwn(bytes.data(), bytes.size());
	mrpt::serialization::archiveFrom(buf) >> map;
}
}  // namespace mrpt_evidential::test
