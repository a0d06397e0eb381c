/* Shared by the fuzz targets and fuzz_seeds: reading and writing the fuzzers'
 * input layouts, the checks every map must pass, and MRPT's framing of a
 * serialized map. Maps to bytes, map checks and scans come from
 * tests/support, as in the unit tests. */
#pragma once

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

#include "../support/map_bytes.h"
#include "../support/maps.h"
#include "../support/scans.h"

namespace fuzz
{
/** A finding: the message, then abort(), which libFuzzer reports as a crash
 * and saves the input for. */
[[noreturn]] inline void fail(const std::string& what)
{
	std::fprintf(stderr, "fuzz check failed: %s\n", what.c_str());
	std::abort();
}

/** The map writes its one-time warnings (growth refused, tilted scans) to
 * std::cerr; with a new map per input they would flood the log. Findings
 * are printed with fprintf and stay. */
inline void silenceMapWarnings()
{
	std::cerr.setstate(std::ios::badbit);
}

/** Reads values from the fuzzer's bytes in order; past the end every value
 * reads as zero, so that any input decodes. */
class Reader
{
   public:
	Reader(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}

	template <typename T>
	void operator()(T& value)
	{
		static_assert(std::is_trivially_copyable_v<T>);
		std::uint8_t bytes[sizeof(T)] = {};
		const std::size_t n = std::min(sizeof(T), m_size - m_pos);
		if (n > 0) std::memcpy(bytes, m_data + m_pos, n);
		m_pos += n;
		std::memcpy(&value, bytes, sizeof(T));
	}
	/** A count, then that many values (no more than `max`). */
	template <typename T>
	void operator()(std::vector<T>& values, std::size_t max)
	{
		std::uint16_t n = 0;
		(*this)(n);
		values.resize(n % (max + 1));
		for (T& v : values) (*this)(v);
	}

   private:
	const std::uint8_t* m_data;
	std::size_t m_size, m_pos = 0;
};

/** Writes values in the layout Reader reads, to make seeds. */
class Writer
{
   public:
	template <typename T>
	void operator()(T& value)
	{
		static_assert(std::is_trivially_copyable_v<T>);
		const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
		bytes.insert(bytes.end(), p, p + sizeof(T));
	}
	template <typename T>
	void operator()(std::vector<T>& values, std::size_t)
	{
		auto n = static_cast<std::uint16_t>(values.size());
		(*this)(n);
		for (T& v : values) (*this)(v);
	}
	std::vector<std::uint8_t> bytes;
};

/** Every cell a valid mass function, within the budget. */
inline void checkMap(const mrpt_evidential::CEvidentialGridMap2D& map)
{
	const std::string defect = mrpt_evidential::test::mapDefect(map);
	if (!defect.empty()) fail(defect);
}

/** MRPT's object header of the map as it writes it now: 0x80 | name
 * length, the class name, the current version byte. */
inline const std::vector<std::uint8_t>& mapHeader()
{
	static const std::vector<std::uint8_t> header = [] {
		const std::vector<std::uint8_t> bytes = mrpt_evidential::test::serialize(
			mrpt_evidential::CEvidentialGridMap2D(0.0, 1.0, 0.0, 1.0, 1.0));
		const auto size = static_cast<std::ptrdiff_t>(mrpt_evidential::test::payloadStart(bytes));
		return std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + size);
	}();
	return header;
}

/** A whole serialized map around a payload: header, payload, the checksum
 * it should have (FNV-1a, 64 bit, little-endian) and MRPT's end marker. */
inline std::vector<std::uint8_t> frame(const std::uint8_t* payload, std::size_t size)
{
	std::vector<std::uint8_t> out = mapHeader();
	out.insert(out.end(), payload, payload + size);
	const std::uint64_t h = mrpt_evidential::test::payloadChecksum(payload, size);
	for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(h >> (8 * i)));
	out.push_back(0x88);
	return out;
}

using mrpt_evidential::test::serialize;

/** The fuzz_insert input: map options from table indices and bytes (the
 * options' own checks are fuzz_ini's job), then up to four scans with raw
 * ranges, apertures and poses. */
struct InsertCase
{
	std::uint8_t resolution = 0, model = 1, rule = 0, handling = 0, flags = 0,
				 imprecision = 0, sectorWidth = 0, maxRange = 1, decay = 0,
				 tolerance = 1, margin = 10;
	std::uint16_t muF = 45875, muO = 58982;
	struct Scan
	{
		float aperture = static_cast<float>(M_PI);
		std::uint8_t rightToLeft = 1;
		float sensorPose[6] = {};
		double robotPose[6] = {};
		std::int64_t ticks = 0;
		std::vector<float> ranges;
		std::vector<std::uint8_t> valid;  //!< bit i % 8 of byte i / 8
	};
	std::vector<Scan> scans;
};

/** The layout of InsertCase, for Reader and Writer alike. */
template <typename IO>
void visit(IO& io, InsertCase& c)
{
	for (std::uint8_t* b :
		 {&c.resolution, &c.model, &c.rule, &c.handling, &c.flags, &c.imprecision,
		  &c.sectorWidth, &c.maxRange, &c.decay, &c.tolerance, &c.margin})
		io(*b);
	io(c.muF);
	io(c.muO);
	std::uint8_t count = static_cast<std::uint8_t>(c.scans.size());
	io(count);
	c.scans.resize(count % 5);
	for (InsertCase::Scan& s : c.scans)
	{
		io(s.aperture);
		io(s.rightToLeft);
		io(s.sensorPose);
		io(s.robotPose);
		io(s.ticks);
		io(s.ranges, 511);
		io(s.valid, 64);
	}
}

/** The fuzz_cloud input: map options from table indices and bytes, then up
 * to four clouds of raw points (any float), each with its observation type,
 * sensor and robot pose and time. */
struct CloudCase
{
	std::uint8_t resolution = 0, model = 1, handling = 2, removal = 1, returns = 0,
				 minHeight = 10, heightSpan = 36, sectorWidth = 0, maxRange = 1;
	struct Cloud
	{
		/** 0: CObservationPointCloud, 1: CObservationVelodyneScan's
		 * point_cloud, 2: CObservation3DRangeScan's points3D. */
		std::uint8_t type = 0;
		float sensorPose[6] = {0, 0, 1.8f, 0, 0, 0};
		double robotPose[6] = {};
		std::int64_t ticks = 0;
		std::vector<float> xyz;  //!< x, y, z of each point in turn
	};
	std::vector<Cloud> clouds;
};

/** The layout of CloudCase, for Reader and Writer alike. */
template <typename IO>
void visit(IO& io, CloudCase& c)
{
	for (std::uint8_t* b :
		 {&c.resolution, &c.model, &c.handling, &c.removal, &c.returns, &c.minHeight,
		  &c.heightSpan, &c.sectorWidth, &c.maxRange})
		io(*b);
	std::uint8_t count = static_cast<std::uint8_t>(c.clouds.size());
	io(count);
	c.clouds.resize(count % 5);
	for (CloudCase::Cloud& cl : c.clouds)
	{
		io(cl.type);
		for (float& v : cl.sensorPose) io(v);
		for (double& v : cl.robotPose) io(v);
		io(cl.ticks);
		io(cl.xyz, 3 * 20000);
	}
}

}  // namespace fuzz
