/* memory_budget: runs one test command and holds it to a memory budget.
 *
 *   memory_budget [--budget-mb MB] [--record DIR] [--name NAME] -- COMMAND ARGS...
 *
 * Runs COMMAND, waits for it and reads the peak resident memory of the
 * largest process of its tree: getrusage(RUSAGE_CHILDREN) keeps the maximum
 * over every descendant that was waited for, so a script's programs count,
 * each on its own. With --record, writes "PEAK_KB NAME" to DIR/NAME.peak
 * (replacing the figure of an earlier run of the same test). The exit code is
 * the command's; a command that passed but peaked above MB (default 2048)
 * fails with exit code 1 and its figure on stderr.
 *
 * NAME defaults to the program's name, followed by its --gtest_filter when
 * it has one (the tests gtest_discover_tests makes); listing a GoogleTest
 * program's tests is never recorded. */

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace
{
pid_t g_child = -1;

/** CTest ends a test that ran out of time with a signal: pass it on. */
void forward(int sig)
{
	if (g_child > 0) kill(g_child, sig);
}

[[noreturn]] void usage(const char* why)
{
	std::fprintf(
		stderr,
		"memory_budget: %s\nusage: memory_budget [--budget-mb MB] [--record "
		"DIR] [--name NAME] -- COMMAND ARGS...\n",
		why);
	std::exit(2);
}

std::string baseName(const std::string& path)
{
	const auto slash = path.find_last_of('/');
	return slash == std::string::npos ? path : path.substr(slash + 1);
}

/** What a test is called in the record when no --name was given. */
std::string defaultName(char** command)
{
	std::string name = baseName(command[0]);
	for (char** arg = command + 1; *arg; ++arg)
	{
		const std::string a = *arg;
		if (a.rfind("--gtest_filter=", 0) == 0) name += " " + a.substr(15);
	}
	return name;
}

bool listsTests(char** command)
{
	for (char** arg = command + 1; *arg; ++arg)
		if (std::strcmp(*arg, "--gtest_list_tests") == 0) return true;
	return false;
}

/** A file name for a test name: characters other than letters, digits, '.',
 * '-' and '_' become '_'. */
std::string fileNameOf(const std::string& name)
{
	std::string out = name;
	for (char& c : out)
		if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' &&
			c != '_')
			c = '_';
	return out;
}
}  // namespace

int main(int argc, char** argv)
{
	long budgetMb = 2048;
	std::string recordDir, name;
	int i = 1;
	for (; i < argc; ++i)
	{
		const std::string a = argv[i];
		if (a == "--") break;
		if (i + 1 >= argc) usage(("a value is missing after " + a).c_str());
		if (a == "--budget-mb")
		{
			char* end = nullptr;
			budgetMb = std::strtol(argv[++i], &end, 10);
			if (*end != '\0' || budgetMb <= 0) usage("--budget-mb needs a positive number");
		}
		else if (a == "--record")
			recordDir = argv[++i];
		else if (a == "--name")
			name = argv[++i];
		else
			usage(("unknown option " + a).c_str());
	}
	if (i + 1 >= argc) usage("no command given after --");
	char** command = argv + i + 1;
	if (name.empty()) name = defaultName(command);

	g_child = fork();
	if (g_child < 0)
	{
		std::perror("memory_budget: fork");
		return 1;
	}
	if (g_child == 0)
	{
		execvp(command[0], command);
		std::fprintf(
			stderr, "memory_budget: cannot run %s: %s\n", command[0],
			std::strerror(errno));
		_exit(127);
	}
	for (const int sig : {SIGTERM, SIGINT, SIGHUP}) std::signal(sig, forward);

	int status = 0;
	while (waitpid(g_child, &status, 0) < 0)
		if (errno != EINTR)
		{
			std::perror("memory_budget: waitpid");
			return 1;
		}
	rusage usage{};
	getrusage(RUSAGE_CHILDREN, &usage);
	const long peakKb = usage.ru_maxrss;  // kilobytes on Linux

	if (!recordDir.empty() && !listsTests(command))
	{
		std::ofstream record(recordDir + "/" + fileNameOf(name) + ".peak");
		record << peakKb << ' ' << name << '\n';
	}

	const int code = WIFEXITED(status) ? WEXITSTATUS(status)
									   : 128 + WTERMSIG(status);
	if (peakKb > budgetMb * 1024)
	{
		std::fprintf(
			stderr,
			"memory_budget: %s peaked at %.1f MB of resident memory, over its "
			"budget of %ld MB\n",
			name.c_str(), peakKb / 1024.0, budgetMb);
		return code == 0 ? 1 : code;
	}
	return code;
}
