/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The scenes evgrid-simulate's --scene names. */
#include "SceneCatalog.h"

#include <cstdio>

#include "CPeopleScene.h"
#include "CRoomScene.h"

namespace mrpt_evidential::simulate
{
namespace
{
template <typename Scene>
std::unique_ptr<CScene> make()
{
	return std::make_unique<Scene>();
}

std::string roomDoorBoxSummary()
{
	using S = CRoomDoorBoxScene;
	char text[256];
	std::snprintf(
		text, sizeof(text),
		"the door opens at %g s; a %g m box is pushed from\n"
		"(%g, %g) to (%g, %g) between %g and %g s",
		S::kDoorOpensAt, S::kBoxSize, S::kBoxStartX, S::kBoxStartY,
		S::kBoxEndX, S::kBoxEndY, S::kBoxMoveStart, S::kBoxMoveEnd);
	return text;
}
}  // namespace

const std::vector<TSceneEntry>& sceneCatalog()
{
	static const std::vector<TSceneEntry> catalog = {
		{"room_door_box", roomDoorBoxSummary(), make<CRoomDoorBoxScene>},
		{"people",
		 "four people walk (two cross, one stops 5 s, one leaves\n"
		 "through the door at 27.5 s), the door opens at 15 s, a box is\n"
		 "pushed at 45 to 50 s, a parked cart rolls out at 52 to 62 s",
		 make<CPeopleScene>},
		{"static", "nothing moves; the door stands open",
		 make<CStaticRoomScene>},
		{"room_before",
		 "nothing moves; the door is shut and the box stands where\n"
		 "room_door_box's starts (a run before its changes)",
		 [] { return std::unique_ptr<CScene>(std::make_unique<CChangedRoomScene>(false)); }},
		{"room_after",
		 "nothing moves; the door is open and the box stands where\n"
		 "room_door_box's ends (a run after its changes)",
		 [] { return std::unique_ptr<CScene>(std::make_unique<CChangedRoomScene>(true)); }},
	};
	return catalog;
}

const TSceneEntry* findScene(const std::string& name)
{
	for (const TSceneEntry& entry : sceneCatalog())
		if (name == entry.name) return &entry;
	return nullptr;
}

}  // namespace mrpt_evidential::simulate
