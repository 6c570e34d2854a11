// Code for AVX2 beside code for any x86 (the default build assumes no more than SSE2): whether it
// can be compiled here, and whether this CPU runs it. The reference's 8-wide tree
// (solutions/05c_wide_bvh/wide8.h) and the sampler's blocks (framework/src/sampler.cpp) use it.
#pragma once

// GCC or Clang on x86; not MinGW's GCC, which cannot align a 32-byte vector on the stack of a
// Win64 function (GCC bug 54412) and could crash on the spilled __m256 values. Functions for AVX2
// are marked __attribute__((target("avx2"))) and called only where avx2_runs_here().
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__)) && \
    !(defined(_WIN32) && !defined(__clang__))
#include <immintrin.h>
#define RAYLAB_AVX2_COMPILES 1
#endif

namespace raylab {

inline bool avx2_runs_here() {
#if RAYLAB_AVX2_COMPILES
  __builtin_cpu_init();                  // (in case it is asked before the constructors have run)
  return __builtin_cpu_supports("avx2");  // (GCC's and Clang's check include the OS saving AVX state)
#else
  return false;
#endif
}

}  // namespace raylab
