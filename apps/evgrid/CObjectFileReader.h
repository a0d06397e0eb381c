/* evgrid: reading the MRPT objects of a file one at a time. */
#pragma once

#include <mrpt/serialization/CSerializable.h>

#include <cstdint>
#include <memory>
#include <string>

namespace evgrid
{
/** Reads the serialized MRPT objects stored one after the other in a file
 * (a rawlog, a simplemap, a saved map), plain or gzip-compressed, without
 * loading the whole file.
 *
 * MRPT's CRawlog::getActionObservationPairOrObservation returns false both at
 * the end of a rawlog and on an error, so a truncated or corrupted rawlog
 * would pass for a shorter one. This reader keeps zlib's own error state and
 * the offset of every object, and tells a clean end of file from one that
 * stops inside an object or inside the compressed stream. */
class CObjectFileReader
{
   public:
	/** \throws std::runtime_error naming `path` if it cannot be opened. */
	explicit CObjectFileReader(const std::string& path);
	~CObjectFileReader();
	CObjectFileReader(const CObjectFileReader&) = delete;
	CObjectFileReader& operator=(const CObjectFileReader&) = delete;

	/** The next object, or nullptr at the clean end of the file.
	 * \throws std::runtime_error "<path>: entry K at byte N: <why>" if the file
	 *  ends inside an object, its compressed data is damaged, or the bytes are
	 *  not an MRPT object. */
	mrpt::serialization::CSerializable::Ptr next();

	/** Index (from 0) of the object next() returned last. */
	std::size_t entryIndex() const { return m_entry - 1; }
	/** Share of the file's bytes read so far, in [0, 1] (compressed bytes
	 * for a compressed file). */
	double fractionRead() const;
	bool isCompressed() const;

   private:
	class CZlibArchive;
	[[noreturn]] void fail(const std::string& why) const;

	std::string m_path;
	std::uint64_t m_fileSize = 0;
	std::unique_ptr<CZlibArchive> m_archive;
	/** Number of objects started (the next one has index m_entry). */
	std::size_t m_entry = 0;
	/** Offset of the object being read, in the decompressed data. */
	std::uint64_t m_entryOffset = 0;
};

}  // namespace evgrid
