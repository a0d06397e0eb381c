/* evgrid: progress report of a long run on stderr. */
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace evgrid
{
/** Reports how far a run is: on a terminal a one-line bar redrawn in place
 * (share done, scans, scans per second, time left); otherwise (a log file, a
 * pipe) a plain line at every tenth of the work or every five seconds. */
class CProgress
{
   public:
	enum class Mode
	{
		Off,
		Bar,
		Lines
	};
	/** Bar if stderr is a terminal, Lines otherwise, Off when quiet. */
	static Mode modeFor(bool quiet);

	CProgress(Mode mode, std::string label);
	/** `fraction` of the work done, in [0, 1]; `scans` inserted so far. */
	void update(double fraction, std::size_t scans);
	/** Erases the bar, so that what follows starts on a clean line. */
	void finish();

   private:
	using Clock = std::chrono::steady_clock;
	void drawBar(double fraction, std::size_t scans, double elapsed);

	Mode m_mode;
	std::string m_label;
	Clock::time_point m_start = Clock::now(), m_lastOutput = m_start;
	int m_nextTenth = 1;
	bool m_barShown = false;
};

}  // namespace evgrid
