/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The options of the evidential grid map: how it inserts observations, how
 * it scores them, how it is drawn. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/img/TColor.h>
#include <mrpt_evidential/CellClass.h>
#include <mrpt_evidential/EnumNames.h>
#include <mrpt_evidential/RenderStyle.h>
#include <mrpt_evidential/TInvalidOption.h>
#include <mrpt_evidential/algebra/combination.h>
#include <mrpt_evidential/scan/CPolarSourceGrid.h>

#include <cmath>
#include <optional>
#include <ostream>
#include <string>

namespace mrpt_evidential
{
class CEvidentialGridMap2D;

/** Insertion options of CEvidentialGridMap2D (its TInsertionOptions),
 * `[<prefix>_evidentialGrid_NN_insertOpts]` in .ini files. Angles are in
 * degrees in files, radians here. */
struct TEvidentialInsertionOptions : public mrpt::config::CLoadableOptions
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
	 * something appeared or left reads so (CEvidentialGridMap2D::getCellMotion()), (0, 1e6],
	 * default 2. */
	double motionWindow = 2.0;
	/** `motionMinConflict`: least conflict of one cause, seen free
	 * before and occupied now or the other way round, for a fusion to be
	 * a motion event, (0, 1], default 0.65: with the default masses
	 * (muF 0.7, muO 0.9) a cell must have been seen free twice, or hit
	 * twice, before a change of it counts (doc/dynamics.md). With weaker
	 * masses, where no sight could reach it (muF or muO below 0.7), each
	 * cause asks instead 0.93 of the sight's mass: a cell as sure before
	 * the change as the defaults ask. */
	double motionMinConflict = 0.65;
	/** `motionClearance`: metres; a change closer than this to static
	 * structure (cells that lean occupied and are not themselves moving)
	 * is taken for the error of the robot's pose, not for motion,
	 * [0, 10], default 0.1. For an arrival it is measured from the
	 * imprecise model's spread in front of a face (the clearance less
	 * min(imprecision, freeMargin), at least one cell), and from faces no
	 * beam ever crossed. Far from the sensor it grows to what a degree of
	 * error in the robot's heading moves a face by (doc/dynamics.md). */
	double motionClearance = 0.10;
	/** 3-D clouds (CObservationPointCloud, CObservationVelodyneScan,
	 * CObservation3DRangeScan): `groundRemoval`, where the ground lies:
	 * Terrain (default: a plane fitted to each cloud, the robot's base
	 * plane when none is found, bent to follow the ground where it rises
	 * or falls away from it: a hill ahead, a crest), Plane (that plane
	 * alone), Height (the robot's base plane, z = 0 in its frame) or None
	 * (no ground: every point is an obstacle). */
	GroundRemoval groundRemoval = GroundRemoval::Terrain;
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

/** Likelihood options of CEvidentialGridMap2D (its TLikelihoodOptions),
 * `[<prefix>_evidentialGrid_NN_likelihoodOpts]`: a likelihood field (Thrun)
 * computed from the cells' occupied evidence. The map's
 * computeObservationLikelihood() of a CObservation2DRangeScan is the sum,
 * over its scored rays, of log(zRandom / maxRange + zHit exp(-d^2 /
 * (2 sigma^2))), d the distance from the ray's end to the nearest
 * obstacle cell, cut at maxCorrsDistance (0 for a scan without a scored
 * ray). Other observations give 0, and canComputeObservationLikelihood()
 * is false for them. */
struct TEvidentialLikelihoodOptions : public mrpt::config::CLoadableOptions
{
	/** `occupiedMass`: a cell is an obstacle of the field when its
	 * occupied mass with the conflict set aside, m(O) / (1 - m(empty)),
	 * is >= this (m(O) itself for a cell without conflict; with
	 * ConflictHandling::Keep wall surfaces are mostly conflict), (0, 1],
	 * default 0.3; above EvidentialGridStorage::kMaxCertainty (0.9999, the
	 * most a cell holds) it acts as that. Only cells that have held an
	 * impact are obstacles: the imprecise model draws walls a few cells
	 * thick, but the scans being scored end where beams ended. */
	double occupiedMass = 0.3;
	/** `maxCorrsDistance`: distances to the nearest obstacle are cut at
	 * this, metres, (0, 1000], default 0.3 (the field's 253 steps of
	 * distance would be metres wide beyond that). */
	static constexpr double kMaxCorrsDistance = 1000.0;
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

/** How CEvidentialGridMap2D::getVisualizationInto() and the pictures draw
 * the map (its TRenderingOptions), `[<prefix>_evidentialGrid_NN_renderOpts]`
 * in .ini files. A colour is
 * written `#RRGGBB` or `RRGGBB` (hexadecimal). The defaults draw the
 * static map as MRPT users read occupancy grids (free light, occupied
 * dark, unknown not drawn in 3-D) and what only an evidential map knows
 * in tints apart from the blue of MRPT's points maps and the colours of
 * its paths. */
struct TEvidentialRenderingOptions : public mrpt::config::CLoadableOptions
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

}  // namespace mrpt_evidential
