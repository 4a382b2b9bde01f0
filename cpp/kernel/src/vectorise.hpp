// Internal: lets the hot loops of the kernel use AVX2 where the processor has it.
#pragma once

/// On x86-64 with GCC, a function marked FAIRSPLINES_VECTORISE is compiled twice, for
/// AVX2 and for the baseline, and the loader picks the one the processor runs
/// (function multi-versioning). Elsewhere it is an ordinary function. It changes no
/// result: there is no FMA contraction and no reassociation under either target.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define FAIRSPLINES_VECTORISE __attribute__((target_clones("avx2", "default")))
#else
#define FAIRSPLINES_VECTORISE
#endif
