/* What the e2e scripts expect of the MRPT they run: prints
 * "unknown-maps: rejected" when a stock program stops on an .ini naming a map
 * class nobody registered (MRPT 2.11.3 and later), "unknown-maps: skipped"
 * when it goes on without that map (before). From MrptCompat.h, the one
 * place that knows the MRPT versions. */
#include <mrpt_evidential/MrptCompat.h>

#include <cstdio>

int main()
{
#if MRPT_EVIDENTIAL_MRPT_REJECTS_UNKNOWN_MAPS
	std::puts("unknown-maps: rejected");
#else
	std::puts("unknown-maps: skipped");
#endif
	return 0;
}
