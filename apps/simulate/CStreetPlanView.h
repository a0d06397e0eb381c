/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The scene "street" seen from above, as the 2-D scenes are: what
 * CMotionTruthWriter needs to write its PREFIX.motion.gz. */
#pragma once

#include "CScene.h"
#include "CStreetScene.h"

namespace mrpt_evidential::simulate
{
/** The street's footprints: its static obstacles (houses, parked cars,
 * poles, the tree's trunk; not the kerbs nor what hangs overhead, so that a
 * person stepping over a kerb or a car passing under the gantry is listed
 * as moving there) and its moving things. One lap is the whole drive. */
class CStreetPlanView : public CScene
{
   public:
	CStreetPlanView(const CStreetScene& street, double duration);

	TRect extent() const override;
	std::vector<TShape> staticShapes() const override;
	std::vector<TShape> movingAt(double t) const override;
	mrpt::poses::CPose2D robotPoseAt(double t) const override;
	double lapPeriod() const override { return m_duration; }

   private:
	const CStreetScene& m_street;
	double m_duration;
};

}  // namespace mrpt_evidential::simulate
