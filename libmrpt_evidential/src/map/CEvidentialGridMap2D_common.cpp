/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: construction, registration, options, reading cells. */

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "map/ConfigReading.h"
#include "map/MapWorkspace.h"

using namespace mrpt_evidential;
using mrpt_evidential::detail::enumName;

// The name must hold the exact rtti class name, then the .ini short name.
MAP_DEFINITION_REGISTER(
	"mrpt_evidential::CEvidentialGridMap2D,evidentialGrid",
	mrpt_evidential::CEvidentialGridMap2D)

IMPLEMENTS_SERIALIZABLE(CEvidentialGridMap2D, CMetricMap, mrpt_evidential)

// Known to the rtti system as soon as the library is loaded, so that archives
// (and CMultiMetricMap copies, which go through one) can create the class.
// A C++ initializer placed after the class id above: within one file these
// run in order. MRPT_INITIALIZER (a constructor attribute) may run before the
// id is initialized, as it does with clang, and register an empty name.
namespace
{
const struct RegisterClasses
{
	RegisterClasses() { mrpt::rtti::registerClass(CLASS_ID(CEvidentialGridMap2D)); }
} registerClasses;
}  // namespace

CEvidentialGridMap2D::TMapDefinition::TMapDefinition() = default;

void CEvidentialGridMap2D::TMapDefinition::loadFromConfigFile_map_specific(
	const mrpt::config::CConfigFileBase& source,
	const std::string& sectionNamePrefix)
{
	const std::string section = sectionNamePrefix + "_creationOpts";
	detail::readDouble(source, section, "min_x", min_x);
	detail::readDouble(source, section, "max_x", max_x);
	detail::readDouble(source, section, "min_y", min_y);
	detail::readDouble(source, section, "max_y", max_y);
	detail::readDouble(source, section, "resolution", resolution);
	detail::readCount(source, section, "maxCells", maxCells);
	if (const auto bad = GridGeometry::firstInvalid(
			min_x, max_x, min_y, max_y, resolution, maxCells))
	{
		const auto text = [&](const std::string& key, double value) {
			return detail::valueText(source, section, key, value);
		};
		std::string expected = "must be " + bad->rule;
		// A grid over its budget: the keys that make it, as the file gives them.
		if (bad->key == "maxCells" && maxCells > 0 &&
			maxCells <= GridGeometry::kMaxCellBudget)
		{
			expected += ":";
			for (const auto& [key, value] :
				 {std::pair("min_x", min_x), {"max_x", max_x}, {"min_y", min_y},
				  {"max_y", max_y}, {"resolution", resolution}})
				expected += std::string(" ") + key + " = '" + text(key, value) + "'";
		}
		detail::throwBadValue(section, bad->key, text(bad->key, bad->value), expected);
	}

	insertionOpts.loadFromConfigFile(source, sectionNamePrefix + "_insertOpts");
	// The polar grid's rules at this grid's cells (its bins are as long):
	// a maxRange too long for them fails here, not at the first scan.
	detail::throwIfInvalid(
		source, sectionNamePrefix + "_insertOpts",
		insertionOpts.sourceGridOptions(resolution).firstInvalid());
	likelihoodOpts.loadFromConfigFile(
		source, sectionNamePrefix + "_likelihoodOpts");
	renderingOpts.loadFromConfigFile(source, sectionNamePrefix + "_renderOpts");
}

void CEvidentialGridMap2D::TMapDefinition::dumpToTextStream_map_specific(
	std::ostream& out) const
{
	out << "min_x = " << min_x << " m\nmax_x = " << max_x
		<< " m\nmin_y = " << min_y << " m\nmax_y = " << max_y
		<< " m\nresolution = " << resolution << " m\nmaxCells = " << maxCells
		<< "\n";
	insertionOpts.dumpToTextStream(out);
	likelihoodOpts.dumpToTextStream(out);
	renderingOpts.dumpToTextStream(out);
}

compat::MapFactoryResult CEvidentialGridMap2D::internal_CreateFromMapDefinition(
	const mrpt::maps::TMetricMapInitializer& def)
{
	return compat::toMapFactoryResult(
		fromDefinition(dynamic_cast<const TMapDefinition&>(def)));
}

std::unique_ptr<CEvidentialGridMap2D> CEvidentialGridMap2D::fromDefinition(
	const TMapDefinition& d)
{
	// The budget first: a grid larger than the default budget may be asked
	// for together with a larger budget.
	auto map = std::make_unique<CEvidentialGridMap2D>(
		0.0, d.resolution, 0.0, d.resolution, d.resolution);
	map->setMaxCells(d.maxCells);
	map->setSize(d.min_x, d.max_x, d.min_y, d.max_y, d.resolution);
	map->insertionOptions = d.insertionOpts;
	map->likelihoodOptions = d.likelihoodOpts;
	map->renderingOptions = d.renderingOpts;
	return map;
}

CEvidentialGridMap2D::CWorkspace::CWorkspace()
	: m_work(std::make_unique<TWorkspace>())
{
}

CEvidentialGridMap2D::CWorkspace::CWorkspace(const CWorkspace& other)
	: CWorkspace()
{
	// The copied grid keeps the source's layout: the motion memory's
	// indices hold for it.
	m_work->motion = other->motion;
	std::lock_guard<std::mutex> lock(other->likelihoodMutex);
	m_work->likelihood = other->likelihood;
}

CEvidentialGridMap2D::CWorkspace& CEvidentialGridMap2D::CWorkspace::operator=(
	const CWorkspace& other)
{
	if (this != &other)
	{
		m_work->motion = other->motion;
		std::scoped_lock lock(m_work->likelihoodMutex, other->likelihoodMutex);
		m_work->likelihood = other->likelihood;
	}
	return *this;
}

CEvidentialGridMap2D::CWorkspace::~CWorkspace() = default;

CEvidentialGridMap2D::CEvidentialGridMap2D(
	double min_x, double max_x, double min_y, double max_y, double resolution)
{
	setSize(min_x, max_x, min_y, max_y, resolution);
}

void CEvidentialGridMap2D::setSize(
	double min_x, double max_x, double min_y, double max_y, double resolution)
{
	m_grid.reset(min_x, max_x, min_y, max_y, resolution, m_maxCells);
	m_partlyInserted = 0;
	invalidateLikelihoodCache();
}

void CEvidentialGridMap2D::setMaxCells(std::size_t maxCells)
{
	if (maxCells == 0 || maxCells > GridGeometry::kMaxCellBudget ||
		maxCells < geometry().cellCount())
		throw std::invalid_argument(
			"maxCells must be in [1, 1e9] and not below the grid's " +
			std::to_string(geometry().cellCount()) + " cells, got " +
			std::to_string(maxCells));
	m_maxCells = maxCells;
}

void CEvidentialGridMap2D::internal_clear()
{
	const GridGeometry g = geometry();
	setSize(g.xMin, g.xMax(), g.yMin, g.yMax(), g.resolution);
}

bool CEvidentialGridMap2D::isEmpty() const { return insertionCount() == 0; }

mrpt::math::TBoundingBoxf CEvidentialGridMap2D::boundingBox() const
{
	return {
		{static_cast<float>(getXMin()), static_cast<float>(getYMin()), 0.0f},
		{static_cast<float>(getXMax()), static_cast<float>(getYMax()), 0.0f}};
}

Mass CEvidentialGridMap2D::getCellMassesByIndex(int cx, int cy) const
{
	const GridGeometry& g = geometry();
	if (!g.inside(cx, cy)) return Mass::vacuous();
	return m_grid.read(g.index(cx, cy));
}

Mass CEvidentialGridMap2D::getCellMasses(double x, double y) const
{
	const GridGeometry& g = geometry();
	if (!(x >= g.xMin && x < g.xMax() && y >= g.yMin && y < g.yMax()))
		return Mass::vacuous();  // NaN included
	return getCellMassesByIndex(g.cellX(x), g.cellY(y));
}

double CEvidentialGridMap2D::getCellBetP(double x, double y) const
{
	return betP(getCellMasses(x, y));
}

Decision CEvidentialGridMap2D::getCellDecision(double x, double y) const
{
	return decide(getCellMasses(x, y));
}

CEvidentialGridMap2D::TDecisionCounts CEvidentialGridMap2D::countDecisions()
	const
{
	TDecisionCounts counts;
	geometry().forEachIndex([&](std::size_t i) {
		switch (decide(m_grid.read(i)))
		{
			case Decision::Free: ++counts.free; break;
			case Decision::Occupied: ++counts.occupied; break;
			case Decision::Unknown: ++counts.unknown; break;
			case Decision::Conflict: ++counts.conflict; break;
		}
	});
	return counts;
}

std::string CEvidentialGridMap2D::asString() const
{
	const GridGeometry& g = geometry();
	const TDecisionCounts c = countDecisions();
	std::ostringstream s;
	s << "Evidential grid " << g.sizeX << " x " << g.sizeY << " cells of "
	  << g.resolution << " m over x [" << g.xMin << ", " << g.xMax()
	  << "] y [" << g.yMin << ", " << g.yMax() << "], " << insertionCount()
	  << " observations; cells free " << c.free << ", occupied " << c.occupied
	  << ", unknown " << c.unknown << ", conflict " << c.conflict;
	return s.str();
}

float CEvidentialGridMap2D::compute3DMatchingRatio(
	const mrpt::maps::CMetricMap*, const mrpt::poses::CPose3D&,
	const mrpt::maps::TMatchingRatioParams&) const
{
	return 0.0f;
}

// ---------------------------------------------------------------------------
// Insertion options
// ---------------------------------------------------------------------------

using detail::isMember;

std::optional<TInvalidOption> TEvidentialInsertionOptions::firstInvalidOfTheMap() const
{
	// Written as !(valid) so that NaN fails every test.
	if (!isMember(sensorModel))
		return TInvalidOption{"sensorModel", "a known model", double(sensorModel)};
	if (!isMember(imprecisionProfile))
		return TInvalidOption{
			"imprecisionProfile", "a known profile", double(imprecisionProfile)};
	if (!isMember(fusionRule))
		return TInvalidOption{"fusionRule", "a known rule", double(fusionRule)};
	if (!(decayRate >= 0.0 && std::isfinite(decayRate)))
		return TInvalidOption{
			"decayRate", "a finite number >= 0 (per second)", decayRate};
	if (!(horizontalTolerance >= 0.0 && horizontalTolerance <= M_PI / 2))
		return TInvalidOption{
			"horizontalTolerance", "in [0, pi/2] rad (0 to 90 degrees)",
			horizontalTolerance};
	if (!isMember(conflictHandling))
		return TInvalidOption{
			"conflictHandling", "a known handling", double(conflictHandling)};
	if (!(growthMargin >= 0.0 && std::isfinite(growthMargin)))
		return TInvalidOption{"growthMargin", "a finite number >= 0 (m)", growthMargin};
	if (!(motionWindow > 0.0 && motionWindow <= 1e6))
		return TInvalidOption{"motionWindow", "in (0, 1e6] (s)", motionWindow};
	if (!(motionMinConflict > 0.0 && motionMinConflict <= 1.0))
		return TInvalidOption{"motionMinConflict", "in (0, 1]", motionMinConflict};
	if (!(motionClearance >= 0.0 && motionClearance <= 10.0))
		return TInvalidOption{"motionClearance", "in [0, 10] (m)", motionClearance};
	if (!isMember(groundRemoval))
		return TInvalidOption{"groundRemoval", "a known removal", double(groundRemoval)};
	if (!(minObstacleHeight >= 0.0 && minObstacleHeight < 1000.0))
		return TInvalidOption{"minObstacleHeight", "in [0, 1000) (m)", minObstacleHeight};
	if (!(maxObstacleHeight > minObstacleHeight && maxObstacleHeight <= 1000.0))
		return TInvalidOption{
			"maxObstacleHeight", "in (minObstacleHeight, 1000] (m)", maxObstacleHeight};
	if (!isMember(groundReturns))
		return TInvalidOption{"groundReturns", "a known meaning", double(groundReturns)};
	if (!(insertionThreads >= 1 && insertionThreads <= kMaxInsertionThreads))
		return TInvalidOption{"insertionThreads", "in [1, 64]", double(insertionThreads)};
	return std::nullopt;
}

std::optional<TInvalidOption> TEvidentialInsertionOptions::firstInvalid() const
{
	if (auto bad = firstInvalidOfTheMap()) return bad;
	// The sensor model's and the polar grid's rules, for cells of 1 m (the
	// grid's own size is checked at each scan).
	return sourceGridOptions(1.0).firstInvalid();
}

void TEvidentialInsertionOptions::validate() const
{
	if (const auto bad = firstInvalid()) throw std::invalid_argument(bad->describe());
}

TSourceGridOptions TEvidentialInsertionOptions::sourceGridOptions(double resolution) const
{
	TSourceGridOptions o;
	o.sensorModel.model = sensorModel;
	o.sensorModel.muF = muF;
	o.sensorModel.muO = muO;
	o.sensorModel.imprecision = imprecision;
	o.sensorModel.profile = imprecisionProfile;
	o.sectorWidth = sectorWidth;
	o.maxRange = maxRange;
	o.binSize = resolution;
	o.invalidRangesAsFree = invalidRangesAsFree;
	o.freeMargin = freeMargin;
	return o;
}

void TEvidentialInsertionOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	TEvidentialInsertionOptions o = *this;  // all or nothing: *this changes only if valid
	detail::readEnum(source, section, "sensorModel", o.sensorModel);
	detail::readDouble(source, section, "muF", o.muF);
	detail::readDouble(source, section, "muO", o.muO);
	detail::readDouble(source, section, "imprecision", o.imprecision);
	detail::readEnum(source, section, "imprecisionProfile", o.imprecisionProfile);
	detail::readDegrees(source, section, "sectorWidth", o.sectorWidth);
	detail::readDouble(source, section, "maxRange", o.maxRange);
	detail::readBool(source, section, "invalidRangesAsFree", o.invalidRangesAsFree);
	detail::readDouble(source, section, "freeMargin", o.freeMargin);
	detail::readEnum(source, section, "fusionRule", o.fusionRule);
	detail::readDouble(source, section, "decayRate", o.decayRate);
	detail::readDegrees(
		source, section, "horizontalTolerance", o.horizontalTolerance);
	detail::readEnum(source, section, "conflictHandling", o.conflictHandling);
	detail::readDouble(source, section, "growthMargin", o.growthMargin);
	detail::readDouble(source, section, "motionWindow", o.motionWindow);
	detail::readDouble(source, section, "motionMinConflict", o.motionMinConflict);
	detail::readDouble(source, section, "motionClearance", o.motionClearance);
	detail::readEnum(source, section, "groundRemoval", o.groundRemoval);
	detail::readDouble(source, section, "minObstacleHeight", o.minObstacleHeight);
	detail::readDouble(source, section, "maxObstacleHeight", o.maxObstacleHeight);
	detail::readEnum(source, section, "groundReturns", o.groundReturns);
	detail::readCount(source, section, "insertionThreads", o.insertionThreads);
	// The value in the message is the text of the file, as the user wrote it.
	detail::throwIfInvalid(source, section, o.firstInvalid());
	*this = o;
}

void TEvidentialInsertionOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& target, const std::string& section) const
{
	using detail::writeValue;
	const double toDegrees = 180.0 / M_PI;
	writeValue(target, section, "sensorModel", sensorModel,
			   "MultiEcho, ReinforcedMultiEcho or ImpreciseMultiEcho");
	writeValue(target, section, "muF", muF, "detection rate, [0, 1]");
	writeValue(target, section, "muO", muO, "true-positive rate, [0, 1]");
	writeValue(target, section, "imprecision", imprecision,
			   "m, half-width of an impact (ImpreciseMultiEcho)");
	writeValue(target, section, "imprecisionProfile", imprecisionProfile,
			   "Box or Gaussian");
	writeValue(target, section, "sectorWidth", sectorWidth * toDegrees,
			   "deg, 0 = one sector per beam (0.5 for clouds)");
	writeValue(target, section, "maxRange", maxRange, "m");
	writeValue(target, section, "invalidRangesAsFree", invalidRangesAsFree,
			   "a beam without return proves free space");
	writeValue(target, section, "freeMargin", freeMargin,
			   "m before each impact where a beam proves nothing free");
	writeValue(target, section, "fusionRule", fusionRule,
			   "Conjunctive, Dempster, Yager, DuboisPrade or Cautious");
	writeValue(target, section, "decayRate", decayRate, "1/s of data time, 0 = none");
	writeValue(target, section, "horizontalTolerance",
			   horizontalTolerance * toDegrees, "deg of pitch or roll");
	writeValue(target, section, "conflictHandling", conflictHandling,
			   "Keep, ToUnknown or Normalize");
	writeValue(target, section, "growthMargin", growthMargin,
			   "m added when the grid grows");
	writeValue(target, section, "motionWindow", motionWindow,
			   "s of data time a motion event stays");
	writeValue(target, section, "motionMinConflict", motionMinConflict,
			   "least conflict of one cause for a motion event, (0, 1]");
	writeValue(target, section, "motionClearance", motionClearance,
			   "m from static structure below which a change is pose error");
	writeValue(target, section, "groundRemoval", groundRemoval,
			   "3-D clouds' ground: Plane, Terrain, Height or None");
	writeValue(target, section, "minObstacleHeight", minObstacleHeight,
			   "m above the ground where a cloud's obstacles begin");
	writeValue(target, section, "maxObstacleHeight", maxObstacleHeight,
			   "m above the ground where they end (higher points: nothing)");
	writeValue(target, section, "groundReturns", groundReturns,
			   "what a ground point proves: FreeSpace or Nothing");
	writeValue(target, section, "insertionThreads", double(insertionThreads),
			   "threads that fuse an observation's cells, [1, 64]; the same map");
}

void TEvidentialInsertionOptions::dumpToTextStream(std::ostream& out) const
{
	detail::dumpAsIni(*this, "insertOpts", out);
}
