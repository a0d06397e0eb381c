/* evgrid: Ctrl-C, SIGTERM and SIGHUP as a request to stop cleanly. */
#pragma once

namespace evgrid
{
/** From here on, SIGINT (Ctrl-C), SIGTERM and SIGHUP (the terminal closed)
 * only record a request to stop: the command stops at its next
 * throwIfStopRequested(), and its temporary files (a staging folder, a file
 * under a temporary name) are removed on the way out instead of being left
 * behind by a program killed halfway through a write. */
void catchStopSignals();

/** \throws std::runtime_error "interrupted by signal N; " + `outcome` once a
 *  stop was requested. Call it between steps and before committing
 *  outputs. */
void throwIfStopRequested(const char* outcome = "the output folder is unchanged");

}  // namespace evgrid
