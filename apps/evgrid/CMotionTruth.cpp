/* evgrid score-motion: the ground truth of what moves, as evgrid-simulate
 * writes it (PREFIX.motion.gz, format in rawlogs/README.md). */

#include "CMotionTruth.h"
#include "GzipFile.h"

#include <zlib.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string_view>

namespace evgrid
{
namespace
{
/** The files are about 1 MB decompressed; this guards against a damaged or
 * foreign file that decompresses without end. */
constexpr std::size_t kMaxBytes = std::size_t(1) << 30;
/** Likewise for the grid's cells (the room's scenes have 48,600, the
 * street's a few million); the scorer keeps some 16 bytes a cell. */
constexpr long kMaxCells = 20'000'000;
/** A truth cell's side: the simulator writes 0.05 m. */
constexpr double kMinResolution = 1e-3, kMaxResolution = 10.0;

/** The whole decompressed text (zlib reads a plain file as it is). */
std::string readAll(const std::string& path)
{
	gzFile f = openGzipForReading(path);
	std::string text;
	char buffer[1 << 16];
	int n = 0;
	while ((n = gzread(f, buffer, sizeof(buffer))) > 0 &&
		   text.size() <= kMaxBytes)
		text.append(buffer, static_cast<std::size_t>(n));
	int code = Z_OK;
	std::string message = gzerror(f, &code);
	gzclose(f);
	// zlib's message starts with the path.
	if (message.rfind(path + ": ", 0) == 0) message.erase(0, path.size() + 2);
	if (text.size() > kMaxBytes)
		throw std::runtime_error(path + ": more than 1 GiB of text");
	if (code == Z_BUF_ERROR)
		throw std::runtime_error(
			path + ": the compressed data stops early (truncated file?)");
	if (n < 0 || (code != Z_OK && code != Z_STREAM_END))
		throw std::runtime_error(path + ": cannot read the file: " + message);
	return text;
}

std::vector<std::string_view> splitWords(std::string_view line)
{
	std::vector<std::string_view> words;
	std::size_t start = 0;
	while (start <= line.size())
	{
		const std::size_t end = std::min(line.find(' ', start), line.size());
		words.push_back(line.substr(start, end - start));
		start = end + 1;
	}
	return words;
}
}  // namespace

int TTruthGrid::cellAt(double x, double y) const
{
	const double fx = std::floor((x - x0) / resolution);
	const double fy = std::floor((y - y0) / resolution);
	if (!(fx >= 0 && fx < sizeX && fy >= 0 && fy < sizeY)) return -1;
	return static_cast<int>(fx) + sizeX * static_cast<int>(fy);
}

/** Reads the text line by line; every failure names the file and line. */
class CMotionTruth::CParser
{
   public:
	CParser(const std::string& path, const std::string& text)
		: m_path(path), m_text(text)
	{
	}

	CMotionTruth parse()
	{
		CMotionTruth t;
		t.m_path = m_path;
		if (nextLine() != "evgrid-simulate motion 1")
			fail(
				"not an evgrid-simulate motion file of version 1 (its first "
				"line is not 'evgrid-simulate motion 1')");
		t.m_scene = std::string(expect("scene", 2)[1]);
		t.m_start = number(expect("start", 2)[1], "the start time");
		const auto g = expect("grid", 6);
		t.m_grid.x0 = number(g[1], "X0");
		t.m_grid.y0 = number(g[2], "Y0");
		t.m_grid.resolution = number(g[3], "RES");
		if (!(t.m_grid.resolution >= kMinResolution && t.m_grid.resolution <= kMaxResolution))
			fail("RES must be in [0.001, 10] m");
		t.m_grid.sizeX = static_cast<int>(whole(g[4], "NX", 1, kMaxCells));
		t.m_grid.sizeY = static_cast<int>(whole(g[5], "NY", 1, kMaxCells));
		if (static_cast<long>(t.m_grid.cellCount()) > kMaxCells)
			fail("a grid of more than 2e7 cells");
		m_cells = static_cast<long>(t.m_grid.cellCount());
		const long scans =
			whole(expect("scans", 2)[1], "the scan count", 0, 100'000'000);
		if (!(number(expect("sample", 2)[1], "the sample period") > 0))
			fail("the sample period must be > 0");
		t.m_static = cells(expect("static"), nullptr);

		for (long k = 0; k < scans; ++k)
		{
			if (m_next >= m_text.size())
				fail(
					"the file ends after " + std::to_string(k) + " of its " +
					std::to_string(scans) + " scans (truncated?)");
			const auto s = expect("scan", 3);
			if (whole(s[1], "the scan index", 0, scans) != k)
				fail("scan " + std::to_string(k) + " expected here");
			TTruthScan scan;
			scan.time = number(s[2], "the scan time");
			if (k > 0 && scan.time < t.m_scans.back().time)
				fail("the scan's time goes back");
			scan.occupied = cells(expect("occupied"), nullptr);
			cells(expect("left"), &scan.left);
			for (const auto& [cell, left] : scan.left)
				if (!(left >= 0 && left <= scan.time))
					fail("a cell left after its scan's time or before 0");
			t.m_scans.push_back(std::move(scan));
		}
		while (m_next < m_text.size())
			if (!nextLine().empty()) fail("text after the last scan");
		return t;
	}

   private:
	std::string_view nextLine()
	{
		++m_line;
		if (m_next >= m_text.size()) return {};
		std::size_t end = m_text.find('\n', m_next);
		if (end == std::string::npos) end = m_text.size();
		const std::string_view line(m_text.data() + m_next, end - m_next);
		m_next = end + 1;
		return line;
	}

	/** The next line's words; the first must be `key`, and there must be
	 * `count` of them (0: any number). */
	std::vector<std::string_view> expect(const char* key, std::size_t count = 0)
	{
		const std::string_view line = nextLine();
		auto words = splitWords(line);
		if (words[0] != key)
			fail(std::string("'") + key + " ...' expected here");
		if (count != 0 && words.size() != count)
			fail(
				std::string("'") + key + "' needs " +
				std::to_string(count - 1) + " value(s) after one space each");
		return words;
	}

	[[noreturn]] void fail(const std::string& why) const
	{
		throw std::runtime_error(
			m_path + ": line " + std::to_string(m_line) + ": " + why);
	}

	long whole(std::string_view text, const char* what, long min, long max)
	{
		long v = 0;
		const auto [end, ec] =
			std::from_chars(text.data(), text.data() + text.size(), v);
		if (ec != std::errc() || end != text.data() + text.size() || v < min ||
			v > max)
			fail(
				std::string(what) + " '" + std::string(text) +
				"' is not a whole number from " + std::to_string(min) + " to " +
				std::to_string(max));
		return v;
	}

	double number(std::string_view text, const char* what)
	{
		double v = 0;
		const auto [end, ec] =
			std::from_chars(text.data(), text.data() + text.size(), v);
		if (ec != std::errc() || end != text.data() + text.size() ||
			!std::isfinite(v))
			fail(std::string(what) + " '" + std::string(text) + "' is not a finite number");
		return v;
	}

	/** The cells of a line "KEY C ITEMS": items "I" or "I-J", each ending in
	 * ":TL" when `timed` is given (which then receives them). */
	std::vector<int> cells(
		const std::vector<std::string_view>& words,
		std::vector<std::pair<int, double>>* timed)
	{
		if (words.size() < 2) fail("the cell count is missing");
		const long count = whole(words[1], "cell count", 0, m_cells);
		std::vector<int> out;
		for (std::size_t w = 2; w < words.size(); ++w)
		{
			std::string_view item = words[w];
			double time = 0;
			if (timed)
			{
				const std::size_t colon = item.find(':');
				if (colon == std::string_view::npos)
					fail("an item without its ':TL' time");
				time = number(item.substr(colon + 1), "time of a left cell");
				item = item.substr(0, colon);
			}
			const std::size_t dash = item.find('-');
			const long top = m_cells - 1;
			const long first =
				whole(item.substr(0, dash), "cell index", 0, top);
			const long last = dash == std::string_view::npos
				? first
				: whole(item.substr(dash + 1), "cell index", first, top);
			if (static_cast<long>(out.size()) + (last - first + 1) > count)
				fail("more cells than the line's count");
			for (long i = first; i <= last; ++i)
			{
				out.push_back(static_cast<int>(i));
				if (timed) timed->emplace_back(static_cast<int>(i), time);
			}
		}
		if (static_cast<long>(out.size()) != count)
			fail("fewer cells than the line's count");
		return out;
	}

	const std::string& m_path;
	const std::string& m_text;
	std::size_t m_next = 0, m_line = 0;
	long m_cells = 0;
};

CMotionTruth CMotionTruth::load(const std::string& path)
{
	const std::string text = readAll(path);
	if (text.empty()) throw std::runtime_error(path + ": the file is empty");
	return CParser(path, text).parse();
}

}  // namespace evgrid
