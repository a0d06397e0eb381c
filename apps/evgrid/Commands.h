/* evgrid: the subcommands. Each parses argv[first..argc) and returns the
 * process exit code (see CommandLine.h); runtime failures are thrown as
 * std::exception and reported by main(). */
#pragma once

namespace evgrid
{
int runBuild(int argc, char** argv, int first);
int runInspect(int argc, char** argv, int first);
int runExport(int argc, char** argv, int first);
int runCompare(int argc, char** argv, int first);
int runScoreMotion(int argc, char** argv, int first);
int runMerge(int argc, char** argv, int first);
int runDiff(int argc, char** argv, int first);
}  // namespace evgrid
