/* mrpt-evidential: internal: numbers as text that reads back exactly. */
#pragma once

#include <charconv>
#include <cmath>
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

/** A length in metres as a reader wants it: rounded to the nanometre, then
 * its shortest text. A grid's edge summed from growth margins carries the
 * last bits of binary arithmetic (-45.650000000000006); the nanometre is
 * far below any cell. From 1000 km on (and for inf and NaN) the exact
 * text: there a double's steps come near the nanometre. */
inline std::string metresText(double value)
{
	return shortestText(std::abs(value) < 1e6 ? std::round(value * 1e9) / 1e9 : value);
}
}  // namespace mrpt_evidential::detail
