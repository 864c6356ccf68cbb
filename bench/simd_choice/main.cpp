// simd_choice — the same fragment-shader arithmetic (kernels.h) with softgl's lane types and with three SIMD
// libraries, timed on this machine: nanoseconds per 16 fragments, best of several runs, and the results compared.
//
//   build/release/bench/simd_choice [repeats]
//
// docs/architecture.md quotes its table (why softgl's lanes are GCC vector types rather than one of the libraries).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <softgl/lanes.h>

#include "kernels.h"

using namespace simd_choice;

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 200;
  constexpr std::size_t kN = 4096;  // fragments per pass: 9 arrays of 16 KiB, resident in the L2 cache
  std::vector<float> in[6], out[3], ref[3];
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (auto& a : in) {
    a.resize(kN);
    for (float& x : a) x = u(rng);
  }
  for (int c = 0; c < 3; ++c) {
    out[c].resize(kN);
    ref[c].resize(kN);
  }
  auto frags = [&](std::vector<float>* o) {
    return Fragments{in[0].data(), in[1].data(), in[2].data(), in[3].data(), in[4].data(), in[5].data(),
                     o[0].data(), o[1].data(), o[2].data(), kN};
  };
  ShadeScalar(frags(ref));
  const int level = softgl::SimdLevel();
  struct Row {
    std::string name;
    int needs;  // instruction set needed: 1 AVX2, 2 AVX-512
    std::function<void(const Fragments&)> fn;
  };
  const std::vector<Row> rows = {
      {"plain floats (one lane at a time, as compiled)", 0, ShadeScalar},
      {"softgl lanes, SSE2 (baseline)", 0, [](const Fragments& f) { ShadeSoftgl(f, 0); }},
      {"softgl lanes, AVX2 (run-time dispatch)", 1, [](const Fragments& f) { ShadeSoftgl(f, 1); }},
      {"softgl lanes, AVX-512 (run-time dispatch)", 2, [](const Fragments& f) { ShadeSoftgl(f, 2); }},
      {"std::experimental::simd<16>, baseline unit, avx2 function", 1, ShadeStdSimdBaseline},
      {"std::experimental::simd<16>, unit built for AVX2", 1, ShadeStdSimdAvx2},
      {"std::experimental::simd<16>, unit built for AVX-512", 2, ShadeStdSimdAvx512},
      {"xsimd batch<float, avx2>, unit built for AVX2", 1, ShadeXsimdAvx2},
      {"xsimd batch<float, avx512f>, unit built for AVX-512", 2, ShadeXsimdAvx512},
      {"Highway (static AVX2), unit built for AVX2", 1, ShadeHighwayAvx2},
      {"Highway (static AVX-512), unit built for AVX-512", 2, ShadeHighwayAvx512},
  };
  struct Result {
    std::string name;
    double per16;  // ns per 16 fragments; negative: not available
    float diff;
  };
  std::vector<Result> results;
  double softgl_best = 0.0;
  for (const Row& row : rows) {
    if (row.needs > level) {
      results.push_back({row.name, -1.0, 0.0f});
      continue;
    }
    const Fragments f = frags(out);
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      row.fn(f);
      const auto t1 = std::chrono::steady_clock::now();
      best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count());
    }
    const double per16 = best / double(kN / 16);
    float diff = 0.0f;
    for (int c = 0; c < 3; ++c)
      for (std::size_t i = 0; i < kN; ++i) diff = std::max(diff, std::fabs(out[c][i] - ref[c][i]));
    if (row.needs == level && row.name.rfind("softgl", 0) == 0) softgl_best = per16;
    results.push_back({row.name, per16, diff});
  }
  std::printf("| kernel | ns per 16 fragments | time / softgl lanes' on the widest set | largest difference from plain floats |\n");
  std::printf("|---|---|---|---|\n");
  for (const Result& r : results) {
    if (r.per16 < 0.0)
      std::printf("| %s | (instruction set not available) | | |\n", r.name.c_str());
    else
      std::printf("| %s | %.1f | %.2f | %.2g |\n", r.name.c_str(), r.per16, r.per16 / softgl_best, double(r.diff));
  }
  return 0;
}
