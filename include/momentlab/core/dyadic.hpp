#pragma once

/// \file
/// Exact binary numbers: an integer of any size times a power of two.
///
/// Every double is a Dyadic, and sums, differences and products of Dyadics are Dyadics, so
/// every polynomial in the input doubles (a torque p x n, a friction edge n + mu t, the inertia
/// I + m |c|^2, a determinant of such) is computed exactly, with no overflow, underflow or
/// rounding, and no division (there is none in momentlab's exact paths). This is momentlab's
/// own arithmetic: the library needs no GMP, and the same code runs natively and in
/// WebAssembly (docs/robustness.md, "Exact numbers"). Magnitudes of up to six 64-bit limbs
/// live inside the object; larger ones on the heap.

#include <bit>
#include <cstdint>
#include <span>
#include <string>

#include "momentlab/core/sign.hpp"

namespace momentlab {

/// An exact number m * 2^e with an integer m of any size (sign and magnitude) and e an integer.
class Dyadic {
public:
    using Limb = std::uint64_t;

    /// Zero.
    Dyadic() noexcept : inline_{} {}
    /// The double x, exactly. Precondition: x is finite (asserted in debug builds).
    explicit Dyadic(double x);
    /// The integer v, exactly.
    static Dyadic from_integer(std::int64_t v);

    // Copies, moves and destruction inline for the magnitudes held in the object (the exact
    // paths copy Dyadic numbers by the hundred thousand), out of line for those on the heap.
    Dyadic(const Dyadic& other) : exponent_(other.exponent_), sign_(other.sign_), inline_{} {
        if (other.size_ > kInline) {
            copy_from_heap(other);
            return;
        }
        const Limb* from = other.data();
        for (std::uint32_t i = 0; i < other.size_; ++i) inline_[i] = from[i];
        size_ = other.size_;
    }
    Dyadic(Dyadic&& other) noexcept
        : exponent_(other.exponent_), size_(other.size_), capacity_(other.capacity_), sign_(other.sign_) {
        if (other.capacity_ > kInline) {
            heap_ = other.heap_;
            other.capacity_ = kInline;
        } else {
            for (std::uint32_t i = 0; i < kInline; ++i) inline_[i] = other.inline_[i];
        }
        other.size_ = 0;
        other.sign_ = 0;
        other.exponent_ = 0;
    }
    Dyadic& operator=(const Dyadic& other);
    Dyadic& operator=(Dyadic&& other) noexcept;
    ~Dyadic() {
        if (capacity_ > kInline) delete[] heap_;
    }

    /// The exact sign.
    [[nodiscard]] Sign sign() const { return sign_of_int(sign_); }
    [[nodiscard]] bool is_zero() const { return size_ == 0; }
    /// Exactly 1 (told from the canonical form: an odd magnitude 1 at exponent 0).
    [[nodiscard]] bool is_one() const { return size_ == 1 && sign_ > 0 && exponent_ == 0 && data()[0] == 1; }

    [[nodiscard]] Dyadic operator-() const;
    friend Dyadic operator+(const Dyadic& a, const Dyadic& b);
    friend Dyadic operator-(const Dyadic& a, const Dyadic& b);
    friend Dyadic operator*(const Dyadic& a, const Dyadic& b);
    Dyadic& operator+=(const Dyadic& b) { return *this = *this + b; }
    Dyadic& operator-=(const Dyadic& b) { return *this = *this - b; }
    Dyadic& operator*=(const Dyadic& b) { return *this = *this * b; }

    /// -1, 0 or +1 as a < b, a == b, a > b (exact).
    friend int compare(const Dyadic& a, const Dyadic& b);
    friend bool operator==(const Dyadic& a, const Dyadic& b) { return compare(a, b) == 0; }
    friend bool operator<(const Dyadic& a, const Dyadic& b) { return compare(a, b) < 0; }
    friend bool operator<=(const Dyadic& a, const Dyadic& b) { return compare(a, b) <= 0; }
    friend bool operator>(const Dyadic& a, const Dyadic& b) { return compare(a, b) > 0; }
    friend bool operator>=(const Dyadic& a, const Dyadic& b) { return compare(a, b) >= 0; }

    /// This number times 2^k (exact).
    [[nodiscard]] Dyadic scaled(std::int64_t k) const;

    /// floor(log2 |x|); meaningless for zero.
    [[nodiscard]] std::int64_t exponent() const {
        if (size_ == 0) return 0;
        return exponent_ + 64 * static_cast<std::int64_t>(size_ - 1) + 63 - std::countl_zero(data()[size_ - 1]);
    }
    /// x * 2^-k correctly rounded to a double (to nearest, ties to even; 0 or infinite outside
    /// the double range).
    [[nodiscard]] double to_double_scaled(std::int64_t k) const;
    /// x correctly rounded to a double (0 or infinite outside the range).
    [[nodiscard]] double to_double() const { return to_double_scaled(0); }
    /// True when x is exactly a finite double (then to_double() is exact).
    [[nodiscard]] bool fits_double() const {
        if (size_ == 0) return true;
        if (size_ > 1) return false;
        // (one odd limb: its bits are the significand's, at most 53, and the exponent in range)
        return std::bit_width(data()[0]) <= 53 && exponent_ >= -1074 && exponent() <= 1023;
    }

    /// The representation: |x| = sum of limbs()[i] 2^(64 i) times 2^binary_exponent(), the
    /// magnitude odd (no trailing zero bits) and without leading zero limbs; no limbs for 0.
    [[nodiscard]] std::span<const Limb> limbs() const { return {data(), size_}; }
    [[nodiscard]] std::int64_t binary_exponent() const { return exponent_; }
    /// The number with that representation: sign times the magnitude (limbs as limbs() gives
    /// them: odd, no leading zero limb; none for zero) times 2^binary_exponent.
    static Dyadic from_limbs(Sign sign, std::span<const Limb> magnitude, std::int64_t binary_exponent);
    /// "-0x1.8p+3"-style exact text (hexadecimal magnitude and binary exponent), for messages.
    [[nodiscard]] std::string to_string() const;

private:
    static constexpr std::uint32_t kInline = 6;  // limbs in the object (docs/robustness.md)

    [[nodiscard]] Limb* data() { return capacity_ > kInline ? heap_ : inline_; }
    [[nodiscard]] const Limb* data() const { return capacity_ > kInline ? heap_ : inline_; }
    // Room for n limbs (contents not kept); size_ untouched.
    Limb* reserve(std::uint32_t n);
    // The copy constructor's path for a magnitude beyond kInline limbs.
    void copy_from_heap(const Dyadic& other);
    // Strips leading zero limbs and trailing zero bits (into the exponent); zero becomes 0.
    void normalize();
    friend Dyadic add_magnitudes(const Dyadic& a, const Dyadic& b, bool subtract);

    std::int64_t exponent_ = 0;
    std::uint32_t size_ = 0;
    std::uint32_t capacity_ = kInline;
    std::int32_t sign_ = 0;
    union {
        Limb inline_[kInline];
        Limb* heap_;
    };
};

}  // namespace momentlab
