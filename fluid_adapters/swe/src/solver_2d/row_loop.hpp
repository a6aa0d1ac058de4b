#pragma once

// The solver's row loops are compiled for AVX-512 and AVX2 too and picked at
// run time where the CPU has them (GCC function multi-versioning). Without
// FMA contraction (-ffp-contract=off on the solver's files) every version
// gives the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && \
    !defined(__SANITIZE_ADDRESS__)
#define SWE_2D_ROW_LOOP [[gnu::target_clones("avx512f", "avx2", "default")]]
#else
#define SWE_2D_ROW_LOOP
#endif
