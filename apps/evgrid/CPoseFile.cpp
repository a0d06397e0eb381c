/* evgrid: robot poses from a text file. */

#include "CPoseFile.h"

#include "CommandLine.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace evgrid
{
namespace
{
bool isPlainInteger(const std::string& token)
{
	return !token.empty() &&
		std::all_of(token.begin(), token.end(), [](unsigned char c) {
			   return std::isdigit(c) != 0;
		   });
}
}  // namespace

CPoseFile CPoseFile::load(const std::string& path, Kind kind)
{
	std::ifstream in(path);
	if (!in)
		throw std::runtime_error(
			path + ": cannot open the pose file: " + std::strerror(errno));

	CPoseFile file;
	file.m_path = path;
	std::vector<std::size_t> lineNumbers;
	std::vector<std::string> keyTexts;
	bool keysAreSteps = true;
	std::string line;
	for (std::size_t lineNumber = 1; std::getline(in, line); ++lineNumber)
	{
		std::istringstream words(line);
		std::vector<std::string> tokens;
		for (std::string w; words >> w;) tokens.push_back(w);
		if (tokens.empty() || tokens[0][0] == '#' || tokens[0][0] == '%')
			continue;
		const auto where = path + ":" + std::to_string(lineNumber) + ": ";
		if (tokens.size() != 4)
			throw std::runtime_error(
				where + "expected 4 numbers 'time-or-step x y phi', got " +
				std::to_string(tokens.size()) + " fields");
		double v[4];
		for (int i = 0; i < 4; ++i)
		{
			const auto n = toNumber(tokens[i]);
			if (!n)
				throw std::runtime_error(
					where + "'" + tokens[i] + "' is not a number");
			v[i] = *n;
		}
		keysAreSteps = keysAreSteps && isPlainInteger(tokens[0]) &&
			v[0] == static_cast<double>(file.m_keys.size());
		file.m_keys.push_back(v[0]);
		file.m_poses.emplace_back(v[1], v[2], v[3]);
		lineNumbers.push_back(lineNumber);
		keyTexts.push_back(tokens[0]);
	}
	if (in.bad())
		throw std::runtime_error(path + ": read error: " + std::strerror(errno));
	if (file.m_keys.empty())
		throw std::runtime_error(path + ": no pose in the file");

	file.m_kind = kind != Kind::Auto ? kind
		: keysAreSteps               ? Kind::Step
									 : Kind::Time;
	// Times may repeat (a sensor logging twice in a tick) but never go back;
	// steps are indices and must grow.
	for (std::size_t i = 1; i < file.m_keys.size(); ++i)
	{
		const double a = file.m_keys[i - 1], b = file.m_keys[i];
		const bool ordered = file.m_kind == Kind::Step ? b > a : b >= a;
		if (!ordered)
			throw std::runtime_error(
				path + ":" + std::to_string(lineNumbers[i]) + ": " +
				(file.m_kind == Kind::Step ? "step " : "time ") +
				keyTexts[i] + " does not follow " + keyTexts[i - 1]);
	}
	if (file.m_kind == Kind::Step)
		for (std::size_t i = 0; i < file.m_keys.size(); ++i)
			if (file.m_keys[i] < 0 || file.m_keys[i] != std::floor(file.m_keys[i]))
				throw std::runtime_error(
					path + ":" + std::to_string(lineNumbers[i]) +
					": a step must be an integer >= 0");
	return file;
}

std::optional<mrpt::math::TPose2D> CPoseFile::atTime(
	double t, double tolerance) const
{
	const auto after = std::lower_bound(m_keys.begin(), m_keys.end(), t);
	const std::size_t b = static_cast<std::size_t>(after - m_keys.begin());
	if (b == m_keys.size())
	{
		if (t - m_keys.back() > tolerance) return std::nullopt;
		return m_poses.back();
	}
	if (b == 0 || m_keys[b] == t)
	{
		if (m_keys[b] - t > tolerance) return std::nullopt;
		return m_poses[b];
	}
	const std::size_t a = b - 1;
	if (std::min(t - m_keys[a], m_keys[b] - t) > tolerance) return std::nullopt;
	const double w = (t - m_keys[a]) / (m_keys[b] - m_keys[a]);
	const auto& pa = m_poses[a];
	const auto& pb = m_poses[b];
	return mrpt::math::TPose2D(
		pa.x + w * (pb.x - pa.x), pa.y + w * (pb.y - pa.y),
		mrpt::math::wrapToPi(
			pa.phi + w * mrpt::math::wrapToPi(pb.phi - pa.phi)));
}

std::optional<mrpt::math::TPose2D> CPoseFile::atStep(std::size_t step) const
{
	const auto it = std::lower_bound(
		m_keys.begin(), m_keys.end(), static_cast<double>(step));
	if (it == m_keys.end() || *it != static_cast<double>(step))
		return std::nullopt;
	return m_poses[static_cast<std::size_t>(it - m_keys.begin())];
}

}  // namespace evgrid
