/* Links mrpt_evidential::algebra alone: the mass algebra needs no MRPT and
 * no library. Exits non-zero on a wrong answer. */
#include <mrpt_evidential/algebra/combination.h>

#include <cmath>

int main()
{
	using namespace mrpt_evidential;
	const Mass fused = conjunctive(Mass::simpleFree(0.7), Mass::simpleOccupied(0.9));
	const Mass kept = handleConflict(fused, ConflictHandling::Normalize);
	return (std::abs(fused.conflict - 0.63) < 1e-12 && kept.conflict == 0.0) ? 0 : 1;
}
