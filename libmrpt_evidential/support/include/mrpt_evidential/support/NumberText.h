/* mrpt-evidential: internal: numbers as text that reads back exactly. */
#pragma once

#include <charconv>
#include <string>

namespace mrpt_evidential::detail
{
/** The shortest text that reads back as exactly `value` (std::to_string
 * prints 1e-7 as 0.000000, and streams' default 6 digits lose time stamps). */
inline std::string shortestText(double value)
{
	char text[32];
	return std::string(text, std::to_chars(text, text + sizeof(text), value).ptr);
}
}  // namespace mrpt_evidential::detail
