/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The evidential grid as an MRPT metric map. */
#pragma once

#include <mrpt/core/Clock.h>
#include <mrpt/math/TBoundingBox.h>
#include <mrpt/math/TPoint3D.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt_evidential/CellClass.h>
#include <mrpt_evidential/EnumNames.h>
#include <mrpt_evidential/EvidentialGridOptions.h>
#include <mrpt_evidential/Motion.h>
#include <mrpt_evidential/MrptCompat.h>
#include <mrpt_evidential/algebra/combination.h>
#include <mrpt_evidential/grid/EvidentialGridStorage.h>

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
	 * it. \throws std::invalid_argument if 0, above 1e9
	 *  (GridGeometry::kMaxCellBudget: a saved map holds no more) or below the
	 *  current number of cells. */
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
	/** Observations this map object fused only in part: their reach lay
	 * beyond what `maxCells` (or 1e9 m of the origin) lets the grid grow to,
	 * so they were fused where they overlap the grid (a warning says so
	 * once). Counted since the map was made, read, cleared or resized
	 * (setSize()); not stored in map files. */
	std::size_t partlyInsertedCount() const { return m_partlyInserted; }
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
	/** Fills an occupancy grid of the same geometry with occupancy = BetP.
	 * COccupancyGridMap2D keeps its bounds in single precision: from about
	 * 1e6 m from the origin its origin may be a cell off, and MRPT throws
	 * for bounds its floats cannot tell apart (1e9 m). */
	void getAsOccupancyGrid(mrpt::maps::COccupancyGridMap2D& grid) const;
	/** Writes a ROS map_server pair, `<prefix>.pgm` and `<prefix>.yaml`
	 * (occupancy = BetP; unknown cells as 205). Written atomically.
	 * \throws std::runtime_error if a file cannot be written. */
	void saveAsROSMap(const std::string& prefix) const;
	/** Writes the five pictures above as `<prefix>map.png`,
	 * `<prefix>evidential.png`, `<prefix>betp.png`, `<prefix>conflict.png`
	 * and `<prefix>motion.png` (pictureNames()), all or none (written
	 * under temporary names, then renamed together); the prefix
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
	 * than half of the height). \throws std::out_of_range if which >= 5;
	 *  std::invalid_argument if width or height is outside [0, 8192]. */
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
	/** The classes of cells that the 3-D view and getAsImage() draw
	 * (CellClass.h). */
	using CellClass = mrpt_evidential::CellClass;
	/** The class of the cell holding (x, y): its motion when the motion
	 * layer reports one (getCellMotion()), else its decision (decide());
	 * Unknown outside the map. Never throws. */
	CellClass classOfCell(double x, double y) const;
	/** The geometry in four lines, each after `indent`: "x: [xmin, xmax]
	 * m", "y: [ymin, ymax] m", "resolution: r m", "cells: NX x NY (budget
	 * B)", lengths to the nanometre in their shortest text. */
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
	 * into an empty map copies. \throws std::invalid_argument if `rule` or
	 *  `handling` is no member of its enum, if the lattices differ (the
	 *  message gives both), or if the grid cannot grow to other's extent
	 *  within maxCells(); the map is then unchanged. */
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
	/** Writes savePictures(`<prefix>_`), `<prefix>.3Dscene` (saveAsScene()),
	 * `<prefix>_info.txt` (geometry, options and counts per decision) and
	 * `<prefix>.evgrid` (the serialized map), all or none: each is written
	 * under a temporary name first, and they replace the files of an
	 * earlier call together, once all are written.
	 * \throws std::invalid_argument, before writing anything, if the prefix
	 *  is empty or ends in '/' (it names a folder: the files would be hidden
	 *  ones, `out/.evgrid`) or an option set in code is invalid (the map
	 *  could not be read back); std::runtime_error if a file cannot be
	 *  written. */
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
	/** 0: the map takes no part in point matching. Point matching itself
	 * (determineMatching2D(), determineMatching3D(),
	 * squareDistanceToClosestCorrespondence()) is not implemented: MRPT's
	 * CMetricMap throws std::logic_error ("Virtual method not
	 * implemented in derived class"), as it does for COccupancyGridMap2D; ICP matches a
	 * CMultiMetricMap's points map instead. */
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

	/** @name Options (EvidentialGridOptions.h)
	 * Read from the map's .ini sections; every insertion, likelihood and
	 * picture uses the values they hold at the time.
	 * @{ */
	using TInsertionOptions = TEvidentialInsertionOptions;
	using TLikelihoodOptions = TEvidentialLikelihoodOptions;
	using TRenderingOptions = TEvidentialRenderingOptions;
	/** `[<prefix>_evidentialGrid_NN_insertOpts]`. */
	TInsertionOptions insertionOptions;
	/** `[<prefix>_evidentialGrid_NN_likelihoodOpts]`. */
	TLikelihoodOptions likelihoodOptions;
	/** `[<prefix>_evidentialGrid_NN_renderOpts]`. */
	TRenderingOptions renderingOptions;
	/** @} */

	MAP_DEFINITION_START(CEvidentialGridMap2D)
	/** `[<prefix>_evidentialGrid_NN_creationOpts]`: min_x, max_x, min_y,
	 * max_y (metres, min < max, within 1e9 m of the origin), resolution
	 * (metres, 1e-6 to 1e6) and maxCells (cell budget for growth, 1 to 1e9,
	 * at least the cells of the initial grid). */
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
	/** The points of a 3-D observation in the robot's frame, written over
	 * `points`, and its sensor pose on the robot; nothing (and `points` left
	 * as it was) for a type that holds no cloud. */
	std::optional<mrpt::poses::CPose3D> cloudInRobotFrame(
		const mrpt::obs::CObservation& obs, std::vector<mrpt::math::TPoint3Df>& points) const;
	/** Fuses the workspace's polar grid, built for an observation of time
	 * `stamp` taken at `sensor`. */
	void fusePolarGrid(const PlanarSensorPose& sensor, mrpt::Clock::time_point stamp);
	/** Writes saveAsScene()'s scene to `file` as it is (no temporary name);
	 * false if MRPT fails to write it. */
	bool writeScene(const std::string& file, const std::vector<mrpt::math::TPoint3D>& path) const;
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
	/** The tilted-scan and the upside-down-cloud messages are printed once
	 * per map each, the cell-budget one at the first partly inserted
	 * observation. */
	bool m_tiltNoticeShown = false, m_upsideDownNoticeShown = false;
	std::size_t m_partlyInserted = 0;  //!< partlyInsertedCount()

	/** What the map keeps beside its cells: the insertion's scratch space
	 * (a scan's polar grid and its transform), the likelihood field (per
	 * cell, the distance to the nearest obstacle, built on first use under
	 * a lock and dropped on every change), and the motion layer's memory
	 * between scans (part of the map's value: copied and saved). Defined in
	 * src/map/MapWorkspace.h. */
	struct TWorkspace;
	struct LikelihoodField;
	/** Owns a TWorkspace. A copy gets scratch space of its own, the
	 * source's motion memory, and shares the source's likelihood field, read
	 * under the source's lock. */
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
