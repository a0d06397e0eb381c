/* Shared helpers of the unit tests: random masses, mass comparisons, threads
 * that start together, captured stderr and scratch directories. The algebra
 * alone: test_mass_algebra links no MRPT. */
#pragma once

#include <gtest/gtest.h>
#include <mrpt_evidential/algebra/Mass.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "mass_text.h"

namespace mrpt_evidential::test
{
/** Random valid masses from a fixed seed. One draw in eight puts some of the
 * masses at exactly 0, so that the corners of the simplex are exercised. */
class MassGenerator
{
   public:
	explicit MassGenerator(unsigned seed = 20261122) : m_rng(seed) {}

	/** withConflict = false gives normal masses (m(empty) = 0). */
	Mass operator()(bool withConflict = true)
	{
		std::uniform_real_distribution<double> u(0.0, 1.0);
		double v[4];
		for (double& x : v) x = -std::log(1.0 - u(m_rng));  // flat on the simplex
		if (!withConflict) v[0] = 0.0;
		if (u(m_rng) < 0.125) v[1 + static_cast<int>(u(m_rng) * 2.999)] = 0.0;
		double total = v[0] + v[1] + v[2] + v[3];
		if (total == 0.0) v[3] = total = 1.0;
		return {v[0] / total, v[1] / total, v[2] / total, v[3] / total};
	}

	std::vector<Mass> many(std::size_t n, bool withConflict = true)
	{
		std::vector<Mass> out;
		for (std::size_t i = 0; i < n; ++i) out.push_back((*this)(withConflict));
		return out;
	}

	std::mt19937& rng() { return m_rng; }

   private:
	std::mt19937 m_rng;
};

inline ::testing::AssertionResult massNear(
	const Mass& actual, const Mass& expected, double tol)
{
	if (maxAbsDifference(actual, expected) <= tol)
		return ::testing::AssertionSuccess();
	return ::testing::AssertionFailure()
		<< actual << " differs from " << expected << " by "
		<< maxAbsDifference(actual, expected) << " > " << tol;
}

/** Calls f(t) for t in [0, count) on as many threads, released together so
 * that their first calls race; returns when every thread is done. */
template <typename F>
void runTogether(int count, F f)
{
	std::atomic<int> ready{0};
	std::vector<std::thread> threads;
	for (int t = 0; t < count; ++t)
		threads.emplace_back([&, t] {
			++ready;
			while (ready.load() < count) std::this_thread::yield();
			f(t);
		});
	for (auto& thread : threads) thread.join();
}

/** Runs f and returns what it wrote to stderr. */
inline std::string stderrOf(const std::function<void()>& f)
{
	::testing::internal::CaptureStderr();
	f();
	return ::testing::internal::GetCapturedStderr();
}

/** How many times `needle` occurs in `text`, overlaps included. */
inline std::size_t occurrences(const std::string& text, const std::string& needle)
{
	std::size_t n = 0;
	for (auto p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1))
		++n;
	return n;
}

#ifdef TEST_SCRATCH_DIR
/** A fresh, empty directory for one test: `name` in the suite's own folder
 * of the build tree's scratch space. */
inline std::filesystem::path scratchDir(const std::string& suite, const std::string& name)
{
	const std::filesystem::path dir = std::filesystem::path(TEST_SCRATCH_DIR) / suite / name;
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	return dir;
}
#endif

/** The names of the entries of a directory. */
inline std::set<std::string> filesIn(const std::filesystem::path& dir)
{
	std::set<std::string> names;
	for (const auto& e : std::filesystem::directory_iterator(dir))
		names.insert(e.path().filename().string());
	return names;
}

}  // namespace mrpt_evidential::test

#define EXPECT_MASS_NEAR(actual, expected, tol) \
	EXPECT_TRUE(::mrpt_evidential::test::massNear((actual), (expected), (tol)))

/** For loops over grid cells: stops at the first cell that differs. */
#define ASSERT_MASS_NEAR_AT(actual, expected, tol, row, col)                  \
	ASSERT_TRUE(::mrpt_evidential::test::massNear((actual), (expected), (tol))) \
		<< "at (" << (row) << ", " << (col) << ")"
