/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "map/BandWorkers.h"

namespace mrpt_evidential
{
CBandWorkers::~CBandWorkers()
{
	{
		std::lock_guard<std::mutex> lock(m_mutex);
		m_stop = true;
	}
	m_start.notify_all();
	for (std::thread& t : m_threads) t.join();
}

void CBandWorkers::run(std::size_t n, const std::function<void(std::size_t)>& job)
{
	if (n == 0) return;
	if (n == 1)
	{
		job(0);
		return;
	}
	{
		std::lock_guard<std::mutex> lock(m_mutex);
		while (m_threads.size() < n - 1)
			m_threads.emplace_back(&CBandWorkers::work, this, m_threads.size() + 1);
		m_job = &job;
		m_jobs = n;
		m_pending = n - 1;
		m_error = nullptr;
		++m_run;
	}
	m_start.notify_all();
	std::exception_ptr mine;
	try
	{
		job(0);
	}
	catch (...)
	{
		mine = std::current_exception();
	}
	std::unique_lock<std::mutex> lock(m_mutex);
	m_done.wait(lock, [&] { return m_pending == 0; });
	m_job = nullptr;
	if (mine) std::rethrow_exception(mine);
	if (m_error) std::rethrow_exception(m_error);
}

void CBandWorkers::work(std::size_t slot)
{
	std::size_t seen = 0;
	std::unique_lock<std::mutex> lock(m_mutex);
	for (;;)
	{
		m_start.wait(lock, [&] { return m_stop || m_run != seen; });
		if (m_stop) return;
		seen = m_run;
		// Workers beyond this run's jobs (a run with fewer threads than an
		// earlier one) have nothing to do and are not waited for.
		if (slot >= m_jobs) continue;
		const std::function<void(std::size_t)>& job = *m_job;
		lock.unlock();
		std::exception_ptr error;
		try
		{
			job(slot);
		}
		catch (...)
		{
			error = std::current_exception();
		}
		lock.lock();
		if (error && !m_error) m_error = error;
		if (--m_pending == 0) m_done.notify_one();
	}
}

}  // namespace mrpt_evidential
