#pragma once
// Named fixed-point types used in the per-pixel and per-edge stages of the pipeline.
// A Q<IntBits, FracBits> holds a signed value in a 32-bit or 64-bit integer with FracBits
// fraction bits. Conversions round to nearest and saturate at the type's range, so that
// a value out of range shows as the extreme, never as a wrapped number.
#include <cstdint>
#include <limits>
#include <type_traits>

namespace icacam::vision {

template <int IntBits, int FracBits> class Q {
    static_assert(IntBits >= 1 && FracBits >= 0, "Q needs a sign/integer bit");
    static_assert(IntBits + FracBits <= 64, "Q wider than 64 bits");

public:
    using Raw = std::conditional_t<(IntBits + FracBits <= 32), int32_t, int64_t>;
    static constexpr int kFracBits = FracBits;
    static constexpr Raw kOne = Raw(1) << FracBits;
    static constexpr Raw kMaxRaw = (IntBits + FracBits == 8 * sizeof(Raw)) ? std::numeric_limits<Raw>::max()
                                                                           : (Raw(1) << (IntBits + FracBits - 1)) - 1;
    static constexpr Raw kMinRaw = -kMaxRaw - 1;

    constexpr Q() = default;
    static constexpr Q fromRaw(int64_t raw) { return Q(saturate(raw)); }
    static constexpr Q fromInt(int64_t v) { return fromRaw(v * int64_t(kOne)); }
    static constexpr Q fromDouble(double v)
    {
        const double scaled = v * double(kOne);
        if (!(scaled == scaled)) return Q(0); // NaN maps to zero
        if (scaled >= double(kMaxRaw)) return Q(kMaxRaw);
        if (scaled <= double(kMinRaw)) return Q(kMinRaw);
        return Q(Raw(scaled < 0 ? scaled - 0.5 : scaled + 0.5));
    }
    constexpr Raw raw() const { return raw_; }
    constexpr double toDouble() const { return double(raw_) / double(kOne); }
    // Integer part, rounding towards minus infinity (an arithmetic shift).
    constexpr Raw floor() const { return raw_ >> FracBits; }
    constexpr Raw frac() const { return raw_ & (kOne - 1); }

    constexpr Q operator+(Q o) const { return fromRaw(int64_t(raw_) + o.raw_); }
    constexpr Q operator-(Q o) const { return fromRaw(int64_t(raw_) - o.raw_); }
    constexpr Q operator-() const { return fromRaw(-int64_t(raw_)); }
    constexpr bool operator<(Q o) const { return raw_ < o.raw_; }
    constexpr bool operator==(const Q &o) const = default;

    // Product rounded to nearest; the intermediate is 64-bit (the static_assert bounds it).
    template <int I2, int F2> constexpr Q mul(Q<I2, F2> o) const
    {
        static_assert(IntBits + FracBits + I2 + F2 <= 63, "product needs more than 64 bits");
        using Wide = int64_t;
        const Wide p = Wide(raw_) * Wide(o.raw());
        if constexpr (F2 == 0)
            return fromRaw(int64_t(p));
        else {
            const Wide half = Wide(1) << (F2 - 1);
            return fromRaw(int64_t((p + half) >> F2));
        }
    }

private:
    constexpr explicit Q(Raw r) : raw_(r) {}
    static constexpr Raw saturate(int64_t v)
    {
        if (v > int64_t(kMaxRaw)) return kMaxRaw;
        if (v < int64_t(kMinRaw)) return kMinRaw;
        return Raw(v);
    }
    Raw raw_ = 0;
};

// Pixel coordinates and radii: ±32768 px with 1/65536 px resolution.
using Q16_16 = Q<16, 16>;
// Unit vectors (ray directions): ±2 with 1/16384 resolution.
using Q2_14 = Q<2, 14>;
// Luma samples after bilinear interpolation: 0..255 with 1/256 grey level.
using Q24_8 = Q<24, 8>;

} // namespace icacam::vision
