/* mrpt-evidential: internal: files written under a temporary name, then renamed. */
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace mrpt_evidential::detail
{
/** Writes the file `path` so that a reader sees either its previous content
 * or the complete new one, never a partial file: `writer` writes into a
 * temporary file of the same directory, which is flushed, closed and renamed
 * over `path` only if every step succeeded. The stream is binary. When
 * `path` is a symbolic link, the file it leads to is replaced (the link
 * stays).
 * \throws std::runtime_error naming `path` if it exists and is no regular
 *  file (a device, a pipe: renaming over it would replace it), if the
 *  temporary file cannot be created, written, closed or renamed, or if
 *  `writer` throws a std::exception (its message is kept). The temporary
 *  file is removed in every failure case. */
void writeFileAtomically(
	const std::string& path, const std::function<void(std::ostream&)>& writer);

/** As writeFileAtomically(), for writers that want a file name rather than
 * a stream (e.g. image savers that pick the format from the extension): the
 * temporary name given to `writer` ends with the same extension as `path`.
 * `writer` returns false (or throws) on failure.
 * \throws std::runtime_error naming `path` on any failure, also when `writer`
 *  reports success without creating the file. */
void writeFileAtomicallyByName(
	const std::string& path,
	const std::function<bool(const std::string& temporaryPath)>& writer);

/** Several files replaced together, so that a failure leaves the previous
 * files as they were rather than some new and some old: each is written
 * under a temporary name first (the rules of writeFileAtomically()), and
 * commit() renames them all once every one is written. A set destroyed
 * before commit() removes its temporary files. */
class CAtomicFileSet
{
   public:
	CAtomicFileSet() = default;
	CAtomicFileSet(const CAtomicFileSet&) = delete;
	CAtomicFileSet& operator=(const CAtomicFileSet&) = delete;
	~CAtomicFileSet();

	/** Writes what will replace `path`, as writeFileAtomicallyByName().
	 * \throws std::runtime_error as writeFileAtomicallyByName() (this
	 *  file's temporary is removed; those of the others stay, for the
	 *  destructor). */
	void addByName(
		const std::string& path,
		const std::function<bool(const std::string& temporaryPath)>& writer);
	/** Writes what will replace `path`, as writeFileAtomically(). */
	void add(const std::string& path, const std::function<void(std::ostream&)>& writer);
	/** Renames every file into place, in the order they were added.
	 * \throws std::runtime_error naming the file if a rename fails (the
	 *  files renamed before it stay replaced; the others are removed). */
	void commit();

   private:
	struct TStaged
	{
		std::string path, temporaryPath;
	};
	std::vector<TStaged> m_staged;
};

}  // namespace mrpt_evidential::detail
