/* mrpt-evidential: internal: the insertion's hot loops built twice, for any
 * x86-64 processor and for one with AVX2. */
#pragma once

/** Put on a function (or function template) to have GCC compile it once for
 * the baseline x86-64 of Debian's packages and once with AVX2, the loader
 * choosing the copy the processor can run (function multiversioning, through
 * glibc's ifunc). The AVX2 copy handles twice the cells per vector
 * instruction in the loops the compiler vectorizes (doc/performance-history.md).
 * Everything the function calls is inlined into each copy (`flatten`): GCC
 * does not inline a baseline function into an AVX2 one by itself, and the
 * copy calling the transform's per-cell mix out of line was slower than no
 * copy.
 * FMA is left out on purpose: fused multiply-adds round differently, and a
 * map must be the same bit for bit on every processor. Empty where the
 * mechanism is missing (another compiler or architecture), or when the build
 * defines MRPT_EVIDENTIAL_NO_CPU_CLONES (CMake: -DMRPT_EVIDENTIAL_AVX2=OFF).
 * Empty under GCC's ThreadSanitizer too: the loader runs the copies' ifunc
 * resolvers while it relocates the library, before ThreadSanitizer's
 * runtime is up, and the process dies there (GCC 12, glibc 2.36). */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && \
	defined(__ELF__) && !defined(MRPT_EVIDENTIAL_NO_CPU_CLONES) && \
	!defined(__SANITIZE_THREAD__)
#define MRPT_EVIDENTIAL_CPU_CLONES \
	__attribute__((target_clones("default", "avx2"), flatten))
#else
#define MRPT_EVIDENTIAL_CPU_CLONES
#endif
