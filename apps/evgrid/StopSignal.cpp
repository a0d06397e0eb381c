/* evgrid: Ctrl-C, SIGTERM and SIGHUP as a request to stop cleanly. */

#include "StopSignal.h"

#include <csignal>
#include <stdexcept>
#include <string>

namespace evgrid
{
namespace
{
volatile std::sig_atomic_t g_stopSignal = 0;
void onStopSignal(int signal) { g_stopSignal = signal; }
}  // namespace

void catchStopSignals()
{
	for (const int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, onStopSignal);
}

void throwIfStopRequested(const char* outcome)
{
	if (g_stopSignal != 0)
		throw std::runtime_error(
			"interrupted by signal " + std::to_string(g_stopSignal) + "; " + outcome);
}

}  // namespace evgrid
