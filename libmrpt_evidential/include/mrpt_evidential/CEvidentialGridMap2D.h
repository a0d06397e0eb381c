/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The evidential grid as an MRPT metric map. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/Clock.h>
#include <mrpt/img/TColor.h>
#include <mrpt/math/TBoundingBox.h>
#include <mrpt/math/TPoint3D.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt_evidential/EnumNames.h>
#include <mrpt_evidential/Motion.h>
#include <mrpt_evidential/MrptCompat.h>
#include <mrpt_evidential/RenderStyle.h>
#include <mrpt_evidential/algebra/combination.h>
#include <mrpt_evidential/grid/EvidentialGridStorage.h>
#include <mrpt_evidential/scan/CPolarSourceGrid.h>

#include <array>
#include <functional>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mrpt::img
{
class CImage;
}
namespace mrpt::maps
{
class COccupancyGridMap2D;
}

namespace mrpt_evidential
{
class CScanImpacts;
struct PlanarSensorPose;

/** An evidential (Dempster-Shafer) occupancy grid, an MRPT metric map.
 *
 * Each cell holds a mass function on {F, O} (Mass): free, occupied, unknown
 * and conflict. `CObservation2DRangeScan`s are turned into a polar SourceGrid
 * by one of the lidar inverse sensor models (SensorModel.h), placed at the
 * sensor's pose, interpolated bilinearly onto the cells they inform, and fused
 * with the cells' previous masses, decayed by the data time elapsed since
 * they were last written. Every cell is fused at most once per scan. 3-D
 * clouds (`CObservationPointCloud`, `CObservationVelodyneScan`,
 * `CObservation3DRangeScan`) go the same way once their ground is removed
 * and their points grouped by azimuth (TInsertionOptions::groundRemoval).
 * Other observations are not for this map: insertObservation() returns false.
 *
 * In a CMultiMetricMap .ini file it is the map `evidentialGrid`:
 * \code
 * [MappingApplication_MetricMaps]
 * evidentialGrid_count=1
 * [MappingApplication_MetricMaps_evidentialGrid_00_creationOpts]
 * min_x=-10 max_x=10 min_y=-10 max_y=10 resolution=0.05
 * [MappingApplication_MetricMaps_evidentialGrid_00_insertOpts]
 * sensorModel=ReinforcedMultiEcho muF=0.7 muO=0.9 fusionRule=Conjunctive
 * \endcode
 * Loading the library is all a program needs (LD_PRELOAD, rawlog-edit -p,
 * RawLogViewer -l, mrpt::system::loadPluginModule, or linking it).
 *
 * Cells are 8 bytes: three masses in 16-bit fixed point (a stored mass is
 * within 1/131070 of the exact one) and a time stamp (EvidentialGridStorage).
 *
 * Threads:
 * - Const methods may run from any number of threads at once on the same
 *   map: reading cells (getCellMasses*, getCellBetP, getCellDecision,
 *   countDecisions, storage()), pictures and conversions (getAs*,
 *   getOccupiedCellCenters, saveAsROSMap and saveMetricMapRepresentationToFile
 *   to different files), asString, serialization into different archives,
 *   copies, and computeObservationLikelihood, whose likelihood field the
 *   first caller builds under a lock while the others wait for it.
 * - Nothing may change the map meanwhile: insertion, clear, setSize,
 *   setMaxCells, deserialization and assigning to insertionOptions,
 *   likelihoodOptions or genericMapParams need the map to themselves.
 * - Distinct maps share nothing and may be used from different threads
 *   freely.
 * tests/test_threads.cpp checks the first rule under ThreadSanitizer
 * (doc/reliability.md). */
class CEvidentialGridMap2D : public mrpt::maps::CMetricMap
{
	DEFINE_SERIALIZABLE(CEvidentialGridMap2D, mrpt_evidential)

   public:
	/** Default cell budget: 100 million cells, 800 MB. */
	static constexpr std::size_t kDefaultMaxCells = 100'000'000;

	/** A grid covering [min_x, max_x] x [min_y, max_y] with square cells of
	 * `resolution` metres, every cell vacuous.
	 * \throws std::invalid_argument as setSize(). */
	explicit CEvidentialGridMap2D(
		double min_x = -10.0, double max_x = 10.0, double min_y = -10.0,
		double max_y = 10.0, double resolution = 0.10);

	/** Discards every cell and sets a new geometry (the cell budget stays).
	 * \throws std::invalid_argument if the resolution is not in [1e-6, 1e6]
	 *  m, a bound is not within 1e9 m of the origin, min >= max, or the grid
	 *  would exceed maxCells(). */
	void setSize(
		double min_x, double max_x, double min_y, double max_y,
		double resolution);

	/** Largest number of cells the grid may grow to when scans reach beyond
	 * it. \throws std::invalid_argument if 0 or below the current number of
	 * cells. */
	void setMaxCells(std::size_t maxCells);
	std::size_t maxCells() const { return m_maxCells; }

	/** @name Geometry
	 * @{ */
	const GridGeometry& geometry() const { return m_grid.geometry(); }
	double getXMin() const { return geometry().xMin; }
	double getXMax() const { return geometry().xMax(); }
	double getYMin() const { return geometry().yMin; }
	double getYMax() const { return geometry().yMax(); }
	double getResolution() const { return geometry().resolution; }
	int getSizeX() const { return geometry().sizeX; }
	int getSizeY() const { return geometry().sizeY; }
	/** @} */

	/** @name Reading cells
	 * Every read is decayed to the data time of the latest observation
	 * inserted (latestTime()), whether or not that observation saw the cell.
	 * @{ */
	/** Masses of the cell holding world point (x, y); the vacuous mass
	 * outside the map. Never throws. */
	Mass getCellMasses(double x, double y) const;
	/** Masses of cell (cx, cy); the vacuous mass outside the map. Never
	 * throws. */
	Mass getCellMassesByIndex(int cx, int cy) const;
	/** Pignistic probability of occupancy of the cell holding (x, y), 0.5
	 * outside the map. Never throws. */
	double getCellBetP(double x, double y) const;
	/** Maximum-mass decision of the cell holding (x, y) (decide()); Unknown
	 * outside the map. Never throws. */
	Decision getCellDecision(double x, double y) const;

	/** Number of cells per decision. */
	struct TDecisionCounts
	{
		std::size_t free = 0, occupied = 0, unknown = 0, conflict = 0;
	};
	TDecisionCounts countDecisions() const;

	/** @name The motion layer
	 * Maps whose conflictHandling is not Keep remember, per cell, the latest
	 * time something appeared there or left (doc/dynamics.md). Maps that
	 * keep conflict have no motion layer and read Motion::None everywhere.
	 * @{ */
	/** The motion of the cell holding (x, y) as of the latest insertion:
	 * Appeared or Disappeared if that happened within the last motionWindow
	 * seconds of data time, else None; None outside the map. Never throws. */
	Motion getCellMotion(double x, double y) const;
	/** getCellMotion() of cell (cx, cy); None outside the map. Never
	 * throws. */
	Motion getCellMotionByIndex(int cx, int cy) const;
	/** Data time (seconds, as latestTime()) of the event getCellMotion()
	 * reports for (x, y); NaN when it reports None. Never throws. */
	double getCellMotionTime(double x, double y) const;
	/** Number of cells per motion. */
	struct TMotionCounts
	{
		std::size_t appeared = 0, disappeared = 0;
	};
	TMotionCounts countMotion() const;
	/** Centres of the cells whose motion is Appeared: what a planner must
	 * treat as moving obstacles. */
	std::vector<std::pair<double, double>> getAppearedCellCenters() const;
	/** Centres of the cells whose motion is Disappeared. */
	std::vector<std::pair<double, double>> getDisappearedCellCenters() const;
	/** @} */

	/** Data time of the latest observation inserted, seconds
	 * (mrpt::Clock::toDouble of its timestamp); 0 before the first. */
	double latestTime() const { return m_grid.latestTime(); }
	/** Number of observations inserted since the last clear(). */
	std::size_t insertionCount() const { return m_grid.insertionCount(); }
	/** The cells, for loops that read them all (decay not applied: use
	 * storage().read(); geometry().forEachIndex() walks the indices, which a
	 * grown grid spaces out between rows). */
	const EvidentialGridStorage& storage() const { return m_grid; }
	/** @} */

	/** @name Pictures and conversions
	 * Pictures have one pixel per cell, row 0 at the top (largest y). The
	 * colours of getAsImage() and getAsMotionImage() are renderingOptions'.
	 * @{ */
	/** The map as its 3-D view draws it (RenderStyle::Classes), 8-bit RGB: each
	 * cell in the colour of its class (classOfCell()), unknown cells in
	 * renderingOptions.unknownColor. */
	void getAsImage(mrpt::img::CImage& img) const;
	/** Evidential colours, 8-bit RGB: red = m(O) + m(empty),
	 * green = m(F) + m(empty), blue = m(Omega) + m(empty), times 255. Without
	 * conflict the channels sum to 255 (pure red, green, blue and their
	 * mixes); conflict brightens a cell towards white, which no other mass
	 * can. */
	void getAsEvidentialImage(mrpt::img::CImage& img) const;
	/** BetP in grey levels: white = free (BetP 0), black = occupied (BetP 1),
	 * as MRPT draws occupancy grids. */
	void getAsBetPImage(mrpt::img::CImage& img) const;
	/** Conflict in grey levels: black = none, white = total conflict (black
	 * everywhere in a map without conflict: see getAsMotionImage()). */
	void getAsConflictImage(mrpt::img::CImage& img) const;
	/** The motion layer over the static map: the static map as BetP in grey
	 * levels (white free, black occupied, mid-grey unknown), cells where
	 * something appeared in renderingOptions.appearedColor, cells it left in
	 * renderingOptions.disappearedColor. */
	void getAsMotionImage(mrpt::img::CImage& img) const;
	/** Fills an occupancy grid of the same geometry with occupancy = BetP. */
	void getAsOccupancyGrid(mrpt::maps::COccupancyGridMap2D& grid) const;
	/** Writes a ROS map_server pair, `<prefix>.pgm` and `<prefix>.yaml`
	 * (occupancy = BetP; unknown cells as 205). Written atomically.
	 * \throws std::runtime_error if a file cannot be written. */
	void saveAsROSMap(const std::string& prefix) const;
	/** Writes the five pictures above as `<prefix>map.png`,
	 * `<prefix>evidential.png`, `<prefix>betp.png`, `<prefix>conflict.png`
	 * and `<prefix>motion.png` (pictureNames()), each atomically; the prefix
	 * is a folder ending in '/' or a file name's stem. Each file is the
	 * picture (one pixel per cell, at its top left) above a strip with its
	 * legend and a scale bar (doc/map.md, "Pictures"); `withLegend` false
	 * writes the bare pictures.
	 * \throws std::runtime_error if a file cannot be written. */
	void savePictures(const std::string& prefix, bool withLegend = true) const;
	/** Picture `which` of pictureNames() as savePictures() writes it, above
	 * its legend and scale bar unless `withLegend` is false; with `width`
	 * and `height` > 0 (a video's frames), scaled to fit a picture of that
	 * size above the legend (the legend left out when it would take more
	 * than half of the height). \throws std::out_of_range if which >= 5. */
	void getAsPicture(
		std::size_t which, mrpt::img::CImage& img, bool withLegend = true, int width = 0,
		int height = 0) const;
	/** The names savePictures() appends to its prefix. */
	static const std::array<const char*, 5>& pictureNames();
	/** Writes a scene that MRPT's SceneViewer3D opens (an
	 * mrpt::opengl::COpenGLScene): the map as getVisualizationInto() draws it
	 * and, when `path` is not empty, the robot's path as a line strip through
	 * its positions (in red, above the map). Written atomically.
	 * \throws std::runtime_error if the file cannot be written;
	 *  std::invalid_argument as getVisualizationInto(). */
	void saveAsScene(
		const std::string& path3Dscene,
		const std::vector<mrpt::math::TPoint3D>& path = {}) const;
	/** The classes of cells that the 3-D view and getAsImage() draw. */
	enum class CellClass
	{
		Unknown,
		Free,
		Occupied,
		Conflict,
		Appeared,
		Disappeared
	};
	/** The class of the cell holding (x, y): its motion when the motion
	 * layer reports one (getCellMotion()), else its decision (decide());
	 * Unknown outside the map. Never throws. */
	CellClass classOfCell(double x, double y) const;
	/** The geometry in four lines, each after `indent`: "x: [xmin, xmax]
	 * m", "y: [ymin, ymax] m", "resolution: r m", "cells: NX x NY (budget
	 * B)", numbers in their shortest exact text. */
	std::string geometryText(const std::string& indent = "") const;
	/** Centres of the cells whose decision is Occupied. */
	std::vector<std::pair<double, double>> getOccupiedCellCenters() const;
	/** @} */

	/** @name Maps from many runs (doc/map.md, "Maps from many runs")
	 * Both maps must share a lattice: the same resolution, and origins a
	 * whole number of cells apart. @{ */
	/** Fuses `other` into this map, cell by cell: each cell of `other` that
	 * it saw, read decayed to its own latest time, is combined with this
	 * map's cell by `rule`, its conflict handled by `handling`. The map grows
	 * to hold other's extent, takes the later of the two latest times, sets
	 * its conflictHandling to `handling` (Keep: the cells keep the conflict
	 * between the runs), keeps the cells that held impacts in either, and
	 * clears its motion layer (events of two runs share no clock). Fusing
	 * into an empty map copies. \throws std::invalid_argument if the
	 *  lattices differ (the message gives both), or if the grid cannot grow
	 *  to other's extent within maxCells(); the map is then unchanged. */
	void fuseMap(const CEvidentialGridMap2D& other, FusionRule rule, ConflictHandling handling);
	/** What changed from an earlier run of the same place to this one. */
	struct TMapChanges
	{
		/** Cells of this map (index cx + sizeX cy) where something
		 * appeared (free then, occupied now) or disappeared. */
		std::vector<std::size_t> appeared, disappeared;
		/** Cells that both runs saw (m(Omega) below 1 in both). */
		std::size_t compared = 0;
	};
	/** The cells both maps saw whose conflict of one cause, m_earlier(F)
	 * m_this(O) or m_earlier(O) m_this(F), reaches `minConflict`, except
	 * those within `clearance` metres of a cell that leans occupied in both
	 * (walls seen from two runs' poses). \throws std::invalid_argument if
	 *  the lattices differ, minConflict is not in (0, 1] or clearance not in
	 *  [0, 10]. */
	TMapChanges changesSince(
		const CEvidentialGridMap2D& earlier, double minConflict = 0.5, double clearance = 0.1) const;
	/** This map as getAsMotionImage() draws it, with `changes` (of
	 * changesSince()) as the motion (appeared and disappeared in
	 * renderingOptions' colours), above the motion picture's legend when
	 * `withLegend`. */
	void getAsChangesImage(
		const TMapChanges& changes, mrpt::img::CImage& img, bool withLegend = false) const;
	/** @} */

	/** @name CMetricMap interface
	 * @{ */
	/** True until an observation has been inserted. */
	bool isEmpty() const override;
	/** The grid's extent, [getXMin(), getXMax()] x [getYMin(), getYMax()] at
	 * z = 0, as COccupancyGridMap2D gives its own (a CMetricMap virtual since
	 * MRPT 2.11.3). */
	mrpt::math::TBoundingBoxf boundingBox() const MRPT_EVIDENTIAL_OVERRIDE_SINCE_2_11_3;
	/** Writes savePictures(`<prefix>_`), `<prefix>_info.txt` (geometry, options and
	 * counts per decision) and `<prefix>.evgrid` (the serialized map), each
	 * atomically. \throws std::runtime_error if a file cannot be written. */
	void saveMetricMapRepresentationToFile(
		const std::string& filNamePrefix) const override;
	/** One line: geometry, insertions and counts per decision. */
	std::string asString() const override;
	/** The map at its place, as renderingOptions says: with
	 * RenderStyle::Classes, one set of unlit triangles (CSetOfTriangles) per
	 * class of cell that the map holds and the options show, named
	 * "evidentialGrid.unknown", "evidentialGrid.free",
	 * "evidentialGrid.occupied", "evidentialGrid.conflict",
	 * "evidentialGrid.disappeared" and "evidentialGrid.appeared", covering
	 * exactly the cells of its class in the option's colour; with
	 * RenderStyle::Masses, one textured plane "evidentialGrid.masses" with
	 * getAsEvidentialImage(), never-seen cells transparent unless
	 * showUnknown. Everything lies at z = renderingOptions.height. Nothing
	 * when genericMapParams.enableSaveAs3DObject is false.
	 * \throws std::invalid_argument if renderingOptions is invalid (set in
	 *  code: TRenderingOptions::validate()); `o` is then unchanged. */
	void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
	/** 0: the map takes no part in point matching. */
	float compute3DMatchingRatio(
		const mrpt::maps::CMetricMap* otherMap,
		const mrpt::poses::CPose3D& otherMapPose,
		const mrpt::maps::TMatchingRatioParams& params) const override;
	/** nullptr: the map holds no point cloud (getOccupiedCellCenters() gives
	 * the occupied cells), so that a CMultiMetricMap keeps using its own
	 * points map for ICP. */
	const mrpt::maps::CSimplePointsMap* getAsSimplePointsMap() const override
	{
		return nullptr;
	}
	/** @} */

	/** Insertion options, `[<prefix>_evidentialGrid_NN_insertOpts]` in .ini
	 * files. Angles are in degrees in files, radians here. */
	struct TInsertionOptions : public mrpt::config::CLoadableOptions
	{
		/** `sensorModel`: MultiEcho, ReinforcedMultiEcho or
		 * ImpreciseMultiEcho (default: walls seen with the error of a SLAM
		 * front end read occupied, doc/dynamics.md). */
		SensorModel sensorModel = SensorModel::ImpreciseMultiEcho;
		/** `muF`: detection rate, [0, 1], default 0.7. */
		double muF = 0.7;
		/** `muO`: true-positive rate, [0, 1], default 0.9. */
		double muO = 0.9;
		/** `imprecision`: half-width d of an impact, metres, >= 0, default
		 * 0.1 (ImpreciseMultiEcho only): the error of a SLAM front end's
		 * poses and of the scanner, a few centimetres each. */
		double imprecision = 0.1;
		/** `imprecisionProfile`: Box (default) or Gaussian. */
		ImprecisionProfile imprecisionProfile = ImprecisionProfile::Box;
		/** `sectorWidth`: angular width of a polar sector, radians (degrees in
		 * files), [0, 2 pi], default 0 = one sector per beam of a 2-D scan,
		 * 0.5 degree for a 3-D cloud (whose points are grouped by azimuth). */
		double sectorWidth = 0.0;
		/** `maxRange`: ranges are used up to this distance, metres, > 0,
		 * default 20. */
		double maxRange = 20.0;
		/** `invalidRangesAsFree`: a beam without return proves free space up
		 * to maxRange, default false (it proves nothing). */
		bool invalidRangesAsFree = false;
		/** `freeMargin`: metres before each impact where a beam proves
		 * nothing free, measured across the surface it hit (longer along a
		 * beam that grazes it; TSourceGridOptions::freeMargin), >= 0,
		 * default 0.1. */
		double freeMargin = 0.1;
		/** `fusionRule`: Conjunctive (default), Dempster, Yager, DuboisPrade
		 * or Cautious. */
		FusionRule fusionRule = FusionRule::Conjunctive;
		/** `decayRate`: per second of data time, >= 0, default 0 (no decay).
		 * After dt seconds a cell is discounted with rate
		 * 1 - exp(-decayRate dt). */
		double decayRate = 0.0;
		/** `horizontalTolerance`: largest pitch or roll of a scan's sensor
		 * pose for it to count as planar, radians (degrees in files),
		 * [0, pi/2], default 0.05 degrees (as COccupancyGridMap2D). */
		double horizontalTolerance = 0.05 * M_PI / 180.0;
		/** `conflictHandling`: what leaves a cell of the conflict of each
		 * fusion. Normalize (default): the cell keeps the rest renormalized
		 * (Dempster's rule for the conjunctive rule) and the motion layer
		 * keeps what caused it. ToUnknown: the conflict becomes ignorance,
		 * with the motion layer too. Keep: the cell accumulates it (the
		 * seed's conjunctive grid); such a map has no motion layer, its
		 * conflict is where things changed. doc/dynamics.md. */
		ConflictHandling conflictHandling = ConflictHandling::Normalize;
		/** `growthMargin`: metres added beyond the scan when the grid grows,
		 * >= 0, default 5. */
		double growthMargin = 5.0;
		/** `motionWindow`: seconds of data time during which a cell where
		 * something appeared or left reads so (getCellMotion), (0, 1e6],
		 * default 2. */
		double motionWindow = 2.0;
		/** `motionMinConflict`: least conflict of one cause, seen free
		 * before and occupied now or the other way round, for a fusion to be
		 * a motion event, (0, 1], default 0.65: with the default masses
		 * (muF 0.7, muO 0.9) a cell must have been seen free twice, or hit
		 * twice, before a change of it counts (doc/dynamics.md). */
		double motionMinConflict = 0.65;
		/** `motionClearance`: metres; a change closer than this to static
		 * structure (cells that lean occupied and are not themselves moving)
		 * is taken for the error of the robot's pose, not for motion,
		 * [0, 10], default 0.1. */
		double motionClearance = 0.10;
		/** 3-D clouds (CObservationPointCloud, CObservationVelodyneScan,
		 * CObservation3DRangeScan): `groundRemoval`, where the ground lies:
		 * Plane (default: fitted to each cloud, the robot's base plane when
		 * none is found), Height (the robot's base plane, z = 0 in its
		 * frame) or None (no ground: every point is an obstacle). */
		GroundRemoval groundRemoval = GroundRemoval::Plane;
		/** `minObstacleHeight`, `maxObstacleHeight`: a cloud's points from
		 * min to max metres above the ground are obstacles; lower ones are
		 * ground, higher ones (above the robot: branches, a barrier)
		 * nothing. 0 <= min < max <= 1000, defaults 0.2 and 2.0. */
		double minObstacleHeight = 0.2, maxObstacleHeight = 2.0;
		/** `groundReturns`: what a ground point proves: FreeSpace (default:
		 * free space up to it along its azimuth) or Nothing. */
		GroundReturns groundReturns = GroundReturns::FreeSpace;
		/** `insertionThreads`: threads that fuse an observation's cells,
		 * 1 to 64, default 1. Each fuses a band of rows; the motion layer's
		 * decisions are settled afterwards in row order, so the map is the
		 * same, bit for bit, whatever the count. How the map is built, not
		 * what it holds: not stored in map files (a loaded map inserts on
		 * one thread). */
		unsigned insertionThreads = 1;
		static constexpr unsigned kMaxInsertionThreads = 64;

		/** Reads the keys above from `section`; absent keys keep their value.
		 * \throws std::invalid_argument naming the key and value of the first
		 *  invalid one (out of range, or an unknown enum name). */
		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		/** Writes every key (angles in degrees), with its unit as a comment;
		 * loadFromConfigFile() reads them back exactly. */
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;
		/** Prints the keys as saveToConfigFile() writes them. */
		void dumpToTextStream(std::ostream& out) const override;
		/** The first invalid field, with its rule (angles in radians). The
		 * sensor model's and polar grid's fields follow their own rules
		 * (TSourceGridOptions::firstInvalid()), checked for cells of 1 m. */
		std::optional<TInvalidOption> firstInvalid() const;
		/** \throws std::invalid_argument describing firstInvalid(). */
		void validate() const;
		/** The sector model and polar grid options these options give for a
		 * grid of the given resolution. */
		TSourceGridOptions sourceGridOptions(double resolution) const;

	   private:
		friend class CEvidentialGridMap2D;
		/** The rules of the fields that only the map uses; insertion checks
		 * them, then the polar grid checks its own at the grid's resolution,
		 * so that a scan validates each rule once. */
		std::optional<TInvalidOption> firstInvalidOfTheMap() const;
	};
	TInsertionOptions insertionOptions;

	/** Likelihood options, `[<prefix>_evidentialGrid_NN_likelihoodOpts]`: a
	 * likelihood field (Thrun) computed from the cells' occupied evidence.
	 * computeObservationLikelihood() of a CObservation2DRangeScan is the sum,
	 * over its scored rays, of log(zRandom / maxRange + zHit exp(-d^2 /
	 * (2 sigma^2))), d the distance from the ray's end to the nearest
	 * obstacle cell, cut at maxCorrsDistance (0 for a scan without a scored
	 * ray). Other observations give 0, and canComputeObservationLikelihood()
	 * is false for them. */
	struct TLikelihoodOptions : public mrpt::config::CLoadableOptions
	{
		/** `occupiedMass`: a cell is an obstacle of the field when its
		 * occupied mass with the conflict set aside, m(O) / (1 - m(empty)),
		 * is >= this (m(O) itself for a cell without conflict; with
		 * ConflictHandling::Keep wall surfaces are mostly conflict), (0, 1],
		 * default 0.3. Only cells that have held an impact are obstacles:
		 * the imprecise model draws walls a few cells thick, but the scans
		 * being scored end where beams ended. */
		double occupiedMass = 0.3;
		/** `maxCorrsDistance`: distances to the nearest obstacle are cut at
		 * this, metres, > 0, default 0.3. */
		double maxCorrsDistance = 0.3;
		/** `sigma`: standard deviation of a hit, metres, > 0, default 0.35. */
		double sigma = 0.35;
		/** `zHit`, `zRandom`: weights of a hit and of a random reading,
		 * >= 0, not both 0; defaults 0.95 and 0.05. */
		double zHit = 0.95, zRandom = 0.05;
		/** `maxRange`: rays longer than this are not scored, metres, > 0,
		 * default 81. */
		double maxRange = 81.0;
		/** `decimation`: score one ray in this many, >= 1, default 5. */
		unsigned int decimation = 5;
		/** `unknownAsNeutral`: a ray ending in a never-seen cell with no
		 * obstacle nearby scores as a ray ending half of maxCorrsDistance from
		 * an obstacle, neither a hit nor a miss; default true. false scores it
		 * as a miss, as if the cell were free. */
		bool unknownAsNeutral = true;

		/** Reads the keys above from `section`; absent keys keep their value.
		 * A number must be the whole first word of the value ("0.3x" is
		 * refused; a trailing comment is fine), a boolean true, false, yes,
		 * no, 1 or 0. Nothing changes unless every value is valid.
		 * \throws std::invalid_argument naming the key and value of the first
		 *  invalid one. */
		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		/** Writes every key with its unit as a comment; loadFromConfigFile()
		 * reads them back exactly. */
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;
		/** Prints the keys as saveToConfigFile() writes them. */
		void dumpToTextStream(std::ostream& out) const override;
		/** The first invalid field, with its rule. */
		std::optional<TInvalidOption> firstInvalid() const;
		/** \throws std::invalid_argument "likelihoodOpts: " followed by the
		 *  description of firstInvalid(). */
		void validate() const;
	};
	TLikelihoodOptions likelihoodOptions;

	/** How getVisualizationInto() and the pictures draw the map,
	 * `[<prefix>_evidentialGrid_NN_renderOpts]` in .ini files. A colour is
	 * written `#RRGGBB` or `RRGGBB` (hexadecimal). The defaults draw the
	 * static map as MRPT users read occupancy grids (free light, occupied
	 * dark, unknown not drawn in 3-D) and what only an evidential map knows
	 * in tints apart from the blue of MRPT's points maps and the colours of
	 * its paths. */
	struct TRenderingOptions : public mrpt::config::CLoadableOptions
	{
		/** `style`: Classes (default) or Masses (RenderStyle). */
		RenderStyle style = RenderStyle::Classes;
		/** `freeColor`, default #EBEBEB. */
		mrpt::img::TColor freeColor{0xEB, 0xEB, 0xEB};
		/** `occupiedColor`, default #1E1E1E. */
		mrpt::img::TColor occupiedColor{0x1E, 0x1E, 0x1E};
		/** `unknownColor`, default #8C8C8C: unknown cells in the pictures,
		 * and in the 3-D view when showUnknown. */
		mrpt::img::TColor unknownColor{0x8C, 0x8C, 0x8C};
		/** `conflictColor`, default #B43CC8 (violet): cells whose decision is
		 * Conflict (maps whose conflictHandling is Keep). */
		mrpt::img::TColor conflictColor{0xB4, 0x3C, 0xC8};
		/** `appearedColor`, default #FF8C00 (orange). */
		mrpt::img::TColor appearedColor{0xFF, 0x8C, 0x00};
		/** `disappearedColor`, default #00AAAA (teal). */
		mrpt::img::TColor disappearedColor{0x00, 0xAA, 0xAA};
		/** `showFree`, `showOccupied`, `showConflict`, `showMotion`: whether
		 * the 3-D view has the class's object, default true; without the
		 * motion objects, moving cells show their decision. `showUnknown`,
		 * default false: unknown cells are transparent, as in MRPT's grid.
		 * The pictures draw every class. */
		bool showFree = true, showOccupied = true, showConflict = true,
			 showMotion = true, showUnknown = false;
		/** `height`: z of the 3-D view, metres, within [-1000, 1000], default
		 * -0.001: just under z = 0, where 2-D scans' points and paths lie, so
		 * that they stay visible over the map. */
		double height = -0.001;

		/** Reads the keys above from `section`; absent keys keep their value;
		 * nothing changes unless every value is valid.
		 * \throws std::invalid_argument naming the key and value of the first
		 *  invalid one. */
		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		/** Writes every key; loadFromConfigFile() reads them back exactly. */
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;
		/** Prints the keys as saveToConfigFile() writes them. */
		void dumpToTextStream(std::ostream& out) const override;
		/** The first invalid field, with its rule. */
		std::optional<TInvalidOption> firstInvalid() const;
		/** \throws std::invalid_argument "renderOpts: " followed by the
		 *  description of firstInvalid(). */
		void validate() const;
		/** The colour the options give a class of cell. */
		mrpt::img::TColor colorOf(CellClass c) const;
	};
	TRenderingOptions renderingOptions;

	MAP_DEFINITION_START(CEvidentialGridMap2D)
	/** `[<prefix>_evidentialGrid_NN_creationOpts]`: min_x, max_x, min_y,
	 * max_y (metres, min < max, within 1e9 m of the origin), resolution
	 * (metres, 1e-6 to 1e6) and maxCells (cell budget for growth, > 0, at
	 * least the cells of the initial grid). */
	double min_x = -10.0, max_x = 10.0, min_y = -10.0, max_y = 10.0,
		   resolution = 0.10;
	std::size_t maxCells = CEvidentialGridMap2D::kDefaultMaxCells;
	mrpt_evidential::CEvidentialGridMap2D::TInsertionOptions insertionOpts;
	mrpt_evidential::CEvidentialGridMap2D::TLikelihoodOptions likelihoodOpts;
	mrpt_evidential::CEvidentialGridMap2D::TRenderingOptions renderingOpts;
	MAP_DEFINITION_END(CEvidentialGridMap2D)

	/** The map a definition describes, as CreateFromMapDefinition() makes it
	 * for MRPT's map registry, but owned by the caller alone (MRPT's factory
	 * returns a raw pointer before MRPT 2.11.3, a shared one since).
	 * \throws std::invalid_argument as setMaxCells() and setSize(). */
	static std::unique_ptr<CEvidentialGridMap2D> fromDefinition(
		const TMapDefinition& definition);

   private:
	void internal_clear() override;
	bool internal_insertObservation(
		const mrpt::obs::CObservation& obs,
		const std::optional<const mrpt::poses::CPose3D>& robotPose =
			std::nullopt) override;
	double internal_computeObservationLikelihood(
		const mrpt::obs::CObservation& obs,
		const mrpt::poses::CPose3D& takenFrom) const override;
	bool internal_canComputeObservationLikelihood(
		const mrpt::obs::CObservation& obs) const override;

	/** Fuses one scan: polar grid, bilinear transform, decay, fusion. */
	bool insertScan(
		const mrpt::obs::CObservation2DRangeScan& scan,
		const mrpt::poses::CPose3D& robotPose);
	/** Fuses a 3-D observation's cloud; false for a type that has none. */
	bool insertCloud(const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& robotPose);
	/** The points of a 3-D observation in the robot's frame, and its sensor
	 * pose on the robot; nothing for a type that holds no cloud. */
	std::optional<mrpt::poses::CPose3D> cloudInRobotFrame(
		const mrpt::obs::CObservation& obs, std::vector<mrpt::math::TPoint3Df>& points) const;
	/** Fuses the workspace's polar grid, built for an observation of time
	 * `stamp` taken at `sensor`. */
	void fusePolarGrid(const PlanarSensorPose& sensor, mrpt::Clock::time_point stamp);
	/** \throws std::invalid_argument "... the WHAT's pose is not finite: ..."
	 *  if a coordinate is not finite. */
	static void requireFinitePose(const mrpt::poses::CPose3D& sensorPose, const char* what);
	/** Fuses the scan's cells into a map that keeps conflict. */
	void fuseKeepingConflict(CScanImpacts& impacts);
	/** Fuses the scan's cells into a map without conflict, and settles its
	 * motion events. */
	void fuseWithMotion(CScanImpacts& impacts);
	/** What the motion layer says of cell idx. */
	Motion motionOf(std::size_t idx) const;
	/** The class of cell idx (classOfCell()); its decision's class alone
	 * when `withMotion` is false. */
	CellClass classOf(std::size_t idx, bool withMotion = true) const;
	/** Paints the static map in grey levels with `motion(idx)` over it. */
	void paintMotion(mrpt::img::CImage& img, const std::function<Motion(std::size_t)>& motion) const;
	/** The index in this map of `other`'s cell idx, or nothing when it
	 * lies outside; `offsetX`, `offsetY`: other's origin in this map's
	 * cells. */
	std::optional<std::size_t> cellOfOther(
		const GridGeometry& other, std::size_t idx, int offsetX, int offsetY) const;
	/** Drops the likelihood field; the next likelihood rebuilds it. */
	void invalidateLikelihoodCache();

	EvidentialGridStorage m_grid;
	std::size_t m_maxCells = kDefaultMaxCells;
	/** The cell-budget and tilted-scan messages are printed once per map. */
	bool m_budgetWarningShown = false, m_tiltNoticeShown = false;

	/** What the map keeps beside its cells, not part of its value: the
	 * insertion's scratch space (a scan's polar grid and its transform) and
	 * the likelihood field (per cell, the distance to the nearest obstacle,
	 * built on first use under a lock and dropped on every change). Defined
	 * in src/map/MapWorkspace.h. */
	struct TWorkspace;
	struct LikelihoodField;
	/** Owns a TWorkspace. A copy gets scratch space of its own and shares the
	 * source's likelihood field, read under the source's lock. */
	class CWorkspace
	{
	   public:
		CWorkspace();
		CWorkspace(const CWorkspace& other);
		CWorkspace& operator=(const CWorkspace& other);
		~CWorkspace();
		TWorkspace* operator->() const { return m_work.get(); }

	   private:
		std::unique_ptr<TWorkspace> m_work;
	};
	CWorkspace m_workspace;
	/** Builds the field for the current cells and options. */
	std::shared_ptr<const LikelihoodField> likelihoodField() const;
};

}  // namespace mrpt_evidential
