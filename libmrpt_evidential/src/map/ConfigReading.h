/* mrpt-evidential: internal: strict reading of .ini keys.
 * MRPT's own readers turn a mistyped number into 0 and an enum's digit into
 * any value; these reject both and name the section, key and value. */
#pragma once

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/img/TColor.h>
#include <mrpt/typemeta/TEnumType.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <ostream>
#include <type_traits>
#include <stdexcept>
#include <string>

#include <mrpt_evidential/TInvalidOption.h>
#include <mrpt_evidential/support/NumberText.h>

namespace mrpt_evidential::detail
{
[[noreturn]] inline void throwBadValue(
	const std::string& section, const std::string& key, const std::string& value,
	const std::string& expected)
{
	throw std::invalid_argument(
		"[" + section + "] " + key + " = '" + value + "': " + expected);
}

/** A key's whole value as the file gives it (comment included), for
 * messages: a value cut at a comment marker may not be what was meant. */
inline std::string wholeValue(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::string& key)
{
	return source.read_string(section, key, "", false);
}

/** A key's value, or "" when absent: one word, which may be followed by a
 * comment after `#`, `;` or `//`, with or without a space before it (a `#`
 * that starts the value is a colour's). MRPT's read_string_first_word()
 * would cut "0,95" at its comma and read 0.
 * \throws std::invalid_argument if other text follows the value. */
inline std::string readWord(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::string& key)
{
	const std::string text = source.read_string(section, key, "", false);
	const auto startsComment = [&](std::size_t i) {
		return text[i] == '#' || text[i] == ';' || text.compare(i, 2, "//") == 0;
	};
	std::size_t end = 0;
	while (end < text.size() && text[end] != ' ' && text[end] != '\t' &&
		   !(end > 0 && startsComment(end)))
		++end;
	const auto next = text.find_first_not_of(" \t", end);
	if (next != std::string::npos && !startsComment(next))
		throwBadValue(
			section, key, text, "one value, then at most a comment after #, ; or //");
	return text.substr(0, end);
}

/** A key's value for a message: as the file writes it, or `value` when the
 * file does not give the key. */
inline std::string valueText(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::string& key, double value)
{
	const std::string word = readWord(source, section, key);
	return word.empty() ? shortestText(value) : word;
}

/** Reports an options struct's first invalid value, if any, as the file
 * gives it: "[section] key = 'text': must be rule".
 * \throws std::invalid_argument when `bad` holds a value. */
inline void throwIfInvalid(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::optional<TInvalidOption>& bad)
{
	if (bad)
		throwBadValue(
			section, bad->key, valueText(source, section, bad->key, bad->value),
			"must be " + bad->rule);
}

/** Reads a number into `value` when the key is present.
 * \throws std::invalid_argument if the text is not a finite number. */
inline void readDouble(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::string& key, double& value)
{
	const std::string text = readWord(source, section, key);
	if (text.empty()) return;
	char* end = nullptr;
	errno = 0;
	const double v = std::strtod(text.c_str(), &end);
	if (end == text.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
		throwBadValue(
			section, key, wholeValue(source, section, key),
			text.find(',') == std::string::npos
				? "not a finite number"
				: "not a finite number (the decimal mark is a point)");
	value = v;
}

/** Reads an angle given in degrees into `radians` when the key is present. */
inline void readDegrees(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::string& key, double& radians)
{
	double degrees = radians * 180.0 / M_PI;
	readDouble(source, section, key, degrees);
	radians = degrees * M_PI / 180.0;
}

/** Reads a whole number >= 0 when the key is present (1e8 is accepted). */
template <typename Unsigned>
void readCount(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::string& key, Unsigned& value)
{
	double v = static_cast<double>(value);
	readDouble(source, section, key, v);
	if (!(v >= 0.0) || v != std::floor(v) ||
		v > static_cast<double>(std::numeric_limits<Unsigned>::max()))
		throwBadValue(
			section, key, wholeValue(source, section, key),
			"not a whole number >= 0 within range");
	value = static_cast<Unsigned>(v);
}

/** Reads true/false (also 1/0, yes/no, in any case, as MRPT's own
 * readers take them) when the key is present. */
inline void readBool(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::string& key, bool& value)
{
	const std::string text = readWord(source, section, key);
	if (text.empty()) return;
	std::string lower = text;
	for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
	if (lower == "true" || lower == "1" || lower == "yes")
		value = true;
	else if (lower == "false" || lower == "0" || lower == "no")
		value = false;
	else
		throwBadValue(section, key, wholeValue(source, section, key), "not true or false");
}

/** Whether `value` is one of the enum's named members (MRPT_ENUM_TYPE): a
 * value cast from any integer is not. */
template <typename Enum>
bool isMember(Enum value)
{
	std::string name;
	return mrpt::typemeta::TEnumType<Enum>::getBimap().direct(value, name);
}

/** Reads an enum by name (MRPT_ENUM_TYPE) when the key is present. */
template <typename Enum>
void readEnum(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::string& key, Enum& value)
{
	const std::string text = readWord(source, section, key);
	if (text.empty()) return;
	try
	{
		value = mrpt::typemeta::TEnumType<Enum>::name2value(text);
	}
	catch (const std::exception&)
	{
		std::string names;
		for (const auto& entry : mrpt::typemeta::TEnumType<Enum>::getBimap())
			names += (names.empty() ? "" : ", ") + entry.second;
		throwBadValue(section, key, wholeValue(source, section, key), "not one of " + names);
	}
}

/** Reads a colour written #RRGGBB or RRGGBB (hexadecimal) when the key is
 * present. */
inline void readColor(
	const mrpt::config::CConfigFileBase& source, const std::string& section,
	const std::string& key, mrpt::img::TColor& value)
{
	const std::string text = readWord(source, section, key);
	if (text.empty()) return;
	const std::string hex = text[0] == '#' ? text.substr(1) : text;
	const bool valid = hex.size() == 6 &&
		hex.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos;
	if (!valid) throwBadValue(section, key, wholeValue(source, section, key), "not a colour #RRGGBB");
	const unsigned long rgb = std::strtoul(hex.c_str(), nullptr, 16);
	value = mrpt::img::TColor(
		static_cast<std::uint8_t>(rgb >> 16), static_cast<std::uint8_t>(rgb >> 8),
		static_cast<std::uint8_t>(rgb));
}

/** Name of an enum value, for dumps. */
template <typename Enum>
std::string enumName(Enum value)
{
	return mrpt::typemeta::TEnumType<Enum>::value2name(value);
}

}  // namespace mrpt_evidential::detail

namespace mrpt_evidential::detail
{
/** Writes a key so that reading it back gives the same value exactly. */
inline void writeValue(
	mrpt::config::CConfigFileBase& target, const std::string& section,
	const std::string& key, double value, const std::string& comment)
{
	target.write(section, key, shortestText(value), -1, -1, comment);
}
inline void writeValue(
	mrpt::config::CConfigFileBase& target, const std::string& section,
	const std::string& key, bool value, const std::string& comment)
{
	target.write(section, key, std::string(value ? "true" : "false"), -1, -1, comment);
}
inline void writeValue(
	mrpt::config::CConfigFileBase& target, const std::string& section,
	const std::string& key, const mrpt::img::TColor& value, const std::string& comment)
{
	char text[8];
	std::snprintf(text, sizeof(text), "#%02X%02X%02X", value.R, value.G, value.B);
	target.write(section, key, std::string(text), -1, -1, comment);
}
template <typename Enum, typename = std::enable_if_t<std::is_enum_v<Enum>>>
void writeValue(
	mrpt::config::CConfigFileBase& target, const std::string& section,
	const std::string& key, Enum value, const std::string& comment)
{
	target.write(section, key, enumName(value), -1, -1, comment);
}

/** Prints options as the .ini lines saveToConfigFile() writes. */
inline void dumpAsIni(
	const mrpt::config::CLoadableOptions& options, const std::string& title,
	std::ostream& out)
{
	mrpt::config::CConfigFileMemory ini;
	options.saveToConfigFile(ini, title);
	out << ini.getContent();
}
}  // namespace mrpt_evidential::detail
