/* evgrid: command-line parsing shared by the subcommands. */

#include "CommandLine.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <vector>

namespace evgrid
{
namespace
{
/** TCLAP's standard output, except that a parse error prints one short
 * message instead of the whole usage, and is remembered so that the caller
 * can tell an error from --help (TCLAP reports both as "do not run"). */
class CQuietFailureOutput : public TCLAP::StdOutput
{
   public:
	explicit CQuietFailureOutput(std::string name) : m_name(std::move(name)) {}

	void failure(TCLAP::CmdLineInterface&, TCLAP::ArgException& e) override
	{
		m_failed = true;
		printError(m_name, rephrase(e));
		std::cerr << "Try '" << m_name << " --help'.\n";
	}
	bool failed() const { return m_failed; }

   private:
	/** TCLAP's messages in plainer words, naming the option. */
	static std::string rephrase(const TCLAP::ArgException& e)
	{
		// argId() reads "Argument: (--every)" or "Argument: --bogus".
		std::string arg = e.argId();
		const std::string tag = "Argument: ";
		if (arg.compare(0, tag.size(), tag) == 0) arg.erase(0, tag.size());
		if (arg.size() > 1 && arg.front() == '(' && arg.back() == ')')
			arg = arg.substr(1, arg.size() - 2);
		const std::string error = e.error();
		if (error.rfind("Couldn't find match for argument", 0) == 0)
			return "unknown option or extra argument '" + arg + "'";
		const std::string badValue = "Couldn't read argument value from string ";
		if (error.rfind(badValue, 0) == 0)
			return "bad value " + error.substr(badValue.size()) + " for " + arg;
		return arg.empty() || arg == " " ? error : error + " (" + arg + ")";
	}

	std::string m_name;
	bool m_failed = false;
};
}  // namespace

std::optional<int> parse(
	TCLAP::CmdLine& cmd, const std::string& name, int argc, char** argv,
	int first)
{
	CQuietFailureOutput output(name);
	cmd.setOutput(&output);
	// TCLAP takes argv[0] as the program name shown in the usage.
	std::vector<const char*> args{name.c_str()};
	for (int i = first; i < argc; ++i) args.push_back(argv[i]);
	// TCLAP takes an empty value ("--tolerance ''") for the default.
	for (std::size_t i = 1; i < args.size(); ++i)
	{
		const std::string arg = args[i];
		const bool option = arg.size() > 1 && arg[0] == '-';
		if (option && arg.back() == '=')
			throw UsageError(arg.substr(0, arg.size() - 1) + " needs a non-empty value");
		if (option && arg.find('=') == std::string::npos && i + 1 < args.size() &&
			args[i + 1][0] == '\0')
			throw UsageError(arg + " needs a non-empty value");
	}
	const bool run = cmd.parse(static_cast<int>(args.size()), args.data());
	cmd.setOutput(nullptr);
	if (run) return std::nullopt;
	return output.failed() ? kExitUsage : 0;
}

std::optional<double> toNumber(const std::string& text)
{
	if (text.empty()) return std::nullopt;
	errno = 0;
	char* end = nullptr;
	const double v = std::strtod(text.c_str(), &end);
	if (end != text.c_str() + text.size() || errno != 0 || !std::isfinite(v))
		return std::nullopt;
	return v;
}

std::string requireMapFile(const std::string& value)
{
	if (value.empty())
		throw UsageError("missing the map file (e.g. out/map.evgrid)");
	if (value[0] == '-')
		throw UsageError(
			"unknown option or extra argument '" + value +
			"' (a map file named so: write ./" + value + ")");
	return value;
}

void requireAtLeast(const std::string& option, int value, int minimum)
{
	if (value < minimum)
		throw UsageError(
			option + " must be at least " + std::to_string(minimum) +
			", got " + std::to_string(value));
}

void printError(const std::string& name, const std::string& message)
{
	std::cerr << name << ": error: " << message << "\n";
}

std::string describe(const std::exception& e)
{
	// MRPT exceptions read "==== MRPT exception ====\nMessage: ...\nLocation:
	// ...\nCall stack backtrace: ...", nested ones repeated inside; the last
	// "Message:" is the original cause, unless an "Original exception:" line
	// follows it with a plain exception's text (a class's deserializer that
	// threw while MRPT read the object). A message may take several lines
	// (an ASSERT_ prints its operands on their own). MRPT reads a message
	// that starts "[...]" as a location: the library's .ini errors start with
	// their section, which MRPT then prints as "Location: [section", without
	// its "]"; it is put back in front.
	const std::string what = e.what();
	std::istringstream lines(what);
	std::string line, message;
	const std::string messageTag = "Message:", locationTag = "Location:";
	bool inMessage = false;
	const auto startsWith = [&line](const std::string& tag) {
		return line.compare(0, tag.size(), tag) == 0;
	};
	while (std::getline(lines, line))
	{
		if (line == "Original exception:")
		{
			inMessage = false;
			if (std::getline(lines, line) && !line.empty() && line.rfind("====", 0) != 0)
				message = line;
			continue;
		}
		if (startsWith(messageTag))
		{
			const auto start = line.find_first_not_of(' ', messageTag.size());
			message = start == std::string::npos ? "" : line.substr(start);
			inMessage = true;
		}
		else if (startsWith(locationTag))
		{
			inMessage = false;
			const auto start = line.find_first_not_of(' ', locationTag.size());
			const std::string location =
				start == std::string::npos ? "" : line.substr(start);
			if (location.size() > 1 && location[0] == '[' &&
				location.find(']') == std::string::npos)
				message = location + "] " + message;
		}
		else if (inMessage && !line.empty() && line.rfind("====", 0) != 0 &&
				 !startsWith("Call stack"))
			message += " " + line;
		else
			inMessage = false;
	}
	return message.empty() ? what : message;
}

}  // namespace evgrid
