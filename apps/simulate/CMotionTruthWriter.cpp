/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The per-scan ground truth of what moves in a scene. */
#include "CMotionTruthWriter.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "CellRuns.h"

namespace mrpt_evidential::simulate
{
CMotionTruthWriter::CMotionTruthWriter(
	const std::string& path, CScene& scene, const std::string& sceneName,
	double startTime, double scanPeriod, std::size_t scans)
	: m_path(path),
	  m_scene(scene),
	  m_samplePeriod(scanPeriod / kSamplesPerScan)
{
	m_grid = gridOver(scene.extent(), kResolution);
	const std::size_t cells = static_cast<std::size_t>(m_grid.sizeX) *
		static_cast<std::size_t>(m_grid.sizeY);
	m_static.assign(cells, 0);
	m_covered.assign(cells, 0);
	m_listed.assign(cells, 0);
	m_leftAt.assign(cells, 0.0);
	cover(scene.staticShapes(), m_static);

	if (std::string error; !m_stream.open(path, 9, error))
		throw std::runtime_error("cannot write " + path + ": " + error);
	char header[256];
	std::snprintf(
		header, sizeof(header),
		"evgrid-simulate motion 1\nscene %s\nstart %.3f\n"
		"grid %.2f %.2f %.2f %d %d\nscans %zu\nsample %.2f\n",
		sceneName.c_str(), startTime, m_grid.xMin, m_grid.yMin,
		m_grid.resolution, m_grid.sizeX, m_grid.sizeY, scans, m_samplePeriod);
	write(header + std::string("static ") + cellRuns(m_static) + "\n");
}

void CMotionTruthWriter::cover(
	const std::vector<TShape>& shapes, std::vector<uint8_t>& cells) const
{
	for (const TShape& shape : shapes)
		forEachCell(shape, m_grid, ECoverage::Overlap, [&](int cx, int cy) {
			const auto i = static_cast<std::size_t>(cx + m_grid.sizeX * cy);
			if (!m_static[i]) cells[i] = 1;
		});
}

void CMotionTruthWriter::sample(long n)
{
	const double t = static_cast<double>(n) * m_samplePeriod;
	std::vector<uint8_t> now(m_covered.size(), 0);
	cover(m_scene.movingAt(t), now);
	for (std::size_t i = 0; i < now.size(); ++i)
	{
		if (!m_covered[i] || now[i]) continue;
		m_leftAt[i] = t;
		if (!m_listed[i]) m_left.push_back(static_cast<int>(i));
		m_listed[i] = 1;
	}
	m_covered.swap(now);
	m_lastSample = n;
}

void CMotionTruthWriter::writeScan(std::size_t k)
{
	const long last = static_cast<long>(k) * kSamplesPerScan;
	while (m_lastSample < last)
		sample(m_lastSample + 1);

	char line[64];
	std::snprintf(
		line, sizeof(line), "scan %zu %.2f\n", k,
		static_cast<double>(last) * m_samplePeriod);
	std::string record = line + ("occupied " + cellRuns(m_covered)) + "\n";

	// A cell covered again since it was left is not left. Runs of
	// consecutive cells left at the same time share one item.
	const auto isLeft = [&](int i) { return !m_covered[i]; };
	std::sort(m_left.begin(), m_left.end());
	std::string runs;
	std::size_t count = 0;
	for (std::size_t j = 0; j < m_left.size(); ++j)
	{
		const int first = m_left[j];
		if (!isLeft(first)) continue;
		std::size_t end = j;
		while (end + 1 < m_left.size() && m_left[end + 1] == m_left[end] + 1 &&
			   isLeft(m_left[end + 1]) &&
			   m_leftAt[m_left[end + 1]] == m_leftAt[first])
			++end;
		std::snprintf(line, sizeof(line), ":%.2f", m_leftAt[first]);
		appendCellRun(runs, first, m_left[end], line);
		count += end - j + 1;
		j = end;
	}
	for (const int i : m_left)
		m_listed[i] = 0;
	m_left.clear();
	write(record + "left " + std::to_string(count) + runs + "\n");
}

void CMotionTruthWriter::write(const std::string& text)
{
	if (m_stream.Write(text.data(), text.size()) != text.size())
		throw std::runtime_error("cannot write " + m_path);
}

void CMotionTruthWriter::close()
{
	m_stream.close();
}

}  // namespace mrpt_evidential::simulate
