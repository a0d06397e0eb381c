/* mrpt-evidential: internal: the threads that fuse bands of a scan's rows
 * (insertionOptions.insertionThreads). */
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace mrpt_evidential
{
/** Runs job(0), ..., job(n - 1) at once: job(0) on the calling thread, the
 * others on worker threads that start when first needed and wait between
 * scans (starting a thread per scan would cost as much as a scan at 0.10 m).
 * One run at a time; not copyable. */
class CBandWorkers
{
   public:
	CBandWorkers() = default;
	CBandWorkers(const CBandWorkers&) = delete;
	CBandWorkers& operator=(const CBandWorkers&) = delete;
	~CBandWorkers();

	/** Returns once every job has returned; rethrows the first exception a
	 * job threw (the others still run to their end). */
	void run(std::size_t n, const std::function<void(std::size_t)>& job);

   private:
	void work(std::size_t slot);

	std::vector<std::thread> m_threads;
	std::mutex m_mutex;
	std::condition_variable m_start, m_done;
	const std::function<void(std::size_t)>* m_job = nullptr;
	/** Jobs of the current run, and the workers that have not finished it. */
	std::size_t m_jobs = 0, m_pending = 0;
	/** Counts runs, so that a worker starts each run once. */
	std::size_t m_run = 0;
	bool m_stop = false;
	std::exception_ptr m_error;
};

}  // namespace mrpt_evidential
