/* evgrid score-motion: the ground truth of what moves, as evgrid-simulate
 * writes it (PREFIX.motion.gz, format in rawlogs/README.md). */
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace evgrid
{
/** The truth's grid: cell (cx, cy) covers x in [x0 + cx res, x0 + (cx + 1)
 * res) and y likewise; its index is cx + sizeX cy. */
struct TTruthGrid
{
	double x0 = 0, y0 = 0, resolution = 1;
	int sizeX = 0, sizeY = 0;

	std::size_t cellCount() const
	{
		return static_cast<std::size_t>(sizeX) *
			static_cast<std::size_t>(sizeY);
	}
	/** The index of the cell holding (x, y); -1 outside the grid. */
	int cellAt(double x, double y) const;
	double centreX(int index) const
	{
		return x0 + (index % sizeX + 0.5) * resolution;
	}
	double centreY(int index) const
	{
		return y0 + (index / sizeX + 0.5) * resolution;
	}
};

/** One scan's record. */
struct TTruthScan
{
	/** Seconds from scan 0. */
	double time = 0;
	/** The cells a moving thing covers at `time`. */
	std::vector<int> occupied;
	/** The cells moving things stopped covering after the previous scan,
	 * each with the time (seconds from scan 0) it did. */
	std::vector<std::pair<int, double>> left;
};

/** A motion truth file, read whole and checked: any damage (a truncated or
 * corrupt gzip stream, a line out of place, a count that does not match its
 * items, a cell outside the grid, fewer records than announced) is an
 * error. */
class CMotionTruth
{
   public:
	/** \throws std::runtime_error "<path>: ..." (with the line where the
	 *  text is wrong). */
	static CMotionTruth load(const std::string& path);

	const std::string& path() const { return m_path; }
	const std::string& scene() const { return m_scene; }
	/** Unix time of scan 0. */
	double startTime() const { return m_start; }
	const TTruthGrid& grid() const { return m_grid; }
	/** Cells of walls and furniture. */
	const std::vector<int>& staticCells() const { return m_static; }
	const std::vector<TTruthScan>& scans() const { return m_scans; }

   private:
	class CParser;

	std::string m_path, m_scene;
	double m_start = 0;
	TTruthGrid m_grid;
	std::vector<int> m_static;
	std::vector<TTruthScan> m_scans;
};

}  // namespace evgrid
