/* Calls every public function of the foundation through the installed
 * package; exits non-zero on a wrong answer. */
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt_evidential/scan/CPolarSourceGrid.h>
#include <mrpt_evidential/algebra/Mass.h>
#include <mrpt_evidential/scan/SensorModel.h>
#include <mrpt_evidential/algebra/combination.h>

#include <cmath>
#include <cstdio>

using namespace mrpt_evidential;

int main()
{
	int failures = 0;
	const auto check = [&](bool ok, const char* what) {
		if (!ok) std::printf("FAILED: %s\n", what), ++failures;
	};
	const Mass f = Mass::simpleFree(0.6), o = Mass::simpleOccupied(0.5);
	check(conjunctive(f, o).isValid(), "conjunctive");
	check(disjunctive(f, Mass::degenerate()) == f, "disjunctive");
	check(dempster(Mass{0, 1, 0, 0}, Mass{0, 0, 1, 0}) == Mass::vacuous(), "dempster");
	check(yager(f, o).conflict == 0.0, "yager");
	check(duboisPrade(f, o).isValid(), "duboisPrade");
	check(std::abs(cautious(f, f).free - 0.6) < 1e-12, "cautious");
	check(discount(f, 1.0) == Mass::vacuous(), "discount");
	check(contextualDiscount(f, 0.5, 0.0).free == 0.3, "contextualDiscount");
	check(betP(Mass::vacuous()) == 0.5, "betP");
	check(belief(o) == 0.5 && plausibility(o) == 1.0, "belief/plausibility");

	SensorModelParams params;
	params.model = SensorModel::ReinforcedMultiEcho;
	params.muF = 0.7;
	params.muO = 0.9;
	const auto row = sectorMasses(params, {3, 1, 1}, 1.0, 5);
	check(std::abs(row[1].occupied - 0.99) < 1e-12, "sectorMasses");
	params.model = SensorModel::ImpreciseMultiEcho;
	params.imprecision = 0.2;
	params.profile = ImprecisionProfile::Gaussian;
	check(sectorMassesByCombination(params, {3}, 1.0, 5).size() == 5, "sectorMassesByCombination");

	mrpt::obs::CObservation2DRangeScan scan;
	scan.resizeScanAndAssign(3, 2.0f, true);
	CPolarSourceGrid grid;
	grid.build(scan, TSourceGridOptions{});
	check(grid.sectorCount() == 3 && grid.at(1, 0).free > 0, "CPolarSourceGrid");

	std::printf("consumer: %s\n", failures ? "FAILED" : "all calls answered right");
	return failures ? 1 : 0;
}
