/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include <mrpt_evidential/grid/EvidentialGridStorage.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <mrpt_evidential/support/NumberText.h>

namespace mrpt_evidential
{
namespace
{
/** Files of serialization version 1 kept up to this many insertion times. */
constexpr std::size_t kMaxStampsOfVersion1 = 65535;
/** Above this exponent the gains are rebased, long before exp() overflows. */
constexpr double kMaxGainExponent = 200.0;
/** A rebase keeps the stamps of events whose decay exponent is at most this,
 * so that the next rebase is at least as far away again. */
constexpr double kMaxKeptEventExponent = 100.0;
/** A rebase keeps at most this many event times: the other half of the
 * table is room for new insertions. */
constexpr std::size_t kMaxKeptEventTimes = EvidentialGridStorage::kMaxStamps / 2;
/** Room a grid that outgrows its block gets beyond each side that grows, as
 * a share of its extent along that axis: a path one way moves the cells
 * some log5(length) times. The room is fresh zeroed memory (vacuous cells),
 * resident only once the grid grows into it, so it may be generous. Near
 * the cell budget the share is halved down to the least, then the block
 * gets no room. */
constexpr double kGrowthRoom = 4.0, kLeastGrowthRoom = 1.0 / 16;
/** Room beyond the sides that do not grow, as a share of the growing sides'
 * room: a path that turns finds room without a copy of the grid (each copy
 * writes the grid's cells into fresh memory). */
constexpr double kAsideRoom = 0.5;

/** A layout number no grid has had. */
std::size_t newLayout()
{
	static std::atomic<std::size_t> next{1};
	return next++;
}

std::uint16_t ceilingFor(bool keepsConflict)
{
	return keepsConflict
		? static_cast<std::uint16_t>(kMassScale)
		: quantizeMass(EvidentialGridStorage::kMaxCertainty);
}
}  // namespace

EvidentialGridStorage::EvidentialGridStorage(EvidentialGridStorage&& other)
	: detail::TGridStorageState(std::move(other))
{
	static_cast<detail::TGridStorageState&>(other) = detail::TGridStorageState{};
}

EvidentialGridStorage& EvidentialGridStorage::operator=(EvidentialGridStorage&& other)
{
	if (this != &other)
	{
		static_cast<detail::TGridStorageState&>(*this) = std::move(other);
		static_cast<detail::TGridStorageState&>(other) = detail::TGridStorageState{};
	}
	return *this;
}

void EvidentialGridStorage::reset(
	double xMin, double xMax, double yMin, double yMax, double resolution,
	std::size_t maxCells)
{
	if (const auto bad = GridGeometry::firstInvalid(
			xMin, xMax, yMin, yMax, resolution, maxCells))
		throw std::invalid_argument("grid: " + bad->describe());
	const double sx = GridGeometry::cellsToCover(xMax - xMin, resolution);
	const double sy = GridGeometry::cellsToCover(yMax - yMin, resolution);
	m_geometry = {xMin, yMin, resolution, static_cast<int>(sx), static_cast<int>(sy)};
	m_cells = CellBlock(m_geometry.cellCount());
	m_layout = newLayout();
	m_grownFrom = {};
	m_stampTimes.assign(1, 0.0);
	m_stampGain.assign(1, 1.0);
	m_presentGain = 1.0;
	m_currentStamp = 0;
	m_insertions = 0;
	m_pristine = true;
}

bool EvidentialGridStorage::growToInclude(
	double xMin, double xMax, double yMin, double yMax, double margin,
	std::size_t maxCells)
{
	for (const double v : {xMin, xMax, yMin, yMax, margin})
		if (!std::isfinite(v)) return false;
	const GridGeometry& g = m_geometry;
	const double res = g.resolution;
	const bool growLeft = xMin < g.xMin, growRight = xMax > g.xMax();
	const bool growDown = yMin < g.yMin, growUp = yMax > g.yMax();
	if (!growLeft && !growRight && !growDown && !growUp) return true;

	const auto cellsFor = [res](double length) {
		return GridGeometry::cellsToCover(length, res);
	};
	double addLeft = 0, addRight = 0, addDown = 0, addUp = 0, sx = 0, sy = 0;
	const auto fitsWith = [&](double m) {
		addLeft = growLeft ? cellsFor(g.xMin - xMin + m) : 0;
		addRight = growRight ? cellsFor(xMax - g.xMax() + m) : 0;
		addDown = growDown ? cellsFor(g.yMin - yMin + m) : 0;
		addUp = growUp ? cellsFor(yMax - g.yMax() + m) : 0;
		sx = g.sizeX + addLeft + addRight, sy = g.sizeY + addDown + addUp;
		const double x0 = g.xMin - addLeft * res, y0 = g.yMin - addDown * res;
		return sx * sy <= static_cast<double>(maxCells) &&
			std::max(sx, sy) <= std::numeric_limits<int>::max() &&
			GridGeometry::withinLimits(x0, x0 + sx * res, y0, y0 + sy * res, res);
	};
	// Near the budget (or the limits) the margin gives way before the
	// growth does, halved down to none: the scan is then held whole.
	bool marginFits = fitsWith(margin);
	for (double m = margin / 2; !marginFits && m >= res; m /= 2) marginFits = fitsWith(m);
	if (!marginFits && !fitsWith(0.0)) return false;
	GridGeometry grown{
		g.xMin - addLeft * res, g.yMin - addDown * res, res, static_cast<int>(sx),
		static_cast<int>(sy)};

	// The room kept around the cells, in cells on each side.
	const auto stride = static_cast<double>(g.stride());
	const double rows = stride > 0 ? static_cast<double>(m_cells.size()) / stride : 0;
	const double ox = stride > 0 ? static_cast<double>(g.firstIndex % g.stride()) : 0;
	const double oy = stride > 0 ? static_cast<double>(g.firstIndex / g.stride()) : 0;
	if (g.cellCount() > 0 && addLeft <= ox && addRight <= stride - ox - g.sizeX &&
		addDown <= oy && addUp <= rows - oy - g.sizeY)
	{
		// Within the room: the new cells are vacuous already, none moves.
		grown.rowStride = g.stride();
		grown.firstIndex = static_cast<std::size_t>(oy - addDown) * g.stride() +
			static_cast<std::size_t>(ox - addLeft);
		m_geometry = grown;
		writeOnlyTheGrid();
		return true;
	}

	// A new block, with room beyond each side that grows for up to four
	// times the grid's extent, and half of that beyond the others (a path
	// that turns back): a grid that keeps growing is copied a few times in
	// all, not every few metres. The room stays within the budget of cells:
	// near it, the other sides' room is halved first, down to none, then the
	// growing sides' room, until the block fits.
	double roomLeft = 0, roomRight = 0, roomDown = 0, roomUp = 0;
	const auto fits = [&](double share, double asideShare) {
		const double spareX = std::floor(share * sx), spareY = std::floor(share * sy);
		const double asideX = std::floor(asideShare * sx), asideY = std::floor(asideShare * sy);
		roomLeft = growLeft ? spareX : asideX, roomRight = growRight ? spareX : asideX;
		roomDown = growDown ? spareY : asideY, roomUp = growUp ? spareY : asideY;
		const double width = sx + roomLeft + roomRight, height = sy + roomDown + roomUp;
		return width * height <= static_cast<double>(maxCells) &&
			width <= std::numeric_limits<int>::max();
	};
	bool roomFits = false;
	for (double share = kGrowthRoom; !roomFits && share >= kLeastGrowthRoom; share /= 2)
	{
		for (double aside = share * kAsideRoom; !roomFits && aside >= share * kLeastGrowthRoom;
			 aside /= 2)
			roomFits = fits(share, aside);
		roomFits = roomFits || fits(share, 0.0);
	}
	if (!roomFits) roomLeft = roomRight = roomDown = roomUp = 0;
	const auto width = static_cast<std::size_t>(sx + roomLeft + roomRight);
	const auto height = static_cast<std::size_t>(sy + roomDown + roomUp);
	grown.rowStride = width;
	grown.firstIndex =
		static_cast<std::size_t>(roomDown) * width + static_cast<std::size_t>(roomLeft);
	// New cells are vacuous: their stamp does not matter, vacuous never decays.
	CellBlock cells(width * height);
	const int dx = static_cast<int>(addLeft), dy = static_cast<int>(addDown);
	cells.copyWrittenRows(
		m_cells, g.index(0, 0), g.stride(), grown.index(dx, dy), grown.stride(),
		static_cast<std::size_t>(g.sizeX), static_cast<std::size_t>(g.sizeY));
	m_cells = std::move(cells);
	m_grownFrom = {m_layout, g, dx, dy};
	m_geometry = grown;
	writeOnlyTheGrid();
	m_layout = newLayout();
	return true;
}

void EvidentialGridStorage::writeOnlyTheGrid()
{
	const GridGeometry& g = m_geometry;
	m_cells.setWritableRows(
		g.firstIndex, static_cast<std::size_t>(g.sizeX), g.stride(),
		static_cast<std::size_t>(g.sizeY));
}

std::vector<QuantizedCell> EvidentialGridStorage::packedCells() const
{
	const GridGeometry& g = m_geometry;
	std::vector<QuantizedCell> out;
	out.reserve(g.cellCount());
	for (int cy = 0; cy < g.sizeY; ++cy)
	{
		const QuantizedCell* row = m_cells.data() + g.index(0, cy);
		out.insert(out.end(), row, row + g.sizeX);
	}
	return out;
}

void EvidentialGridStorage::setDecayRate(double perSecond)
{
	if (!(perSecond >= 0.0 && std::isfinite(perSecond)))
		throw std::invalid_argument(
			"decay rate must be a finite number >= 0, got " +
			detail::shortestText(perSecond));
	if (perSecond == m_decayRate) return;
	// Cells decay under the old rate up to now, under the new one from now
	// on; before the first insertion there is nothing to decay.
	if (m_insertions > 0) rebaseStamps(latestTime());
	m_decayRate = perSecond;
	updateGains();
}

QuantizedCell EvidentialGridStorage::withoutConflict(QuantizedCell c)
{
	const std::uint16_t ceiling = ceilingFor(false);
	c.aside = 0;
	c.free = std::min(c.free, ceiling);
	c.occupied = std::min(c.occupied, ceiling);
	return c;
}

void EvidentialGridStorage::setKeepsConflict(bool keeps)
{
	if (keeps == m_keepsConflict) return;
	// A grid fresh from reset() holds vacuous cells only, which read the same
	// either way: a map's first insertion does not walk its whole grid.
	if (!m_pristine)
		m_geometry.forEachIndex([&](std::size_t i) {
			QuantizedCell& c = m_cells[i];
			c = keeps ? QuantizedCell{0, c.free, c.occupied, c.stamp} : withoutConflict(c);
		});
	m_keepsConflict = keeps;
	m_ceiling = ceilingFor(keeps);
}

void EvidentialGridStorage::setEventRetention(double seconds)
{
	if (!(seconds >= 0.0))
		throw std::invalid_argument(
			"event retention must be >= 0 s, got " + detail::shortestText(seconds));
	m_eventRetention = seconds;
}

void EvidentialGridStorage::beginInsertion(double t)
{
	if (!std::isfinite(t))
		throw std::invalid_argument("insertion time must be a finite number");
	m_pristine = false;
	if (m_insertions++ == 0)
	{
		m_stampTimes.assign(1, t);
		updateGains();
		m_currentStamp = 0;
		return;
	}
	if (t <= latestTime()) return;  // same stamp: nothing decays
	if (m_stampTimes.size() >= kMaxStamps ||
		m_decayRate * (t - m_stampTimes.front()) > kMaxGainExponent)
	{
		// Rebased to t itself: the step from the latest time alone may be
		// too long for the gains (exp overflows, and 0 * inf reads as NaN).
		rebaseStamps(t);
		return;
	}
	const double sinceOrigin = t - m_stampTimes.front();
	m_stampTimes.push_back(t);
	m_stampGain.push_back(std::exp(m_decayRate * sinceOrigin));
	m_presentGain = std::exp(-m_decayRate * sinceOrigin);
	m_currentStamp = static_cast<std::uint16_t>(m_stampTimes.size() - 1);
}

void EvidentialGridStorage::rebaseStamps(double to)
{
	if (m_decayRate > 0.0)
	{
		// Each stamp's factor straight from its time, never from the gains:
		// this also serves steps too long for them.
		std::vector<double> factor(m_stampTimes.size());
		for (std::size_t s = 0; s < factor.size(); ++s)
			factor[s] = std::exp(-m_decayRate * (to - m_stampTimes[s]));
		// The grid's cells only: the room kept for growth is vacuous, and
		// stays untouched (no resident memory).
		m_geometry.forEachIndex([&](std::size_t i) {
			QuantizedCell& c = m_cells[i];
			const double d = factor[c.stamp & kStampMask];
			if (d >= 1.0) return;
			if (m_keepsConflict)
				encodeMass(decayed(decodeMass(c), d), c);
			else
				encodeNormal(decayed(decodeNormal(c), d), c);
		});
	}
	// The times of recent events survive, oldest first; `to` comes last and
	// is every cell's stamp.
	std::vector<double> times;
	std::vector<std::uint16_t> newStamp(m_stampTimes.size(), kEventStampMask);
	if (!m_keepsConflict)
	{
		std::size_t first = m_stampTimes.size();
		while (first > 0 && m_stampTimes.size() - first < kMaxKeptEventTimes)
		{
			const double t = m_stampTimes[first - 1];
			if (t < to - m_eventRetention ||
				m_decayRate * (to - t) > kMaxKeptEventExponent)
				break;
			--first;
		}
		for (std::size_t s = first; s < m_stampTimes.size(); ++s)
			if (m_stampTimes[s] < to)
			{
				newStamp[s] = static_cast<std::uint16_t>(times.size());
				times.push_back(m_stampTimes[s]);
			}
	}
	const auto present = static_cast<std::uint16_t>(times.size());
	times.push_back(to);
	for (std::size_t s = 0; s < m_stampTimes.size(); ++s)
		if (m_stampTimes[s] == to) newStamp[s] = present;
	m_geometry.forEachIndex([&](std::size_t i) {
		QuantizedCell& c = m_cells[i];
		c.stamp = static_cast<std::uint16_t>((c.stamp & kStampFlags) | present);
		if (m_keepsConflict || eventOf(c) == CellEvent::None) return;
		const std::uint16_t s = newStamp[eventStampOf(c)];
		c.aside = s == kEventStampMask ? 0 : packEvent(eventOf(c), s);
	});
	m_stampTimes = std::move(times);
	m_currentStamp = present;
	updateGains();
}

void EvidentialGridStorage::updateGains()
{
	const double origin = m_stampTimes.front();
	m_stampGain.resize(m_stampTimes.size());
	for (std::size_t s = 0; s < m_stampTimes.size(); ++s)
		m_stampGain[s] = std::exp(m_decayRate * (m_stampTimes[s] - origin));
	m_presentGain = std::exp(-m_decayRate * (latestTime() - origin));
}

void EvidentialGridStorage::assign(
	const GridGeometry& geometry, std::vector<QuantizedCell> cells,
	std::vector<double> stampTimes, std::size_t insertions, double decayRate,
	bool keepsConflict, bool plainStamps)
{
	if (geometry.sizeX < 0 || geometry.sizeY < 0 ||
		!GridGeometry::withinLimits(
			geometry.xMin, geometry.xMax(), geometry.yMin, geometry.yMax(),
			geometry.resolution))
		throw std::invalid_argument("invalid grid geometry");
	if (cells.size() != geometry.cellCount())
		throw std::invalid_argument(
			"cell count " + std::to_string(cells.size()) +
			" does not match the geometry");
	// Before the first insertion there is one time: the first insertion
	// starts the table again, and must not leave a cell with a later stamp.
	if (stampTimes.empty() ||
		stampTimes.size() > (plainStamps ? kMaxStampsOfVersion1 : kMaxStamps) ||
		(insertions == 0 && stampTimes.size() != 1))
		throw std::invalid_argument("invalid number of insertion times");
	for (std::size_t i = 0; i < stampTimes.size(); ++i)
		if (!std::isfinite(stampTimes[i]) ||
			(i > 0 && stampTimes[i] < stampTimes[i - 1]))
			throw std::invalid_argument("insertion times must be finite and ordered");
	if (!(decayRate >= 0.0 && std::isfinite(decayRate)) ||
		decayRate * (stampTimes.back() - stampTimes.front()) > kMaxGainExponent)
		throw std::invalid_argument("invalid decay rate");
	const std::uint16_t ceiling = ceilingFor(keepsConflict);
	if (plainStamps)
	{
		for (const QuantizedCell& c : cells)
			if (c.stamp >= stampTimes.size())
				throw std::invalid_argument("a cell holds an invalid stamp");
		if (stampTimes.size() > kMaxStamps)
		{
			// Every cell decayed to the latest time, the one time kept.
			const double latest = stampTimes.back();
			for (QuantizedCell& c : cells)
			{
				const double d = std::exp(-decayRate * (latest - stampTimes[c.stamp]));
				if (d < 1.0)
				{
					if (keepsConflict)
						encodeMass(decayed(decodeMass(c), d), c);
					else
						encodeNormal(decayed(decodeNormal(c), d), c);
				}
				c.stamp = 0;
			}
			stampTimes.assign(1, latest);
		}
		for (QuantizedCell& c : cells)
			if (c.occupied > c.free) c.stamp |= kHeldImpact;
	}
	for (const QuantizedCell& c : cells)
		if (!isConsistent(c, keepsConflict) || (c.stamp & ~(kStampMask | kStampFlags)) != 0 ||
			(c.stamp & kStampMask) >= stampTimes.size() ||
			(!keepsConflict &&
			 (std::max(c.free, c.occupied) > ceiling ||
			  (eventOf(c) != CellEvent::None && eventStampOf(c) >= stampTimes.size()))))
			throw std::invalid_argument("a cell holds an invalid mass, stamp or event");
	m_geometry = geometry.packed();
	m_cells = CellBlock(cells.size());
	m_cells.copyWritten(cells.data(), cells.size(), 0);
	m_layout = newLayout();
	m_grownFrom = {};
	m_stampTimes = std::move(stampTimes);
	m_insertions = insertions;
	m_decayRate = decayRate;
	m_keepsConflict = keepsConflict;
	m_pristine = false;
	m_ceiling = ceiling;
	m_currentStamp = static_cast<std::uint16_t>(m_stampTimes.size() - 1);
	updateGains();
}

}  // namespace mrpt_evidential
