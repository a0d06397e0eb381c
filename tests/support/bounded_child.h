/* Running a piece of a test in a child process with a capped address space,
 * so that a runaway allocation fails there instead of taking the machine. */
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <string>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define MRPT_EVIDENTIAL_TEST_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define MRPT_EVIDENTIAL_TEST_SANITIZED 1
#endif

namespace mrpt_evidential::test
{
/** How a bounded child ended. */
struct TChildEnd
{
	bool exited = false;  ///< by _exit(), not by a signal
	int signal = 0;		  ///< the signal that ended it, if any
	/** What the child's function returned: empty when it found nothing
	 * wrong, else the first failure. */
	std::string report;
};

/** The process's address space now, bytes (/proc/self/statm). */
inline std::size_t addressSpaceBytes()
{
	std::ifstream statm("/proc/self/statm");
	std::size_t pages = 0;
	statm >> pages;
	return pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

/** Runs `f` (returning std::string, empty for success) in a forked child
 * whose address space may grow by at most `extraBytes`, and returns how it
 * ended. An allocation beyond the cap fails in the child (malloc returns
 * null, operator new throws std::bad_alloc) instead of growing the test.
 * Sanitizer builds reserve terabytes of shadow memory up front, so there the
 * cap is not set and the memory budget of the test launcher bounds the run. */
template <typename F>
TChildEnd runInBoundedChild(std::size_t extraBytes, F f)
{
	int fds[2];
	if (pipe(fds) != 0) return {false, 0, "pipe() failed"};
	std::fflush(nullptr);
	const pid_t pid = fork();
	if (pid < 0) return {false, 0, "fork() failed"};
	if (pid == 0)
	{
		close(fds[0]);
#ifndef MRPT_EVIDENTIAL_TEST_SANITIZED
		const rlim_t cap = addressSpaceBytes() + extraBytes;
		const rlimit limit{cap, cap};
		setrlimit(RLIMIT_AS, &limit);
#else
		(void)extraBytes;
#endif
		const rlimit noCore{0, 0};
		setrlimit(RLIMIT_CORE, &noCore);
		const std::string report = f();
		for (std::size_t done = 0; done < report.size();)
		{
			const ssize_t n = write(fds[1], report.data() + done, report.size() - done);
			if (n <= 0) break;
			done += static_cast<std::size_t>(n);
		}
		_exit(0);
	}
	close(fds[1]);
	TChildEnd end;
	char buf[4096];
	for (ssize_t n; (n = read(fds[0], buf, sizeof(buf))) > 0;)
		end.report.append(buf, static_cast<std::size_t>(n));
	close(fds[0]);
	int status = 0;
	while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
	{
	}
	end.exited = WIFEXITED(status) && WEXITSTATUS(status) == 0;
	end.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
	return end;
}
}  // namespace mrpt_evidential::test
