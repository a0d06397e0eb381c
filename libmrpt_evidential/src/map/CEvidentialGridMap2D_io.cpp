/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: serialization (CSerializable).
 *
 * Layout of version 6, after MRPT's object header (class name, version byte),
 * every number little-endian:
 *   geometry     f64 xMin, f64 yMin, f64 resolution, i32 sizeX, i32 sizeY
 *   budget       u64 maxCells
 *   insertion    u8 sensorModel, f64 muF, f64 muO, f64 imprecision,
 *                u8 imprecisionProfile, f64 sectorWidth (rad), f64 maxRange,
 *                u8 invalidRangesAsFree, f64 freeMargin, u8 fusionRule,
 *                f64 decayRate,
 *                f64 horizontalTolerance (rad), u8 conflictHandling,
 *                f64 growthMargin, f64 motionWindow, f64 motionMinConflict,
 *                f64 motionClearance, u8 groundRemoval,
 *                f64 minObstacleHeight, f64 maxObstacleHeight,
 *                u8 groundReturns, u32 insertionThreads
 *   motion       what the motion layer remembers between scans
 *                (CMotionDetector::TMemory), cells as packed indices
 *                (row * sizeX + column): u64 count A, A x u64 recent
 *                arrivals in the order they were set; u64 count L, L x u64
 *                departures under way, ascending; u64 leavingKept
 *   likelihood   f64 occupiedMass, f64 maxCorrsDistance, f64 sigma, f64 zHit,
 *                f64 zRandom, f64 maxRange, u32 decimation,
 *                u8 unknownAsNeutral
 *   rendering    u8 style, 6 x (u8 R, u8 G, u8 B) colours (free, occupied,
 *                unknown, conflict, appeared, disappeared), u8 showFree,
 *                u8 showOccupied, u8 showConflict, u8 showMotion,
 *                u8 showUnknown, f64 height
 *   generic      genericMapParams as an MRPT object (its own header/version)
 *   stamps       u32 count N, N x f64 insertion times
 *   storage      u64 insertionCount, f64 decayRate (the storage's),
 *                u8 keepsConflict
 *   cells        sizeX * sizeY cells, row by row from (0, 0), each
 *                u16 aside, u16 free, u16 occupied, u16 stamp: the conflict
 *                (keepsConflict) or the motion event, and the normal part's
 *                free and occupied masses (QuantizedCell); the stamp's
 *                bit 15 says that the motion layer saw the cell flip
 *                (kFlipped)
 * Version 5 had no insertionThreads (read as 1) and no motion memory (its
 * maps start the lists again, as a reset map does).
 * Version 4 had that bit always 0 (its maps remember no flips).
 * Version 3 had no rendering options (read as the defaults).
 * Version 2 had no cloud options (groundRemoval to groundReturns: read as
 * the defaults). Version 1 had no freeMargin (read as 0), no motion options and no
 * keepsConflict: its cells always
 * kept conflict. A file of a map whose conflictHandling is Keep still does;
 * any other has its conflict (0 but for rounding) dropped. Version 0 had
 * the layout of version 1 with m(F) and m(O) themselves in the cells
 * instead of the normal part's. Both are read and converted.
 *   checksum     u64 FNV-1a (64 bit) of every byte above, header excluded
 * Enums are stored as their integer values; booleans as 0 or 1.
 * Reading refuses a budget above GridGeometry::kMaxCellBudget (as setting
 * one does) and a grid of more cells than its budget, before allocating
 * anything for it, and allocates the cells of a larger grid than
 * kCellsTrustedAhead as they arrive. */

#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "map/MapWorkspace.h"
#include "map/OptionsCheck.h"

using namespace mrpt_evidential;
using mrpt::serialization::CArchive;

namespace
{
/** Cells are streamed in blocks of this many, to bound the scratch buffer. */
constexpr std::size_t kCellsPerBlock = 4096;
constexpr std::size_t kBytesPerCell = 8;
/** Cells allocated before any is read (32 MB, a 2000 x 2000 grid): beyond
 * this, memory follows the data actually present. */
constexpr std::size_t kCellsTrustedAhead = std::size_t(1) << 22;

/** Reads exactly len bytes. CArchive::ReadBuffer throws only when it reads
 * nothing; a short read at the end of a truncated stream must throw too. */
void readFully(CArchive& in, void* buf, std::size_t len)
{
	auto* bytes = static_cast<std::uint8_t*>(buf);
	for (std::size_t done = 0; done < len;)
		done += in.ReadBuffer(bytes + done, len - done);
}

/** An archive that forwards every byte to another one and keeps a 64-bit
 * FNV-1a hash of them, so that the payload's checksum covers exactly what was
 * written or read, nested objects included. Reads are all or nothing. */
class ChecksummedArchive : public CArchive
{
   public:
	explicit ChecksummedArchive(CArchive& inner) : m_inner(inner) {}

	std::uint64_t hash() const { return m_hash; }

	std::string getArchiveDescription() const override
	{
		return m_inner.getArchiveDescription();
	}

   protected:
	std::size_t write(const void* buf, std::size_t len) override
	{
		m_inner.WriteBuffer(buf, len);
		add(buf, len);
		return len;
	}
	std::size_t read(void* buf, std::size_t len) override
	{
		readFully(m_inner, buf, len);
		add(buf, len);
		return len;
	}

   private:
	void add(const void* buf, std::size_t len)
	{
		const auto* bytes = static_cast<const std::uint8_t*>(buf);
		for (std::size_t i = 0; i < len; ++i)
			m_hash = (m_hash ^ bytes[i]) * 0x100000001b3ULL;
	}

	CArchive& m_inner;
	std::uint64_t m_hash = 0xcbf29ce484222325ULL;
};

[[noreturn]] void corrupted(const std::string& what)
{
	throw std::runtime_error(
		"CEvidentialGridMap2D: corrupted or invalid serialized map: " + what);
}

template <typename E>
void writeEnum(CArchive& out, E value)
{
	out << static_cast<std::uint8_t>(value);
}

/** An enum stored as an integer, checked against the enum's declared
 * members. */
template <typename E>
E readEnum(CArchive& in, const char* field)
{
	const auto value = static_cast<E>(in.ReadAs<std::uint8_t>());
	std::string name;
	if (!mrpt::typemeta::TEnumType<E>::getBimap().direct(value, name))
		corrupted(std::string("unknown value of ") + field);
	return value;
}

/** The rendering options' colours in the order the file holds them. */
template <typename Options>
auto colorsOf(Options& o)
{
	return std::array{&o.freeColor,     &o.occupiedColor,  &o.unknownColor,
					  &o.conflictColor, &o.appearedColor, &o.disappearedColor};
}

bool readBool(CArchive& in, const char* field)
{
	const auto v = in.ReadAs<std::uint8_t>();
	if (v > 1) corrupted(std::string("invalid boolean ") + field);
	return v == 1;
}

/** The motion memory's cells as packed indices (the file's order). */
void writeMotionMemory(CArchive& ar, const GridGeometry& g, const CMotionDetector::TMemory& m)
{
	const auto packed = [&](std::size_t idx) {
		return static_cast<std::uint64_t>(g.rowOf(idx)) * static_cast<std::uint64_t>(g.sizeX) +
			static_cast<std::uint64_t>(g.columnOf(idx));
	};
	for (const std::vector<std::size_t>* list : {&m.arrivals, &m.leaving})
	{
		ar << static_cast<std::uint64_t>(list->size());
		for (const std::size_t idx : *list) ar << packed(idx);
	}
	ar << static_cast<std::uint64_t>(m.leavingKept);
}

/** Reads what writeMotionMemory() wrote for a grid of `cellCount` cells, as
 * packed indices; checks them (in the grid, the departures ascending). */
CMotionDetector::TMemory readMotionMemory(CArchive& ar, std::size_t cellCount)
{
	CMotionDetector::TMemory m;
	for (std::vector<std::size_t>* list : {&m.arrivals, &m.leaving})
	{
		// Each list names each cell once at most: a count beyond the grid
		// is corrupted. Memory follows the data read, not the count.
		const auto count = ar.ReadAs<std::uint64_t>();
		if (count > cellCount) corrupted("a motion list longer than the grid");
		list->reserve(static_cast<std::size_t>(std::min<std::uint64_t>(count, kCellsPerBlock)));
		for (std::uint64_t i = 0; i < count; ++i)
		{
			const auto packed = ar.ReadAs<std::uint64_t>();
			if (packed >= cellCount) corrupted("a motion list names a cell outside the grid");
			list->push_back(static_cast<std::size_t>(packed));
		}
	}
	if (std::adjacent_find(m.leaving.begin(), m.leaving.end(), std::greater_equal<>()) !=
		m.leaving.end())
		corrupted("the departures under way are not in ascending order");
	const auto kept = ar.ReadAs<std::uint64_t>();
	if (kept > cellCount) corrupted("a motion list's kept length beyond the grid");
	m.leavingKept = static_cast<std::size_t>(kept);
	return m;
}

void putU16(std::uint8_t* p, std::uint16_t v)
{
	p[0] = static_cast<std::uint8_t>(v & 0xFF);
	p[1] = static_cast<std::uint8_t>(v >> 8);
}
std::uint16_t getU16(const std::uint8_t* p)
{
	return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
}  // namespace

uint8_t CEvidentialGridMap2D::serializeGetVersion() const { return 6; }

void CEvidentialGridMap2D::serializeTo(CArchive& out) const
{
	// Options set in code are checked only when used: a map must not write
	// a file that reading refuses.
	detail::validateSavedOptions(
		insertionOptions, likelihoodOptions, renderingOptions, geometry().resolution);
	ChecksummedArchive ar(out);
	const GridGeometry& g = geometry();
	ar << g.xMin << g.yMin << g.resolution << static_cast<std::int32_t>(g.sizeX)
	   << static_cast<std::int32_t>(g.sizeY);
	ar << static_cast<std::uint64_t>(m_maxCells);

	const TInsertionOptions& io = insertionOptions;
	writeEnum(ar, io.sensorModel);
	ar << io.muF << io.muO << io.imprecision;
	writeEnum(ar, io.imprecisionProfile);
	ar << io.sectorWidth << io.maxRange
	   << static_cast<std::uint8_t>(io.invalidRangesAsFree) << io.freeMargin;
	writeEnum(ar, io.fusionRule);
	ar << io.decayRate << io.horizontalTolerance;
	writeEnum(ar, io.conflictHandling);
	ar << io.growthMargin << io.motionWindow << io.motionMinConflict
	   << io.motionClearance;
	writeEnum(ar, io.groundRemoval);
	ar << io.minObstacleHeight << io.maxObstacleHeight;
	writeEnum(ar, io.groundReturns);
	ar << static_cast<std::uint32_t>(io.insertionThreads);
	writeMotionMemory(ar, g, m_workspace->motion.memory(m_grid));

	const TLikelihoodOptions& lo = likelihoodOptions;
	ar << lo.occupiedMass << lo.maxCorrsDistance << lo.sigma << lo.zHit
	   << lo.zRandom << lo.maxRange << static_cast<std::uint32_t>(lo.decimation)
	   << static_cast<std::uint8_t>(lo.unknownAsNeutral);

	const TRenderingOptions& ro = renderingOptions;
	writeEnum(ar, ro.style);
	for (const mrpt::img::TColor* c : colorsOf(ro)) ar << c->R << c->G << c->B;
	for (const bool b : {ro.showFree, ro.showOccupied, ro.showConflict, ro.showMotion, ro.showUnknown})
		ar << static_cast<std::uint8_t>(b);
	ar << ro.height;

	ar << genericMapParams;

	const std::vector<double>& stamps = m_grid.stampTimes();
	ar << static_cast<std::uint32_t>(stamps.size());
	for (const double t : stamps) ar << t;
	ar << static_cast<std::uint64_t>(m_grid.insertionCount()) << m_grid.decayRate()
	   << static_cast<std::uint8_t>(m_grid.keepsConflict());

	// Explicit little-endian bytes: independent of the host's byte order and
	// of the struct's layout. Row by row: the file holds the cells packed,
	// not the room the grid keeps between its rows for growth.
	const auto& cells = m_grid.cells();
	const auto sizeX = static_cast<std::size_t>(g.sizeX);
	std::vector<std::uint8_t> block(std::min(sizeX, kCellsPerBlock) * kBytesPerCell);
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (std::size_t first = 0; first < sizeX; first += kCellsPerBlock)
		{
			const std::size_t n = std::min(kCellsPerBlock, sizeX - first);
			const QuantizedCell* row = cells.data() + g.index(0, cy) + first;
			for (std::size_t i = 0; i < n; ++i)
			{
				std::uint8_t* p = &block[i * kBytesPerCell];
				putU16(p, row[i].aside);
				putU16(p + 2, row[i].free);
				putU16(p + 4, row[i].occupied);
				putU16(p + 6, row[i].stamp);
			}
			ar.WriteBuffer(block.data(), n * kBytesPerCell);
		}

	out << ar.hash();  // little-endian, as the archive writes integers
}

void CEvidentialGridMap2D::serializeFrom(CArchive& in, uint8_t version)
{
	// Said in words: a fleet whose robots run different releases meets it.
	if (version > 6)
		throw std::runtime_error(
			"CEvidentialGridMap2D: a map of format version " + std::to_string(version) +
			", saved by a newer mrpt-evidential; this one reads versions 0 to 6");

	// Everything goes into locals: the map changes only once all is read,
	// checked and validated.
	ChecksummedArchive ar(in);
	GridGeometry g;
	ar >> g.xMin >> g.yMin >> g.resolution;
	g.sizeX = ar.ReadAs<std::int32_t>();
	g.sizeY = ar.ReadAs<std::int32_t>();
	const auto maxCells = ar.ReadAs<std::uint64_t>();
	// Sizes are checked before anything is allocated, so that a corrupted
	// size fails here rather than in a huge allocation.
	// The budget governs later growth: a forged one must not let a scan
	// allocate what no grid read from a file may hold.
	if (maxCells == 0 || maxCells > GridGeometry::kMaxCellBudget)
		corrupted("a cell budget of " + std::to_string(maxCells));
	if (g.sizeX < 1 || g.sizeY < 1) corrupted("an empty grid");
	if (g.cellCount() > maxCells)
		corrupted(
			"a grid of " + std::to_string(g.sizeX) + " x " +
			std::to_string(g.sizeY) + " cells, beyond the cell budget");

	TInsertionOptions io;
	io.sensorModel = readEnum<SensorModel>(ar, "sensorModel");
	ar >> io.muF >> io.muO >> io.imprecision;
	io.imprecisionProfile =
		readEnum<ImprecisionProfile>(ar, "imprecisionProfile");
	ar >> io.sectorWidth >> io.maxRange;
	io.invalidRangesAsFree = readBool(ar, "invalidRangesAsFree");
	if (version >= 2) ar >> io.freeMargin;
	else io.freeMargin = 0.0;  // what version 1 maps were built with
	io.fusionRule = readEnum<FusionRule>(ar, "fusionRule");
	ar >> io.decayRate >> io.horizontalTolerance;
	io.conflictHandling = readEnum<ConflictHandling>(ar, "conflictHandling");
	ar >> io.growthMargin;
	if (version >= 2) ar >> io.motionWindow >> io.motionMinConflict >> io.motionClearance;
	if (version >= 3)
	{
		io.groundRemoval = readEnum<GroundRemoval>(ar, "groundRemoval");
		ar >> io.minObstacleHeight >> io.maxObstacleHeight;
		io.groundReturns = readEnum<GroundReturns>(ar, "groundReturns");
	}
	CMotionDetector::TMemory motion;
	if (version >= 6)
	{
		io.insertionThreads = ar.ReadAs<std::uint32_t>();
		motion = readMotionMemory(ar, g.cellCount());
	}

	TLikelihoodOptions lo;
	ar >> lo.occupiedMass >> lo.maxCorrsDistance >> lo.sigma >> lo.zHit >>
		lo.zRandom >> lo.maxRange;
	lo.decimation = ar.ReadAs<std::uint32_t>();
	lo.unknownAsNeutral = readBool(ar, "unknownAsNeutral");

	TRenderingOptions ro;
	if (version >= 4)
	{
		ro.style = readEnum<RenderStyle>(ar, "style");
		for (mrpt::img::TColor* c : colorsOf(ro)) ar >> c->R >> c->G >> c->B;
		for (bool* b : {&ro.showFree, &ro.showOccupied, &ro.showConflict, &ro.showMotion, &ro.showUnknown})
			*b = readBool(ar, "show");
		ar >> ro.height;
	}

	mrpt::maps::TMapGenericParams generic;
	ar >> generic;

	const auto stampCount = ar.ReadAs<std::uint32_t>();
	// Version 1 kept up to 65535 times; the storage rebases such a table.
	const std::uint32_t maxStamps =
		version >= 2 ? EvidentialGridStorage::kMaxStamps : 65535;
	if (stampCount < 1 || stampCount > maxStamps)
		corrupted(std::to_string(stampCount) + " insertion times");
	std::vector<double> stamps(stampCount);
	for (double& t : stamps) ar >> t;
	const auto insertions = ar.ReadAs<std::uint64_t>();
	const auto decayRate = ar.ReadAs<double>();
	const bool keepsConflict = version >= 2
		? readBool(ar, "keepsConflict")
		: io.conflictHandling == ConflictHandling::Keep;

	// The cells are allocated as they arrive, beyond a first share that
	// typical maps fit in: a header that claims a huge grid in a short
	// (truncated or forged) stream fails when the data runs out, having
	// allocated at most twice what it read.
	const std::size_t cellCount = g.cellCount();
	std::vector<QuantizedCell> cells;
	cells.reserve(std::min(cellCount, kCellsTrustedAhead));
	std::vector<std::uint8_t> block(
		std::min(cellCount, kCellsPerBlock) * kBytesPerCell);
	for (std::size_t first = 0; first < cellCount; first += kCellsPerBlock)
	{
		const std::size_t n = std::min(kCellsPerBlock, cellCount - first);
		ar.ReadBuffer(block.data(), n * kBytesPerCell);
		if (first + n > cells.capacity())
			cells.reserve(std::min(cellCount, 2 * cells.capacity()));
		cells.resize(first + n);
		for (std::size_t i = 0; i < n; ++i)
		{
			const std::uint8_t* p = &block[i * kBytesPerCell];
			QuantizedCell& c = cells[first + i];
			c.aside = getU16(p);
			c.free = getU16(p + 2);
			c.occupied = getU16(p + 4);
			c.stamp = getU16(p + 6);
			if (version >= 2 && version < 5 && (c.stamp & kFlipped) != 0)
				corrupted("a cell of version " + std::to_string(version) + " has bit 15 of its stamp set");
			if (version == 0)
			{
				if (std::uint32_t(c.aside) + c.free + c.occupied > std::uint32_t(kMassScale))
					corrupted("a cell of version 0 holds masses above 1");
				c = fromVersion0(c);
			}
			if (version < 2 && !keepsConflict)
			{
				if (!isConsistent(c, true)) corrupted("a cell holds an invalid mass");
				c = EvidentialGridStorage::withoutConflict(c);
			}
		}
	}

	std::array<std::uint8_t, 8> stored{};
	readFully(in, stored.data(), stored.size());
	std::uint64_t checksum = 0;
	for (std::size_t i = stored.size(); i-- > 0;)
		checksum = (checksum << 8) | stored[i];
	if (checksum != ar.hash()) corrupted("checksum mismatch");

	try
	{
		detail::validateSavedOptions(io, lo, ro, g.resolution);
	}
	catch (const std::invalid_argument& e)
	{
		corrupted(std::string("invalid options: ") + e.what());
	}
	EvidentialGridStorage grid;
	try
	{
		grid.assign(
			g, std::move(cells), std::move(stamps),
			static_cast<std::size_t>(insertions), decayRate, keepsConflict,
			version < 2);
	}
	catch (const std::invalid_argument& e)
	{
		corrupted(e.what());
	}

	for (std::size_t& idx : motion.arrivals) idx = grid.geometry().indexOfPacked(idx);
	for (std::size_t& idx : motion.leaving) idx = grid.geometry().indexOfPacked(idx);

	// Commit: nothing below can fail (maxCells > 0 was checked).
	m_grid = std::move(grid);
	m_workspace->motion.restore(m_grid, std::move(motion));
	m_partlyInserted = 0;
	setMaxCells(static_cast<std::size_t>(maxCells));
	insertionOptions = io;
	likelihoodOptions = lo;
	renderingOptions = ro;
	genericMapParams = generic;
	invalidateLikelihoodCache();
}
