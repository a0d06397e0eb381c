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
 * stops inside an object or inside the compressed stream.
 *
 * MRPT allocates what a count in the data claims before it reads the data
 * (CObservation2DRangeScan: 13 bytes per claimed ray), and dereferences null
 * when the allocation is refused. So that no count the file cannot justify
 * reaches this process, the constructor first reads the whole file in a
 * child process whose address space may grow by at most
 * kBudgetBaseBytes + kBudgetPerFileByte x the file's size; reads hand MRPT
 * whole fields or nothing, so a cut never leaves a count half read. */
class CObjectFileReader
{
   public:
	/** Memory a file of S bytes may make MRPT allocate while it is read:
	 * kBudgetBaseBytes + kBudgetPerFileByte S. */
	static constexpr std::uint64_t kBudgetBaseBytes = std::uint64_t(256) << 20;
	static constexpr std::uint64_t kBudgetPerFileByte = 64;

	/** Opens `path` and reads it once, whole, in a bounded child process.
	 * \throws std::runtime_error naming `path` if it cannot be opened, and
	 *  as next() would for the first entry that does not read, including
	 *  "entry K at byte N: ... more memory than ..." for one that needs more
	 *  than the budget. */
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
	enum class Check
	{
		InChild,
		None
	};
	CObjectFileReader(const std::string& path, Check check);
	/** Reads every entry in a child process under the memory budget and
	 * throws what the child met. */
	void checkInBoundedChild() const;
	/** In that child: reads every entry and reports through `fd`. */
	[[noreturn]] static void checkEntries(const std::string& path, int fd);
	/** Offset of the next entry in the decompressed data. */
	std::uint64_t nextOffset() const;
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
