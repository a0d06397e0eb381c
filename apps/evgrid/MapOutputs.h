/* evgrid: what more than one subcommand writes about a map. */
#pragma once

#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace evgrid
{
/** Creates `dir` and its parents if missing; an empty path is the current
 * folder. \throws std::runtime_error naming `dir` if it cannot be created. */
void createFolder(const std::string& dir);

/** Before any work, for a file written at the end: the folder of `path`
 * exists (created if needed) and can be written, `path` is not a folder nor
 * a device or a pipe, and it is none of `inputs` (under any name: a link, a
 * path with ..). \throws std::runtime_error naming `path` otherwise. */
void checkOutputFile(const std::string& path, const std::vector<std::string>& inputs = {});

/** Writes the map's pictures (CEvidentialGridMap2D::pictureNames()) into
 * `dir`, created if missing, each atomically, above their legends unless
 * `withLegend` is false.
 * \return the paths written. \throws std::runtime_error naming the file or
 *  folder that cannot be written. */
std::vector<std::string> savePicturesIn(
	const mrpt_evidential::CEvidentialGridMap2D& map, const std::string& dir,
	bool withLegend = true);

/** "cells by decision:" and one line per decision, each count with its share
 * of `cellCount`, as `build`'s summary and `inspect` print them. */
void printDecisionCounts(
	std::ostream& os,
	const mrpt_evidential::CEvidentialGridMap2D::TDecisionCounts& counts,
	std::size_t cellCount);
/** One line: the cells the motion layer flags (or that the map has none). */
void printMotionCounts(
	std::ostream& os, const mrpt_evidential::CEvidentialGridMap2D& map);

/** "options:" and the map's insertion, likelihood and rendering options as
 * .ini sections. */
void printMapOptions(
	std::ostream& os, const mrpt_evidential::CEvidentialGridMap2D& map);

}  // namespace evgrid
