/* evgrid: wall time spent in the phases of a run. */
#pragma once

#include <chrono>

namespace evgrid
{
using SteadyClock = std::chrono::steady_clock;

inline double secondsSince(SteadyClock::time_point start)
{
	return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

/** Adds the wall time of its scope to a running total, also when the scope
 * is left by an exception. */
class CScopedTimer
{
   public:
	explicit CScopedTimer(double& total) : m_total(total) {}
	~CScopedTimer() { m_total += secondsSince(m_start); }
	CScopedTimer(const CScopedTimer&) = delete;
	CScopedTimer& operator=(const CScopedTimer&) = delete;

   private:
	double& m_total;
	SteadyClock::time_point m_start = SteadyClock::now();
};

}  // namespace evgrid
