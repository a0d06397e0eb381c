/* evgrid: command-line parsing shared by the subcommands. */
#pragma once

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace evgrid
{
/** Exit codes: 0 success, 1 a runtime failure (a file that cannot be read or
 * written), 2 a command line that does not make sense. */
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

/** A command line that parses but whose values make no sense together. */
class UsageError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

/** Parses argv[first..argc) with `cmd`, printing TCLAP's help and version on
 * stdout and a short error (with a hint to --help) on stderr. `name` is what
 * messages call the program, e.g. "evgrid build".
 * \return nothing when the options are set and the command should run; else
 *  the exit code: 0 after --help or --version, kExitUsage after an error. */
std::optional<int> parse(
	TCLAP::CmdLine& cmd, const std::string& name, int argc, char** argv,
	int first);

/** The saved map named by the positional argument of inspect and export.
 * \throws UsageError if it is missing or looks like an option (TCLAP takes
 *  any word there, options included). */
std::string requireMapFile(const std::string& value);

/** The whole (non-empty) text as a finite number, or nothing. */
std::optional<double> toNumber(const std::string& text);

/** The value that `text`, given to `option`, names among `choices` (each a
 * name and its value).
 * \throws UsageError "OPTION must be A, B or C, got 'TEXT'" when it names
 *  none. */
template <typename T>
T oneOf(
	const std::string& option, const std::string& text,
	std::initializer_list<std::pair<const char*, T>> choices)
{
	std::string names;
	std::size_t i = 0;
	for (const auto& [name, value] : choices)
	{
		if (text == name) return value;
		names += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + std::string(name);
		++i;
	}
	throw UsageError(option + " must be " + names + ", got '" + text + "'");
}

/** Throws UsageError unless `value` >= `minimum`. */
void requireAtLeast(const std::string& option, int value, int minimum);

/** Prints "<name>: error: <message>" on stderr. */
void printError(const std::string& name, const std::string& message);

/** The text of an exception without MRPT's decoration (stack of source
 * locations): the lines that say what went wrong. */
std::string describe(const std::exception& e);

}  // namespace evgrid
