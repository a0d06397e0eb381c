/* evgrid: an output folder whose files change only when a run succeeds. */
#pragma once

#include <string>
#include <vector>

namespace evgrid
{
/** The output folder of `evgrid build`. Everything a run writes goes first
 * into a hidden staging folder inside it (same file system, so a rename is
 * atomic); commit() then moves each old entry aside and the staged one
 * into its place, files and folders (frames/) alike. A run that
 * fails before commit() leaves the folder as it was: the destructor removes
 * the staging folder. */
class COutputFolder
{
   public:
	/** Creates `dir` if needed and the staging folder in it.
	 * \throws std::runtime_error naming `dir` if either cannot be created or
	 *  written: the check that the output can be written, done before any
	 *  work. */
	explicit COutputFolder(const std::string& dir);
	~COutputFolder();
	COutputFolder(const COutputFolder&) = delete;
	COutputFolder& operator=(const COutputFolder&) = delete;

	/** Where to write `name` (a file, or a folder such as "frames") during
	 * the run. */
	std::string staged(const std::string& name) const;
	/** The staging folder itself. */
	const std::string& stagingFolder() const { return m_staging; }
	/** The final path of `name`. */
	std::string final(const std::string& name) const;

	/** Moves the staged entries `names` into place, in that order (put the
	 * file that marks a complete run last), then removes the staging folder
	 * with the entries they replaced. Names not staged are skipped. All or
	 * nothing: when an entry cannot be moved, those moved are put back.
	 * \throws std::runtime_error naming the entry that cannot be replaced
	 *  (a folder where a file goes, or the reverse, before any moves), or
	 *  before moving any if a stop was requested (throwIfStopRequested()). */
	void commit(const std::vector<std::string>& names);

   private:
	std::string m_dir, m_staging;
};

}  // namespace evgrid
