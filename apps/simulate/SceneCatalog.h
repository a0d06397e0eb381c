/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The scenes evgrid-simulate's --scene names. */
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "CScene.h"

namespace mrpt_evidential::simulate
{
struct TSceneEntry
{
	const char* name;
	/** What moves in it and when, for --help. */
	std::string summary;
	std::unique_ptr<CScene> (*make)();
};

/** Every scene, the default first. */
const std::vector<TSceneEntry>& sceneCatalog();

/** The scene of that name, or nullptr. */
const TSceneEntry* findScene(const std::string& name);

}  // namespace mrpt_evidential::simulate
