/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The names of the library's enums in .ini files, for MRPT's enum tables
 * (mrpt::typemeta::TEnumType). The algebra and the sensor models never
 * include MRPT, so their enums get their names here. */
#pragma once

#include <mrpt/typemeta/TEnumType.h>
#include <mrpt_evidential/algebra/combination.h>
#include <mrpt_evidential/RenderStyle.h>
#include <mrpt_evidential/cloud/GroundRemoval.h>
#include <mrpt_evidential/scan/SensorModel.h>

MRPT_ENUM_TYPE_BEGIN(mrpt_evidential::SensorModel)
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::SensorModel, MultiEcho);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::SensorModel, ReinforcedMultiEcho);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::SensorModel, ImpreciseMultiEcho);
MRPT_ENUM_TYPE_END()

MRPT_ENUM_TYPE_BEGIN(mrpt_evidential::ImprecisionProfile)
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::ImprecisionProfile, Box);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::ImprecisionProfile, Gaussian);
MRPT_ENUM_TYPE_END()

MRPT_ENUM_TYPE_BEGIN(mrpt_evidential::FusionRule)
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::FusionRule, Conjunctive);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::FusionRule, Dempster);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::FusionRule, Yager);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::FusionRule, DuboisPrade);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::FusionRule, Cautious);
MRPT_ENUM_TYPE_END()

MRPT_ENUM_TYPE_BEGIN(mrpt_evidential::ConflictHandling)
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::ConflictHandling, Keep);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::ConflictHandling, ToUnknown);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::ConflictHandling, Normalize);
MRPT_ENUM_TYPE_END()

MRPT_ENUM_TYPE_BEGIN(mrpt_evidential::GroundRemoval)
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::GroundRemoval, None);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::GroundRemoval, Plane);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::GroundRemoval, Height);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::GroundRemoval, Terrain);
MRPT_ENUM_TYPE_END()

MRPT_ENUM_TYPE_BEGIN(mrpt_evidential::GroundReturns)
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::GroundReturns, FreeSpace);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::GroundReturns, Nothing);
MRPT_ENUM_TYPE_END()

MRPT_ENUM_TYPE_BEGIN(mrpt_evidential::RenderStyle)
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::RenderStyle, Classes);
MRPT_FILL_ENUM_MEMBER(mrpt_evidential::RenderStyle, Masses);
MRPT_ENUM_TYPE_END()
