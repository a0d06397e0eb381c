/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include <mrpt_evidential/support/AtomicFile.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <system_error>

namespace fs = std::filesystem;

namespace mrpt_evidential::detail
{
namespace
{
/** A fresh temporary name next to `path`: the same directory keeps the final
 * rename within one file system (where it is atomic), the same extension
 * lets savers infer the format, the leading dot keeps it out of globs, and a
 * per-process random tag plus a counter keep concurrent writers apart. */
std::string temporaryPathFor(const std::string& path)
{
	static const unsigned processTag = std::random_device{}();
	static std::atomic<unsigned long> counter{0};
	const fs::path p(path);
	fs::path tmp = p;
	tmp.replace_filename(
		"." + p.stem().string() + ".tmp-" + std::to_string(processTag) + "-" +
		std::to_string(counter++) + p.extension().string());
	return tmp.string();
}

/** Removes the temporary file (if any) and reports the failure. */
[[noreturn]] void fail(
	const std::string& path, const std::string& temporaryPath,
	const std::string& why)
{
	std::error_code ignored;
	fs::remove(temporaryPath, ignored);
	throw std::runtime_error("cannot write '" + path + "': " + why);
}

/** Where the file `path` names lies: `path` itself, or the file a symbolic
 * link leads to (renaming over the link would replace the link, not the
 * file). \throws std::runtime_error when that is not a regular file (a
 * device such as /dev/null, a pipe, a socket): renaming over it would put a
 * plain file in its place, which as root replaces a system device. */
std::string fileBehind(const std::string& path)
{
	std::error_code ec;
	const fs::file_status status = fs::status(path, ec);
	if (!fs::exists(status)) return path;
	if (fs::is_directory(status))
		throw std::runtime_error("cannot write '" + path + "': it is a folder");
	if (!fs::is_regular_file(status))
		throw std::runtime_error(
			"cannot write '" + path +
			"': it is not a regular file (a device, a pipe or a socket); give a file");
	if (!fs::is_symlink(fs::symlink_status(path, ec))) return path;
	const fs::path target = fs::canonical(path, ec);
	if (ec) throw std::runtime_error("cannot write '" + path + "': " + ec.message());
	return target.string();
}
}  // namespace

void CAtomicFileSet::addByName(
	const std::string& requestedPath,
	const std::function<bool(const std::string& temporaryPath)>& writer)
{
	const std::string path = fileBehind(requestedPath);
	const std::string tmp = temporaryPathFor(path);
	bool written = false;
	try
	{
		written = writer(tmp);
	}
	catch (const std::exception& e)
	{
		fail(path, tmp, e.what());
	}
	catch (...)
	{
		std::error_code ignored;
		fs::remove(tmp, ignored);
		throw;
	}
	if (!written) fail(path, tmp, "writing the temporary file '" + tmp + "' failed");
	std::error_code ec;
	if (!fs::is_regular_file(tmp, ec))
		fail(path, tmp, "the temporary file '" + tmp + "' was not created");
	m_staged.push_back({path, tmp});
}

void CAtomicFileSet::add(
	const std::string& path, const std::function<void(std::ostream&)>& writer)
{
	addByName(path, [&writer](const std::string& tmp) {
		errno = 0;
		std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
		if (!f)
			throw std::runtime_error(
				"cannot create the temporary file '" + tmp +
				"': " + (errno != 0 ? std::strerror(errno) : "unknown error"));
		writer(f);
		f.close();	// flushes; a failed flush or close sets failbit
		return !f.fail();
	});
}

void CAtomicFileSet::commit()
{
	for (std::size_t i = 0; i < m_staged.size(); ++i)
	{
		std::error_code ec;
		fs::rename(m_staged[i].temporaryPath, m_staged[i].path, ec);
		if (ec)
		{
			const TStaged failed = m_staged[i];
			m_staged.erase(m_staged.begin(), m_staged.begin() + static_cast<std::ptrdiff_t>(i + 1));
			fail(failed.path, failed.temporaryPath,
				 "renaming '" + failed.temporaryPath + "' failed: " + ec.message());
		}
	}
	m_staged.clear();
}

CAtomicFileSet::~CAtomicFileSet()
{
	for (const TStaged& s : m_staged)
	{
		std::error_code ignored;
		fs::remove(s.temporaryPath, ignored);
	}
}

void writeFileAtomicallyByName(
	const std::string& path,
	const std::function<bool(const std::string& temporaryPath)>& writer)
{
	CAtomicFileSet one;
	one.addByName(path, writer);
	one.commit();
}

void writeFileAtomically(
	const std::string& path, const std::function<void(std::ostream&)>& writer)
{
	CAtomicFileSet one;
	one.add(path, writer);
	one.commit();
}

}  // namespace mrpt_evidential::detail
