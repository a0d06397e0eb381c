/* evgrid: reading the MRPT objects of a file one at a time. */

#include "CObjectFileReader.h"

#include <mrpt/system/os.h>

#include <mrpt/serialization/CArchive.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <limits>
#include <new>
#include <stdexcept>
#include <vector>

#include "CommandLine.h"
#include "GzipFile.h"

namespace evgrid
{
/** A read-only MRPT archive over zlib's gz reader, which reads plain files
 * as they are. It records what stopped a read short: MRPT turns every
 * exception raised inside an object into the same "EOF" message, so the cause
 * must be kept aside. */
class CObjectFileReader::CZlibArchive : public mrpt::serialization::CArchive
{
   public:
	explicit CZlibArchive(gzFile f) : m_f(f) {}
	~CZlibArchive() override { gzclose(m_f); }

	/** The next byte without consuming it; -1 at the end or on an error. */
	int peek()
	{
		const int c = gzgetc(m_f);
		if (c >= 0) gzungetc(c, m_f);
		return c;
	}
	/** zlib's error state: Z_OK, Z_BUF_ERROR (compressed data ends early) or
	 * an error code, with its message. */
	int zlibError(std::string& message) const
	{
		int code = Z_OK;
		message = gzerror(m_f, &code);
		return code;
	}
	std::uint64_t decompressedOffset() const
	{
		return static_cast<std::uint64_t>(gztell(m_f));
	}
	std::uint64_t fileOffset() const
	{
		return static_cast<std::uint64_t>(gzoffset(m_f));
	}
	bool isDirect() const { return gzdirect(m_f) != 0; }

	/** Whether a read came short since beginEntry(). */
	bool hitEnd() const { return m_hitEnd; }
	/** Before an entry is read: clears hitEnd() and starts keeping the
	 * entry's first bytes (MRPT's object header: 0x80 | the class name's
	 * length, then the name). */
	void beginEntry()
	{
		m_hitEnd = false;
		m_head.clear();
	}
	/** The class the entry's header names, or "" if not read that far. */
	std::string entryClass() const
	{
		if (m_head.empty() || (m_head[0] & 0x80) == 0) return "";
		const std::size_t length = m_head[0] & 0x7F;
		if (m_head.size() < 1 + length) return "";
		return std::string(m_head.begin() + 1, m_head.begin() + 1 + static_cast<std::ptrdiff_t>(length));
	}

   protected:
	std::size_t write(const void*, std::size_t) override
	{
		throw std::logic_error("CObjectFileReader: the archive is read-only");
	}
	std::size_t read(void* buf, std::size_t len) override
	{
		auto* bytes = static_cast<char*>(buf);
		std::size_t done = 0;
		while (done < len)
		{
			const auto chunk = static_cast<unsigned>(std::min<std::size_t>(
				len - done, std::numeric_limits<int>::max()));
			const int n = gzread(m_f, bytes + done, chunk);
			if (n <= 0) break;
			done += static_cast<std::size_t>(n);
		}
		// Whole or nothing: MRPT takes a short read for a complete one as
		// long as it holds a byte, which would leave a field half read.
		if (done == len)
		{
			const std::size_t keep = std::min(len, kHeadBytes - std::min(kHeadBytes, m_head.size()));
			m_head.insert(m_head.end(), bytes, bytes + keep);
			return done;
		}
		m_hitEnd = true;
		return 0;
	}

   private:
	gzFile m_f;
	bool m_hitEnd = false;
	/** The longest object header: a length byte and 127 characters. */
	static constexpr std::size_t kHeadBytes = 128;
	std::vector<unsigned char> m_head;
};

CObjectFileReader::CObjectFileReader(const std::string& path)
	: CObjectFileReader(path, Check::None)
{
	checkInBoundedChild();
}

CObjectFileReader::CObjectFileReader(const std::string& path, Check)
	: m_path(path)
{
	// The input is read twice (checked in a child first), which a pipe's
	// data cannot be: the second reading would find it empty.
	namespace fs = std::filesystem;
	std::error_code ec;
	const fs::file_status status = fs::status(path, ec);
	if (!ec && fs::exists(status) && !fs::is_regular_file(status) &&
		!fs::is_directory(status))
		throw std::runtime_error(
			path +
			": not a regular file (a pipe or a device); evgrid reads its input "
			"twice, so save the data to a file first");
	gzFile f = openGzipForReading(path);
	m_archive = std::make_unique<CZlibArchive>(f);
	m_fileSize = fs::file_size(path, ec);
	if (ec) m_fileSize = 0;
}

CObjectFileReader::~CObjectFileReader() = default;

namespace
{
/** What the checking child sends before each entry, and once more with
 * kFailed and the length of the message that follows when one fails. */
struct TChildRecord
{
	static constexpr std::uint64_t kFailed = ~std::uint64_t(0);
	std::uint64_t entry = 0, offset = 0;
};

bool writeAll(int fd, const void* data, std::size_t size)
{
	const auto* bytes = static_cast<const char*>(data);
	while (size > 0)
	{
		const ssize_t n = ::write(fd, bytes, size);
		if (n <= 0) return false;
		bytes += n;
		size -= static_cast<std::size_t>(n);
	}
	return true;
}

bool readAll(int fd, void* data, std::size_t size)
{
	auto* bytes = static_cast<char*>(data);
	while (size > 0)
	{
		const ssize_t n = ::read(fd, bytes, size);
		if (n <= 0) return false;
		bytes += n;
		size -= static_cast<std::size_t>(n);
	}
	return true;
}

std::uint64_t addressSpaceBytes()
{
	std::ifstream statm("/proc/self/statm");
	std::uint64_t pages = 0;
	statm >> pages;
	return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

}  // namespace

void CObjectFileReader::checkEntries(const std::string& path, int fd)
{
	std::string message;
	try
	{
		CObjectFileReader reader(path, Check::None);
		for (TChildRecord r;; ++r.entry)
		{
			r.offset = reader.nextOffset();
			if (!writeAll(fd, &r, sizeof(r))) _exit(1);
			if (!reader.next()) _exit(0);
		}
	}
	catch (const std::exception& e)
	{
		message = e.what();
	}
	const TChildRecord failed{TChildRecord::kFailed, message.size()};
	writeAll(fd, &failed, sizeof(failed));
	writeAll(fd, message.data(), message.size());
	_exit(0);
}

void CObjectFileReader::checkInBoundedChild() const
{
	int fds[2];
	if (pipe(fds) != 0)
		throw std::runtime_error(m_path + ": cannot check the file: pipe(): " + std::strerror(errno));
	const std::uint64_t budget = kBudgetBaseBytes + kBudgetPerFileByte * m_fileSize;
	std::fflush(nullptr);
	const pid_t pid = fork();
	if (pid < 0)
		throw std::runtime_error(m_path + ": cannot check the file: fork(): " + std::strerror(errno));
	if (pid == 0)
	{
		::close(fds[0]);
		// Quiet, without core dumps, and refused any allocation beyond the
		// budget (MRPT then dies on the null it gets, which the parent sees).
		const int devNull = ::open("/dev/null", O_WRONLY);
		if (devNull >= 0)
		{
			dup2(devNull, STDOUT_FILENO);
			dup2(devNull, STDERR_FILENO);
		}
		const rlimit noCore{0, 0};
		setrlimit(RLIMIT_CORE, &noCore);
		const rlim_t cap = addressSpaceBytes() + budget;
		const rlimit capped{cap, cap};
		setrlimit(RLIMIT_AS, &capped);
		checkEntries(m_path, fds[1]);
	}
	::close(fds[1]);
	TChildRecord last, r;
	std::string message;
	bool failed = false;
	while (readAll(fds[0], &r, sizeof(r)))
	{
		if (r.entry == TChildRecord::kFailed)
		{
			message.resize(r.offset);
			failed = readAll(fds[0], message.data(), message.size());
			break;
		}
		last = r;
	}
	::close(fds[0]);
	int status = 0;
	while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
	{
	}
	if (failed) throw std::runtime_error(message);
	if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
	std::ostringstream why;
	why << m_path << ": entry " << last.entry << " at byte " << last.offset
		<< (isCompressed() ? " of the decompressed data" : "")
		<< ": reading it took more memory than a file of " << m_fileSize
		<< " bytes can justify (" << budget / (1 << 20)
		<< " MB): a size in it is corrupted";
	if (WIFSIGNALED(status)) why << " (MRPT stopped with signal " << WTERMSIG(status) << ")";
	throw std::runtime_error(why.str());
}

bool CObjectFileReader::isCompressed() const { return !m_archive->isDirect(); }

double CObjectFileReader::fractionRead() const
{
	if (m_fileSize == 0) return 0.0;
	return std::min(
		1.0, static_cast<double>(m_archive->fileOffset()) /
			static_cast<double>(m_fileSize));
}

void CObjectFileReader::fail(const std::string& why) const
{
	// A damaged file can put any byte into a class name quoted here.
	std::string printable = why;
	for (char& c : printable)
		if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
	throw std::runtime_error(
		m_path + ": entry " + std::to_string(m_entry) + " at byte " +
		std::to_string(m_entryOffset) +
		(isCompressed() ? " of the decompressed data" : "") + ": " + printable);
}

std::uint64_t CObjectFileReader::nextOffset() const
{
	return m_archive->decompressedOffset();
}

mrpt::serialization::CSerializable::Ptr CObjectFileReader::next()
{
	m_entryOffset = m_archive->decompressedOffset();
	std::string zlibMessage;
	if (m_archive->peek() < 0)
	{
		switch (m_archive->zlibError(zlibMessage))
		{
			case Z_OK: return nullptr;  // the clean end
			case Z_BUF_ERROR:
				fail("the compressed data stops early (truncated file?)");
			default:
				fail("cannot read the file: " + zlibMessage);
		}
	}

	m_archive->beginEntry();
	// MRPT changed this class's stream under the same version (2.11.4): a
	// file of the other release fails inside it, with a size or an end
	// that looks like damage.
	const auto otherRelease = [this] {
		return m_archive->entryClass().find("RotatingScan") == std::string::npos
			? std::string()
			: " (a CObservationRotatingScan, whose stream differs between MRPT 2.5.8 and "
			  "2.14: written by the other one?)";
	};
	try
	{
		auto object = m_archive->ReadObject();
		if (!object) fail("a null object where data was expected");
		++m_entry;
		return object;
	}
	catch (const std::bad_alloc&)
	{
		fail("a size beyond the memory available (corrupted data?)" + otherRelease());
	}
	catch (const std::exception& e)
	{
		const int code = m_archive->zlibError(zlibMessage);
		if (code != Z_OK && code != Z_BUF_ERROR)
			fail("damaged compressed data: " + zlibMessage);
		if (m_archive->hitEnd())
			fail("the file ends inside this entry (truncated file?)" + otherRelease());
		const std::string cause = describe(e);
		if (cause.find("which is not registered") != std::string::npos)
			fail(
				"an object of a class evgrid does not know (" + cause +
				"): written by a newer MRPT or needing another library?");
		// Our map names itself when its own data are bad (a checksum, a
		// budget): that is the reason, whichever entry it is.
		if (cause.rfind("CEvidentialGridMap2D: ", 0) == 0) fail(cause);
		// A class this MRPT knows, in a newer format of it (a simplemap of
		// MRPT 2.14 read with 2.5.8): whichever entry, say so.
		if (cause.find("unknown serialization version") != std::string::npos)
			fail(
				"an object in a format that " + mrpt::system::MRPT_getVersion() +
				" cannot read (" + cause + "): written by a newer MRPT?");
		// The first bytes of a file that is not MRPT's make a garbage
		// header, and MRPT's complaint about it would only confuse.
		if (m_entry == 0 && otherRelease().empty())
			fail("not a rawlog, simplemap or map saved by MRPT");
		// MRPT reports any failure inside an object as this "EOF", which here
		// (the end was not reached) it is not.
		if (cause.find("Cannot read object due to EOF") != std::string::npos)
			fail("corrupted data: the entry does not parse" + otherRelease());
		fail("corrupted data (" + cause + ")" + otherRelease());
	}
}

}  // namespace evgrid
