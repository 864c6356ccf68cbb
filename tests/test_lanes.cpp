// The lane types and maths of wide shaders (softgl/lanes.h): the exact functions give GLM's and the standard
// library's bits lane for lane, the polynomial ones stay within stated bounds, and every instruction set computes
// the same bits.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <softgl/lanes.h>

using namespace softgl;

namespace {

std::uint32_t BitsOf(float f) {
  std::uint32_t b;
  std::memcpy(&b, &f, 4);
  return b;
}

// Equal as bits, or both NaN.
bool Same(float a, float b) { return BitsOf(a) == BitsOf(b) || (std::isnan(a) && std::isnan(b)); }

// Distance in units in the last place between floats of the same sign.
double Ulps(float got, double want) {
  if (std::isnan(got) || std::isnan(want)) return std::isnan(got) && std::isnan(want) ? 0.0 : 1e30;
  if (std::isinf(want)) return got == float(want) ? 0.0 : 1e30;
  const float w = float(want);
  const double ulp = std::max(std::nextafter(std::fabs(w), INFINITY) - std::fabs(w), std::numeric_limits<float>::denorm_min());
  return std::fabs(double(got) - want) / double(ulp);
}

// 16-lane inputs: random values of several magnitudes, and the special ones.
std::vector<float> Inputs(std::uint32_t seed, float lo, float hi, bool specials) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> d(lo, hi);
  std::vector<float> v(16 * 64);
  for (float& x : v) x = d(rng);
  if (specials) {
    const float s[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 1e-40f, -1e-40f, 1e30f, -1e30f,
                       INFINITY, -INFINITY, NAN, 8388608.5f, -8388609.0f, 0.999999f};
    for (int i = 0; i < 16; ++i) v[std::size_t(i)] = s[i];
  }
  return v;
}

Float Lanes(const std::vector<float>& v, std::size_t block) { return Float::Load(v.data() + block * 16); }

// Every lane of f(x) against g(x), as bits.
void CheckExact(const char* name, const std::vector<float>& x, const std::function<Float(Float)>& f,
                const std::function<float(float)>& g) {
  int wrong = 0;
  for (std::size_t b = 0; b < x.size() / 16; ++b) {
    const Float r = f(Lanes(x, b));
    for (int l = 0; l < 16; ++l) {
      const float in = x[b * 16 + std::size_t(l)], want = g(in);
      if (!Same(r[l], want)) {
        if (wrong++ < 3) INFO(name << "(" << in << "): " << r[l] << " instead of " << want);
        CHECK(Same(r[l], want));
      }
    }
  }
  INFO(name);
  CHECK(wrong == 0);
}

}  // namespace

TEST_CASE("lane arithmetic, sqrt, inversesqrt, floor and friends give the bits of float and GLM", "[lanes]") {
  const auto x = Inputs(1, -100.0f, 100.0f, true), y = Inputs(2, -10.0f, 10.0f, true);
  auto binary = [&](const char* name, const std::function<Float(Float, Float)>& f,
                    const std::function<float(float, float)>& g) {
    int wrong = 0;
    for (std::size_t b = 0; b < x.size() / 16; ++b) {
      const Float r = f(Lanes(x, b), Lanes(y, b));
      for (int l = 0; l < 16; ++l) {
        const std::size_t i = b * 16 + std::size_t(l);
        if (!Same(r[l], g(x[i], y[i]))) ++wrong;
      }
    }
    INFO(name);
    CHECK(wrong == 0);
  };
  binary("+", [](Float a, Float b) { return a + b; }, [](float a, float b) { return a + b; });
  binary("-", [](Float a, Float b) { return a - b; }, [](float a, float b) { return a - b; });
  binary("*", [](Float a, Float b) { return a * b; }, [](float a, float b) { return a * b; });
  binary("/", [](Float a, Float b) { return a / b; }, [](float a, float b) { return a / b; });
  binary("min", [](Float a, Float b) { return min(a, b); }, [](float a, float b) { return glm::min(a, b); });
  binary("max", [](Float a, Float b) { return max(a, b); }, [](float a, float b) { return glm::max(a, b); });
  binary("mod", [](Float a, Float b) { return mod(a, b); }, [](float a, float b) { return glm::mod(a, b); });
  binary("step", [](Float a, Float b) { return step(a, b); }, [](float a, float b) { return glm::step(a, b); });
  const auto pos = Inputs(3, 0.0f, 1e6f, false);
  CheckExact("sqrt", x, [](Float a) { return sqrt(a); }, [](float a) { return std::sqrt(a); });
  CheckExact("sqrt", pos, [](Float a) { return sqrt(a); }, [](float a) { return std::sqrt(a); });
  CheckExact("inversesqrt", pos, [](Float a) { return inversesqrt(a); }, [](float a) { return glm::inversesqrt(a); });
  CheckExact("floor", x, [](Float a) { return floor(a); }, [](float a) { return std::floor(a); });
  CheckExact("ceil", x, [](Float a) { return ceil(a); }, [](float a) { return std::ceil(a); });
  CheckExact("fract", Inputs(4, -1e5f, 1e5f, false), [](Float a) { return fract(a); },
             [](float a) { return glm::fract(a); });
  CheckExact("abs", x, [](Float a) { return abs(a); }, [](float a) { return std::fabs(a); });
  CheckExact("clamp", x, [](Float a) { return clamp(a, -1.0f, 2.0f); }, [](float a) { return glm::clamp(a, -1.0f, 2.0f); });
  CheckExact("mix", x, [](Float a) { return mix(a, Float(3.0f), 0.3f); }, [](float a) { return glm::mix(a, 3.0f, 0.3f); });
  CheckExact("smoothstep", x, [](Float a) { return smoothstep(-50.0f, 70.0f, a); },
             [](float a) { return glm::smoothstep(-50.0f, 70.0f, a); });
  CheckExact("int conversion", Inputs(5, -1e6f, 1e6f, false), [](Float a) { return Float(Int(a)); },
             [](float a) { return float(int(a)); });
}

TEST_CASE("vector functions and matrix products give GLM's bits lane for lane", "[lanes]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> d(-3.0f, 3.0f);
  const glm::mat4 m = glm::perspective(0.8f, 1.3f, 0.1f, 50.0f) *
                      glm::lookAt(glm::vec3(1, 2, 3), glm::vec3(0), glm::vec3(0, 1, 0));
  const glm::mat3 m3 = glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(1, 2, 3)));
  int wrong = 0, checked = 0;
  for (int round = 0; round < 50; ++round) {
    float in[4][16], n[3][16];
    for (auto& c : in)
      for (float& v : c) v = d(rng);
    for (auto& c : n)
      for (float& v : c) v = d(rng);
    const vec4 a(Float::Load(in[0]), Float::Load(in[1]), Float::Load(in[2]), Float::Load(in[3]));
    const vec3 b(Float::Load(n[0]), Float::Load(n[1]), Float::Load(n[2]));
    const vec3 a3(a);
    const vec4 mv = m * a;
    const vec3 m3v = m3 * a3;
    const Float dt = dot(a3, b), len = length(a3), dist = distance(a3, b);
    const vec3 cr = cross(a3, b), nm = normalize(a3), rf = reflect(a3, normalize(b)), rr = refract(nm, normalize(b), 0.7f);
    for (int l = 0; l < 16; ++l) {
      const glm::vec4 ga = a.Lane(l);
      const glm::vec3 ga3(ga), gb = b.Lane(l);
      auto same3 = [&](const vec3& w, const glm::vec3& g) {
        return Same(w.x[l], g.x) && Same(w.y[l], g.y) && Same(w.z[l], g.z);
      };
      const glm::vec4 gmv = m * ga;
      bool ok = Same(mv.x[l], gmv.x) && Same(mv.y[l], gmv.y) && Same(mv.z[l], gmv.z) && Same(mv.w[l], gmv.w);
      ok = ok && same3(m3v, m3 * ga3) && Same(dt[l], glm::dot(ga3, gb)) && Same(len[l], glm::length(ga3)) &&
           Same(dist[l], glm::distance(ga3, gb));
      ok = ok && same3(cr, glm::cross(ga3, gb)) && same3(nm, glm::normalize(ga3)) &&
           same3(rf, glm::reflect(ga3, glm::normalize(gb))) &&
           same3(rr, glm::refract(glm::normalize(ga3), glm::normalize(gb), 0.7f));
      if (!ok) ++wrong;
      ++checked;
    }
  }
  CHECK(checked == 800);
  CHECK(wrong == 0);
}

TEST_CASE("exp2, log2, exp, log, pow, sin and cos stay within their bounds", "[lanes]") {
  // The largest error over many inputs, against double precision: stated in lanes.h as "a few units in the last
  // place"; the bounds below are what the polynomials give, with a little room.
  auto worst = [](const std::vector<float>& x, const std::function<Float(Float)>& f, const std::function<double(double)>& g) {
    double w = 0.0;
    for (std::size_t b = 0; b < x.size() / 16; ++b) {
      const Float r = f(Lanes(x, b));
      for (int l = 0; l < 16; ++l) w = std::max(w, Ulps(r[l], g(double(x[b * 16 + std::size_t(l)]))));
    }
    return w;
  };
  const auto e = Inputs(21, -120.0f, 120.0f, false), small = Inputs(22, -4.0f, 4.0f, false);
  const auto positive = Inputs(23, 1e-30f, 1e30f, false), near_one = Inputs(24, 0.5f, 2.0f, false);
  CHECK(worst(e, [](Float a) { return exp2(a); }, [](double a) { return std::exp2(a); }) <= 2.0);
  CHECK(worst(small, [](Float a) { return exp(a); }, [](double a) { return std::exp(a); }) <= 4.0);
  CHECK(worst(positive, [](Float a) { return log2(a); }, [](double a) { return std::log2(a); }) <= 2.0);
  CHECK(worst(positive, [](Float a) { return log(a); }, [](double a) { return std::log(a); }) <= 3.0);
  // Near 1, log2 is small: measured in units of the last place of the argument's distance from 1 instead.
  double near = 0.0;
  for (std::size_t b = 0; b < near_one.size() / 16; ++b) {
    const Float r = log2(Lanes(near_one, b));
    for (int l = 0; l < 16; ++l)
      near = std::max(near, std::fabs(double(r[l]) - std::log2(double(near_one[b * 16 + std::size_t(l)]))));
  }
  CHECK(near < 2e-7);
  // pow: the error of exp2(y log2 x) grows with |y log2 x|; relative error below 1e-6 where that is below 16.
  std::mt19937 rng(25);
  std::uniform_real_distribution<float> base(0.01f, 4.0f), expo(-4.0f, 4.0f);
  double rel = 0.0;
  for (int round = 0; round < 64; ++round) {
    float xs[16], ys[16];
    for (int l = 0; l < 16; ++l) {
      xs[l] = base(rng);
      ys[l] = expo(rng);
    }
    const Float r = pow(Float::Load(xs), Float::Load(ys));
    for (int l = 0; l < 16; ++l) {
      const double want = std::pow(double(xs[l]), double(ys[l]));
      rel = std::max(rel, std::fabs(double(r[l]) - want) / want);
    }
  }
  CHECK(rel < 1e-6);
  // sin and cos: absolute error against the exact values, |x| up to 1000.
  const auto angles = Inputs(26, -1000.0f, 1000.0f, false);
  double abs_err = 0.0;
  for (std::size_t b = 0; b < angles.size() / 16; ++b) {
    const Float s = sin(Lanes(angles, b)), c = cos(Lanes(angles, b));
    for (int l = 0; l < 16; ++l) {
      const double a = double(angles[b * 16 + std::size_t(l)]);
      abs_err = std::max({abs_err, std::fabs(double(s[l]) - std::sin(a)), std::fabs(double(c[l]) - std::cos(a))});
    }
  }
  CHECK(abs_err < 4e-7);
}

TEST_CASE("the approximations are exact where GLSL's functions are exact, and honour the special values",
          "[lanes]") {
  float ints[16], twos[16];
  for (int l = 0; l < 16; ++l) {
    ints[l] = float(l * 8 - 60);  // -60 .. 60
    twos[l] = std::ldexp(1.0f, l * 8 - 60);
  }
  const Float e = exp2(Float::Load(ints)), lg = log2(Float::Load(twos));
  for (int l = 0; l < 16; ++l) {
    CHECK(e[l] == std::ldexp(1.0f, l * 8 - 60));
    CHECK(lg[l] == float(l * 8 - 60));
  }
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = INFINITY;
  CHECK(std::isnan(log2(Float(-1.0f))[0]));
  CHECK(log2(Float(0.0f))[0] == -inf);
  CHECK(log2(Float(inf))[0] == inf);
  CHECK(std::isnan(log2(Float(nan))[0]));
  CHECK(exp2(Float(-200.0f))[0] == 0.0f);
  CHECK(exp2(Float(200.0f))[0] == inf);
  CHECK(exp2(Float(128.0f))[0] == inf);
  CHECK(exp2(Float(-126.0f))[0] == std::ldexp(1.0f, -126));
  CHECK(std::isnan(exp2(Float(nan))[0]));
  CHECK(pow(Float(7.5f), Float(0.0f))[0] == 1.0f);
  CHECK(pow(Float(1.0f), Float(123.0f))[0] == 1.0f);
  CHECK(pow(Float(0.0f), Float(2.0f))[0] == 0.0f);
  CHECK(pow(Float(0.0f), Float(-2.0f))[0] == inf);
  CHECK(std::isnan(pow(Float(-2.0f), Float(0.5f))[0]));
  CHECK(pow(Float(2.0f), Float(10.0f))[0] == 1024.0f);
  CHECK(std::isnan(sin(Float(inf))[0]));
  CHECK(std::isnan(cos(Float(nan))[0]));
  CHECK(sin(Float(0.0f))[0] == 0.0f);
  CHECK(cos(Float(0.0f))[0] == 1.0f);
}

TEST_CASE("conditions, selection and lane masks", "[lanes]") {
  float v[16];
  for (int l = 0; l < 16; ++l) v[l] = float(l);
  const Float x = Float::Load(v);
  const Bool odd = (Int(x) & 1) != 0;
  CHECK(odd.Bits() == 0xAAAAu);
  CHECK(Bool::FromBits(0x1234u).Bits() == 0x1234u);
  CHECK((x < 4.0f || x >= 12.0f).Bits() == 0xF00Fu);
  CHECK((!(x < 4.0f) && x < 8.0f).Bits() == 0x00F0u);
  CHECK(any(x > 14.5f));
  CHECK_FALSE(any(x > 15.5f));
  CHECK(all(x >= 0.0f));
  CHECK_FALSE(all(x > 0.0f));
  const Float s = select(odd, x * 10.0f, -x);
  for (int l = 0; l < 16; ++l) CHECK(s[l] == (l & 1 ? float(l) * 10.0f : -float(l)));
  const vec2 sv = select(odd, vec2(1.0f, 2.0f), vec2(x, x));
  CHECK(sv.y[3] == 2.0f);
  CHECK(sv.y[4] == 4.0f);
  // Broadcasts keep every float exactly, -0 and NaN payloads included.
  CHECK(std::signbit(Float(-0.0f)[9]));
  CHECK(BitsOf(Float::FromBits(Int(0x7FA5F1A7))[15]) == 0x7FA5F1A7u);
}

TEST_CASE("integer division and remainder truncate toward zero, with a defined result where GLSL has none",
          "[lanes]") {
  const std::int32_t a[16] = {7, -7, 7, -7, 0, 100, INT32_MIN, INT32_MIN, 5, -5, INT32_MAX, 1, 9, -9, 3, 12};
  const std::int32_t b[16] = {2, 2, -2, -2, 5, 0, -1, 1, 0, -1, 7, 1, 3, 4, -1, 5};
  const Int q = Int::Load(a) / Int::Load(b), r = Int::Load(a) % Int::Load(b);
  for (int l = 0; l < 16; ++l) {
    INFO("lane " << l << ": " << a[l] << " / " << b[l]);
    if (b[l] == 0) {
      CHECK(q[l] == 0);
      CHECK(r[l] == 0);
    } else if (b[l] == -1) {  // INT_MIN / -1 overflows in C++: the lane keeps INT_MIN
      CHECK(q[l] == (a[l] == INT32_MIN ? INT32_MIN : -a[l]));
      CHECK(r[l] == 0);
    } else {
      CHECK(q[l] == a[l] / b[l]);
      CHECK(r[l] == a[l] % b[l]);
    }
  }
  Int c = Int(17);
  c /= 5;
  c %= 2;
  CHECK(c[0] == 1);
}

TEST_CASE("dFdx and dFdy take differences within each 2x2 quad of the 16 lanes", "[lanes]") {
  // Lane = quad * 4 + (x & 1) + 2 (y & 1); a value of 10 x + 100 y + 1000 quad has dFdx 10, dFdy 100 everywhere.
  float v[16];
  for (int l = 0; l < 16; ++l) v[l] = float(10 * (l & 1) + 100 * ((l >> 1) & 1) + 1000 * (l >> 2));
  const Float a = Float::Load(v), dx = dFdx(a), dy = dFdy(a), w = fwidth(a);
  for (int l = 0; l < 16; ++l) {
    CHECK(dx[l] == 10.0f);
    CHECK(dy[l] == 100.0f);
    CHECK(w[l] == 110.0f);
  }
  // Within a quad, dFdx is taken along each lane's own row (fine derivatives).
  v[1] = 50.0f;  // quad 0, row 0, right
  const Float rows = dFdx(Float::Load(v));
  CHECK(rows[0] == 50.0f);
  CHECK(rows[1] == 50.0f);
  CHECK(rows[2] == 10.0f);
  CHECK(rows[3] == 10.0f);
}

namespace {

// The same computations compiled for each instruction set (as wide shaders are), to compare their bits.
struct Battery {
  float out[12][16];
};
inline void RunBattery(const float* in, Battery& b) {
  const Float x = Float::Load(in), y = Float::Load(in + 16);
  const vec3 v(x, y, x * y);
  const Float r[12] = {sqrt(abs(x)), inversesqrt(abs(y) + 1.0f), pow(abs(x) + 0.5f, y), exp(y), log(abs(x) + 1e-3f),
                       sin(x * 7.0f), cos(y * 3.0f), floor(x * 3.3f), smoothstep(-1.0f, 1.0f, y),
                       dot(normalize(v), vec3(glm::vec3(0.3f, 0.5f, 0.8f))), mod(x, y + 3.0f), exp2(y * 9.0f)};
  for (int i = 0; i < 12; ++i) r[i].Store(b.out[i]);
}
void BatteryBase(const float* in, Battery& b) { RunBattery(in, b); }
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 void BatteryAvx2(const float* in, Battery& b) { RunBattery(in, b); }
SOFTGL_TARGET_AVX512 void BatteryAvx512(const float* in, Battery& b) { RunBattery(in, b); }
#endif

}  // namespace

TEST_CASE("every instruction set computes the same bits", "[lanes]") {
  std::mt19937 rng(31);
  std::uniform_real_distribution<float> d(-2.0f, 2.0f);
  int compared = 0;
  for (int round = 0; round < 200; ++round) {
    float in[32];
    for (float& f : in) f = d(rng);
    Battery base;
    BatteryBase(in, base);
#if defined(SOFTGL_HAS_DISPATCH)
    for (int level = 1; level <= SimdLevel(); ++level) {
      Battery wide;
      if (level == 1) BatteryAvx2(in, wide);
      else BatteryAvx512(in, wide);
      for (int i = 0; i < 12; ++i)
        for (int l = 0; l < 16; ++l) {
          if (!Same(base.out[i][l], wide.out[i][l])) {
            INFO("function " << i << " level " << level << ": " << base.out[i][l] << " vs " << wide.out[i][l]);
            CHECK(Same(base.out[i][l], wide.out[i][l]));
          }
          ++compared;
        }
    }
#endif
  }
  INFO("instruction sets beyond SSE2 on this processor: " << SimdLevel());
  CHECK(compared == 200 * 12 * 16 * SimdLevel());
}
