/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The scene "street" seen from above. */
#include "CStreetPlanView.h"

namespace mrpt_evidential::simulate
{
CStreetPlanView::CStreetPlanView(const CStreetScene& street, double duration)
	: m_street(street), m_duration(duration)
{
}

TRect CStreetPlanView::extent() const { return m_street.scene().extent; }

std::vector<TShape> CStreetPlanView::staticShapes() const
{
	std::vector<TShape> shapes;
	for (const TBody& body : m_street.scene().staticBodies)
		if (body.kind == EBodyKind::Obstacle) shapes.push_back(body.shape);
	return shapes;
}

std::vector<TShape> CStreetPlanView::movingAt(double t) const
{
	const TScene3D& scene = m_street.scene();
	std::vector<TShape> shapes;
	for (const TMovingBody& m : scene.moving)
		shapes.push_back(m.at(t, scene.ground).shape);
	return shapes;
}

mrpt::poses::CPose2D CStreetPlanView::robotPoseAt(double t) const
{
	return CStreetScene::vehiclePoseAt(t);
}

}  // namespace mrpt_evidential::simulate
