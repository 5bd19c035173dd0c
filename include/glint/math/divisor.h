#pragma once
/// \file Division by a fixed count, bit for bit what `/` and `%` give, faster where the count
/// is a power of two.

#include <bit>
#include <cstdint>

namespace glint {

/// A positive integer d that the caller divides by again and again (a sampler's strata, a
/// set's grid): quotient(i) = i / d, remainder(i) = i % d and divide(x) = x / float(d), each
/// exactly. Where d = 2^k they are a shift, a mask and a product with 2^-k, which equals the
/// quotient x / 2^k bit for bit (2^-k is a float for k ≤ 31, so both round the same exact
/// value x·2^-k once); other d take the divisions. Integer and float divisions cost 10–15
/// cycles of latency, and the samplers chain two or three of them on every draw
/// (docs/performance.md, "Sampler draws without divisions").
class Divisor {
public:
    /// `d` must be positive.
    explicit Divisor(uint32_t d)
        : d_(d),
          shift_(std::has_single_bit(d) ? std::countr_zero(d) : -1),
          d_float_(float(d)),
          reciprocal_(1.0f / float(d)) {}

    [[nodiscard]] uint32_t quotient(uint32_t i) const { return shift_ >= 0 ? i >> shift_ : i / d_; }
    [[nodiscard]] uint32_t remainder(uint32_t i) const { return shift_ >= 0 ? i & (d_ - 1) : i % d_; }
    [[nodiscard]] float divide(float x) const { return shift_ >= 0 ? x * reciprocal_ : x / d_float_; }
    [[nodiscard]] uint32_t value() const { return d_; }

private:
    uint32_t d_;
    /// k where d = 2^k, else −1.
    int shift_;
    float d_float_;
    /// 1/d, exact where d is a power of two (the only case it is used).
    float reciprocal_;
};

}  // namespace glint
