// Turns a fuzzer's input bytes into the values a target needs: bytes, flags, small integers and
// doubles drawn from the classes that break numeric code (NaN, ±inf, huge, denormal, zero,
// negative, raw bit patterns) as well as plausible machine values, so that most inputs also reach
// the deep paths (a move that is accepted and runs). Reading past the end gives zeros: every
// input, however short, is a complete program.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>

namespace fuzz {

// Set by a target when the environment asks for a trace (FUZZ_TRACE=1): every number read is
// printed, so a crashing input can be read as the program it is.
inline bool g_trace = false;

class ByteReader {
 public:
  ByteReader(const uint8_t* data, std::size_t size) noexcept : data_(data), size_(size) {}

  bool empty() const noexcept { return pos_ >= size_; }
  std::size_t consumed() const noexcept { return pos_; }

  uint8_t byte() noexcept { return pos_ < size_ ? data_[pos_++] : 0; }
  bool flag() noexcept { return (byte() & 1U) != 0; }
  uint16_t u16() noexcept {
    const auto hi = static_cast<uint16_t>(byte());
    return static_cast<uint16_t>((hi << 8U) | byte());
  }
  // 0 … n-1 (n > 0).
  std::size_t below(std::size_t n) noexcept { return static_cast<std::size_t>(byte()) % n; }

  // Eight bytes as a double, bit for bit (any NaN payload, denormal, ±0, ±inf).
  double raw_double() noexcept {
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i)
      bits = (bits << 8U) | byte();
    double d = 0.0;
    std::memcpy(&d, &bits, sizeof d);
    return d;
  }

  // A double of a class picked by one tag byte; half of the classes are plausible values of
  // machine size (0.001 … 100000, either sign), the rest the classes that break numeric code.
  double number() noexcept {
    const double x = draw();
    if (g_trace) std::fprintf(stderr, " %.17g", x);
    return x;
  }

 private:
  double draw() noexcept {
    using L = std::numeric_limits<double>;
    const uint8_t tag = byte();
    const double sign = (tag & 0x80U) != 0 ? -1.0 : 1.0;
    switch (tag & 0x0FU) {
      case 0:
        return sign * 0.0;
      case 1:
        return L::quiet_NaN();
      case 2:
        return sign * L::infinity();
      case 3:
        return sign * L::denorm_min() * (1.0 + byte());
      case 4:
        return sign * L::max() / (1.0 + byte());
      case 5:
        return sign * 1e300 * (1.0 + byte());
      case 6:
        return raw_double();
      case 7:
        return sign * L::min() * (1.0 + byte());  // smallest normals
      default: {
        // Plausible: u16 spread over six decades picked by the tag.
        static constexpr double kScale[8] = {1e-3, 1e-2, 1.0, 10.0, 100.0, 1000.0, 1e4, 1e5};
        const double unit = kScale[(tag >> 4U) & 0x07U];
        return sign * unit * (static_cast<double>(u16()) / 65535.0) * 10.0;
      }
    }
  }

  const uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace fuzz
