#pragma once
// SLIDEWAVE_VECTOR_CLONES: a hot loop's function compiled for the widest vector units the machine has, chosen
// when the program starts (GCC's target_clones: an AVX-512F, an AVX2 and a baseline x86-64 clone).
//
// Contraction off: with it, GCC may fuse a product and a sum into one FMA (AVX2 and AVX-512F machines have
// FMA), which rounds once where the baseline code rounds twice. The clones then differ from the baseline
// code only in vector width, which leaves every entry's operations and their order unchanged (GCC does not
// reorder a floating-point sum without -ffast-math): a run gives the same bits on every x86-64 CPU.
// SLIDEWAVE_NO_AVX512 (CMake option of the same name) drops the AVX-512 clone: a build that runs here as an
// AVX2-only machine would, to measure the speed such machines get (bench/whole_run.sh).
// Helpers a cloned function calls must be inlined into it (templates and `inline` functions of the same file
// are) to run at its width.
#if SLIDEWAVE_NO_AVX512
#define SLIDEWAVE_VECTOR_CLONES __attribute__((target_clones("avx2", "default"), optimize("fp-contract=off")))
#else
#define SLIDEWAVE_VECTOR_CLONES \
  __attribute__((target_clones("avx512f", "avx2", "default"), optimize("fp-contract=off")))
#endif
