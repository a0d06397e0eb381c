/* Shared by the map tests and the fuzz targets: a map to and from the bytes
 * of its MRPT serialization, the checksum the map writes over them, and the
 * means of a forger who edits such bytes. */
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

/** Where the version byte of a serialized map lies: MRPT's object header is
 * 0x80 | the class name's length, the class name, the version. */
inline std::size_t versionPosition(const std::vector<std::uint8_t>& bytes)
{
	return 1 + (bytes[0] & 0x7F);
}
/** Where the map's payload (its geometry first) begins: after the header. */
inline std::size_t payloadStart(const std::vector<std::uint8_t>& bytes)
{
	return versionPosition(bytes) + 1;
}
/** Where the checksum lies: before MRPT's one-byte end marker. */
inline std::size_t checksumPosition(const std::vector<std::uint8_t>& bytes)
{
	return bytes.size() - 9;
}
/** Where the first of the map's `cells` 8-byte cells lies: the cells come
 * last, before the checksum. */
inline std::size_t firstCellPosition(const std::vector<std::uint8_t>& bytes, std::size_t cells)
{
	return checksumPosition(bytes) - 8 * cells;
}

/** Writes the checksum a stream's payload should have, as a forger would:
 * over everything between MRPT's header and the checksum. */
inline void reseal(std::vector<std::uint8_t>& bytes)
{
	const std::size_t begin = payloadStart(bytes), end = checksumPosition(bytes);
	const std::uint64_t h = payloadChecksum(bytes.data() + begin, end - begin);
	for (int i = 0; i < 8; ++i) bytes[end + i] = static_cast<std::uint8_t>(h >> (8 * i));
}

/** Puts the n low bytes of v at `at`, little-endian. */
inline void putLE(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint64_t v, int n)
{
	for (int i = 0; i < n; ++i) bytes[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}
}  // namespace mrpt_evidential::test
