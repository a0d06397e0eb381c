/* evgrid: progress report of a long run on stderr. */

#include "CProgress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace evgrid
{
namespace
{
/** "1:05" style duration; "--:--" when unknown. */
std::string formatDuration(double seconds)
{
	if (!(seconds >= 0.0) || seconds > 360000.0) return "--:--";
	const long s = std::lround(seconds);
	char buf[32];
	if (s >= 3600)
		std::snprintf(buf, sizeof(buf), "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
	else
		std::snprintf(buf, sizeof(buf), "%ld:%02ld", s / 60, s % 60);
	return buf;
}

/** Time left at a constant rate; negative when too early to tell. */
double secondsLeft(double fraction, double elapsed)
{
	return fraction > 0.01 ? elapsed * (1.0 - fraction) / fraction : -1.0;
}
}  // namespace

CProgress::Mode CProgress::modeFor(bool quiet)
{
	if (quiet) return Mode::Off;
	return isatty(fileno(stderr)) ? Mode::Bar : Mode::Lines;
}

CProgress::CProgress(Mode mode, std::string label)
	: m_mode(mode), m_label(std::move(label))
{
}

void CProgress::update(double fraction, std::size_t scans)
{
	if (m_mode == Mode::Off) return;
	fraction = std::clamp(fraction, 0.0, 1.0);
	const auto now = Clock::now();
	const double elapsed = std::chrono::duration<double>(now - m_start).count();
	const double sinceOutput =
		std::chrono::duration<double>(now - m_lastOutput).count();

	if (m_mode == Mode::Bar)
	{
		if (sinceOutput < 0.1 && m_barShown) return;  // ~10 redraws a second
		m_lastOutput = now;
		drawBar(fraction, scans, elapsed);
		return;
	}
	const bool tenthPassed = fraction * 10.0 >= m_nextTenth;
	if (!tenthPassed && sinceOutput < 5.0) return;
	while (m_nextTenth <= 10 && fraction * 10.0 >= m_nextTenth) ++m_nextTenth;
	m_lastOutput = now;
	std::fprintf(
		stderr, "%s: %3.0f%%, %zu scans, %.0f scans/s, %s left\n",
		m_label.c_str(), 100.0 * fraction, scans,
		elapsed > 0 ? static_cast<double>(scans) / elapsed : 0.0,
		formatDuration(secondsLeft(fraction, elapsed)).c_str());
}

void CProgress::drawBar(double fraction, std::size_t scans, double elapsed)
{
	constexpr int kWidth = 30;
	const int filled = static_cast<int>(fraction * kWidth);
	std::string bar(static_cast<std::size_t>(filled), '#');
	bar.resize(kWidth, '.');
	std::fprintf(
		stderr, "\r%s [%s] %3.0f%%  %zu scans  %.0f scans/s  ETA %s  ",
		m_label.c_str(), bar.c_str(), 100.0 * fraction, scans,
		elapsed > 0 ? static_cast<double>(scans) / elapsed : 0.0,
		formatDuration(secondsLeft(fraction, elapsed)).c_str());
	std::fflush(stderr);
	m_barShown = true;
}

void CProgress::finish()
{
	if (m_mode != Mode::Bar || !m_barShown) return;
	std::fprintf(stderr, "\r\033[K");  // back to the start, erase the line
	std::fflush(stderr);
	m_barShown = false;
}

}  // namespace evgrid
