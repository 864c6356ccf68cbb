// simd.cpp — the processor's vector level, read once.
#include "simd.h"

#include <softgl/lanes.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

namespace softgl::detail {

namespace {

SimdLevel Detect() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  int level = 0;
  // F16C (half conversions) from CPUID leaf 1, ECX bit 29: every AVX2 processor has it, checked all the same.
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  const bool f16c = __get_cpuid(1, &eax, &ebx, &ecx, &edx) && ((ecx >> 29) & 1u);
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("sse4.1") && f16c) level = 1;
  if (level == 1 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl"))
    level = 2;
  if (const char* cap = std::getenv("SOFTGL_SIMD")) {
    if (std::strcmp(cap, "sse2") == 0) level = 0;
    if (std::strcmp(cap, "avx2") == 0) level = std::min(level, 1);
  }
  return SimdLevel(level);
#else
  return SimdLevel::kBaseline;
#endif
}

}  // namespace

SimdLevel CpuSimdLevel() {
  static const SimdLevel level = Detect();
  return level;
}

}  // namespace softgl::detail

int softgl::SimdLevel() { return int(detail::CpuSimdLevel()); }
