/* An MRPT archive over bytes in memory that delivers every read whole or not
 * at all. */
#pragma once

#include <mrpt/serialization/CArchive.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace mrpt_evidential::test
{
/** MRPT's CArchive::ReadBuffer throws only when a read returns no byte at
 * all. Over a CMemoryStream, a stream cut inside a field therefore returns
 * the field's first bytes and leaves the rest of the variable uninitialized:
 * CObservation2DRangeScan::serializeFrom (MRPT 2.5.8 and 2.14) then calls
 * resizeScan() with a count made of stack garbage, which allocated 8 GB and
 * more, and dereferences null when the allocation is refused. This archive
 * answers a read it cannot fill with nothing, so MRPT throws at the first
 * incomplete field, as evgrid's file reader does. */
class CWholeReadArchive : public mrpt::serialization::CArchive
{
   public:
	CWholeReadArchive(const std::uint8_t* data, std::size_t size)
		: m_data(data), m_size(size)
	{
	}
	explicit CWholeReadArchive(const std::vector<std::uint8_t>& bytes)
		: CWholeReadArchive(bytes.data(), bytes.size())
	{
	}

   protected:
	std::size_t write(const void*, std::size_t) override
	{
		throw std::logic_error("CWholeReadArchive is read-only");
	}
	std::size_t read(void* buf, std::size_t len) override
	{
		if (len > m_size - m_pos)
		{
			m_pos = m_size;
			return 0;
		}
		std::memcpy(buf, m_data + m_pos, len);
		m_pos += len;
		return len;
	}

   private:
	const std::uint8_t* m_data;
	std::size_t m_size, m_pos = 0;
};
}  // namespace mrpt_evidential::test
