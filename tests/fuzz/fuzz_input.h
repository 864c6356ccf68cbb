// fuzz_input.h — reads typed values from a fuzzer's bytes; past the end it returns zeros.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace fuzz {

class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool Empty() const { return pos_ >= size_; }
  std::size_t Remaining() const { return pos_ < size_ ? size_ - pos_ : 0; }
  template <class T>
  T Get() {
    T v{};
    const std::size_t n = sizeof(T) < Remaining() ? sizeof(T) : Remaining();
    if (n) std::memcpy(&v, data_ + pos_, n);
    pos_ += sizeof(T);
    return v;
  }
  std::uint8_t Byte() { return Get<std::uint8_t>(); }
  /// An int mostly in [lo, hi], sometimes anything (negative, huge) to reach the error paths.
  int Int(int lo, int hi) {
    const std::uint8_t pick = Byte();
    const int raw = Get<int>();
    if (pick < 16) return raw;
    const long span = long(hi) - long(lo) + 1;
    return int(lo + ((long(raw) % span) + span) % span);
  }
  /// Int(lo, hi) for an amount of memory or work: a wild value in (cap, limit] (valid, merely huge) is folded back
  /// into [hi, cap], so that one input costs at most `cap`; values below lo or past `limit` stay as they are, to
  /// reach the error paths. A huge valid size would test the machine's memory and patience, not softgl (allocation
  /// failure has its own test, tests/oom_check.cpp), and would make a run's outcome depend on the machine's load.
  int Amount(int lo, int hi, int cap, long limit = 0x7FFFFFFFL) {
    const int v = Int(lo, hi);
    if (v > cap && long(v) <= limit) return hi + int((long(v) - hi) % (long(cap) - hi + 1));
    return v;
  }
  /// One of `choices`, or (rarely) any value, to reach INVALID_ENUM paths.
  template <std::size_t N>
  std::uint32_t Enum(const std::uint32_t (&choices)[N]) {
    const std::uint8_t pick = Byte();
    if (pick < 8) return Get<std::uint32_t>();
    return choices[pick % N];
  }
  /// A float from raw bits (NaN, infinities, huge values included) or a small one.
  float Float() {
    const std::uint8_t pick = Byte();
    if (pick < 32) return Get<float>();
    return float(Get<std::int16_t>()) / 8192.0f;
  }
  const std::uint8_t* Bytes(std::size_t n) {
    const std::uint8_t* p = data_ + (pos_ < size_ ? pos_ : size_);
    pos_ += n;
    return p;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace fuzz
