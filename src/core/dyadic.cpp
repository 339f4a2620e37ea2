// Exact binary numbers (core/dyadic.hpp). Magnitudes are little-endian arrays of 64-bit limbs,
// kept odd (trailing zero bits moved into the exponent) and without leading zero limbs, so
// every number has one representation. Products use 64 x 64 -> 128-bit multiplication
// (unsigned __int128: GCC, Clang, and Clang for WebAssembly).
#include "momentlab/core/dyadic.hpp"

#include "momentlab/core/approx.hpp"
#include "momentlab/core/rounding.hpp"
#include "power_of_two.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <memory>

namespace momentlab {
namespace {

using Limb = Dyadic::Limb;
__extension__ typedef unsigned __int128 Wide;

// Scratch limbs: on the stack when small.
class Scratch {
public:
    explicit Scratch(std::size_t n) : size_(n) {
        if (n > kStack) {
            big_ = std::make_unique<Limb[]>(n);
            p_ = big_.get();
        }
        std::fill(p_, p_ + n, Limb{0});
    }
    Limb* data() { return p_; }
    [[nodiscard]] std::size_t size() const { return size_; }

private:
    static constexpr std::size_t kStack = 24;
    Limb stack_[kStack];
    std::unique_ptr<Limb[]> big_;
    Limb* p_ = stack_;
    std::size_t size_;
};

// dst (zeroed, at least n + q + 1 limbs) += src << s, s = 64 q + r.
void shift_left_into(const Limb* src, std::size_t n, std::uint64_t s, Limb* dst) {
    const std::size_t q = static_cast<std::size_t>(s / 64);
    const unsigned r = static_cast<unsigned>(s % 64);
    for (std::size_t i = 0; i < n; ++i) {
        dst[i + q] |= src[i] << r;
        if (r != 0) dst[i + q + 1] |= src[i] >> (64 - r);
    }
}

// Compares magnitudes a (na limbs) and b (nb limbs), leading zero limbs allowed.
int compare_magnitudes(const Limb* a, std::size_t na, const Limb* b, std::size_t nb) {
    while (na > 0 && a[na - 1] == 0) --na;
    while (nb > 0 && b[nb - 1] == 0) --nb;
    if (na != nb) return na < nb ? -1 : 1;
    for (std::size_t i = na; i-- > 0;) {
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    }
    return 0;
}

// r = a + b (r has max(na, nb) + 1 limbs).
void add_into(const Limb* a, std::size_t na, const Limb* b, std::size_t nb, Limb* r) {
    if (na < nb) {
        std::swap(a, b);
        std::swap(na, nb);
    }
    Limb carry = 0;
    for (std::size_t i = 0; i < na; ++i) {
        const Wide t = static_cast<Wide>(a[i]) + (i < nb ? b[i] : 0) + carry;
        r[i] = static_cast<Limb>(t);
        carry = static_cast<Limb>(t >> 64);
    }
    r[na] = carry;
}

// r = a - b for a >= b (r has na limbs).
void subtract_into(const Limb* a, std::size_t na, const Limb* b, std::size_t nb, Limb* r) {
    Limb borrow = 0;
    for (std::size_t i = 0; i < na; ++i) {
        const Limb bi = i < nb ? b[i] : 0;
        const Limb d = a[i] - bi - borrow;
        borrow = (a[i] < bi || (a[i] == bi && borrow != 0)) ? 1 : 0;
        r[i] = d;
    }
    assert(borrow == 0);
}

}  // namespace

Limb* Dyadic::reserve(std::uint32_t n) {
    if (n <= capacity_) return data();
    if (capacity_ > kInline) delete[] heap_;
    heap_ = new Limb[n];
    capacity_ = n;
    return heap_;
}

Dyadic::Dyadic(double x) : inline_{} {
    assert(std::isfinite(x));
    if (x == 0.0) return;
    // From the bits: |x| = (2^52 + fraction) 2^(biased - 1075), or fraction 2^-1074 for a
    // denormal (biased exponent 0).
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);  // (std::bit_cast: not in the WebAssembly build's library)
    const auto biased = static_cast<std::int64_t>((bits >> 52) & 0x7FF);
    Limb m = bits & ((Limb{1} << 52) - 1);
    if (biased != 0) m |= Limb{1} << 52;
    const int tz = std::countr_zero(m);
    inline_[0] = m >> tz;
    size_ = 1;
    exponent_ = (biased != 0 ? biased - 1075 : -1074) + tz;
    sign_ = x > 0 ? 1 : -1;
}

Dyadic Dyadic::from_integer(std::int64_t v) {
    Dyadic d;
    if (v == 0) return d;
    d.inline_[0] = v < 0 ? Limb{0} - static_cast<Limb>(v) : static_cast<Limb>(v);
    d.size_ = 1;
    d.sign_ = v < 0 ? -1 : 1;
    d.normalize();
    return d;
}

Dyadic Dyadic::from_limbs(Sign sign, std::span<const Limb> magnitude, std::int64_t binary_exponent) {
    Dyadic d;
    if (magnitude.empty()) return d;
    assert(sign != Sign::Zero && magnitude.back() != 0 && (magnitude.front() & 1) != 0);
    Limb* p = d.reserve(static_cast<std::uint32_t>(magnitude.size()));
    std::copy(magnitude.begin(), magnitude.end(), p);
    d.size_ = static_cast<std::uint32_t>(magnitude.size());
    d.exponent_ = binary_exponent;
    d.sign_ = to_int(sign);
    return d;
}

void Dyadic::copy_from_heap(const Dyadic& other) {
    Limb* p = reserve(other.size_);
    std::copy(other.data(), other.data() + other.size_, p);
    size_ = other.size_;
}

Dyadic& Dyadic::operator=(const Dyadic& other) {
    if (this == &other) return *this;
    Limb* p = reserve(other.size_);
    std::copy(other.data(), other.data() + other.size_, p);
    size_ = other.size_;
    exponent_ = other.exponent_;
    sign_ = other.sign_;
    return *this;
}

Dyadic& Dyadic::operator=(Dyadic&& other) noexcept {
    if (this == &other) return *this;
    if (other.capacity_ > kInline) {
        if (capacity_ > kInline) delete[] heap_;
        heap_ = other.heap_;
        capacity_ = other.capacity_;
        other.capacity_ = kInline;
    } else {
        std::copy(other.inline_, other.inline_ + other.size_, data());
    }
    size_ = other.size_;
    exponent_ = other.exponent_;
    sign_ = other.sign_;
    other.size_ = 0;
    other.sign_ = 0;
    other.exponent_ = 0;
    return *this;
}

void Dyadic::normalize() {
    Limb* p = data();
    while (size_ > 0 && p[size_ - 1] == 0) --size_;
    if (size_ == 0) {
        sign_ = 0;
        exponent_ = 0;
        return;
    }
    std::uint32_t k = 0;
    while (p[k] == 0) ++k;
    const unsigned tz = static_cast<unsigned>(std::countr_zero(p[k]));
    if (k == 0 && tz == 0) return;
    const std::uint32_t n = size_ - k;
    for (std::uint32_t i = 0; i < n; ++i) {
        Limb v = p[i + k] >> tz;
        if (tz != 0 && i + k + 1 < size_) v |= p[i + k + 1] << (64 - tz);
        p[i] = v;
    }
    size_ = n;
    while (size_ > 0 && p[size_ - 1] == 0) --size_;
    exponent_ += 64 * static_cast<std::int64_t>(k) + tz;
}

Dyadic Dyadic::operator-() const {
    Dyadic d = *this;
    d.sign_ = -d.sign_;
    return d;
}

namespace {

// The magnitude of at most two limbs as one wide integer.
Wide wide_of(const Limb* p, std::uint32_t n) { return n == 1 ? Wide{p[0]} : (Wide{p[1]} << 64) | p[0]; }

// The number of bits of a magnitude of n limbs (its top limb non-zero).
std::uint64_t bit_length(const Limb* p, std::uint32_t n) {
    return 64 * static_cast<std::uint64_t>(n) - static_cast<std::uint64_t>(std::countl_zero(p[n - 1]));
}

}  // namespace

// a + b, or a - b when `subtract`.
Dyadic add_magnitudes(const Dyadic& a, const Dyadic& b, bool subtract) {
    const int sb = subtract ? -b.sign_ : b.sign_;
    if (b.size_ == 0) return a;
    if (a.size_ == 0) return subtract ? -b : b;
    // Align both to the smaller exponent: the other is shifted left.
    const std::int64_t e = std::min(a.exponent_, b.exponent_);
    const auto sa = static_cast<std::uint64_t>(a.exponent_ - e), sbits = static_cast<std::uint64_t>(b.exponent_ - e);
    // Both aligned magnitudes below 2^127 (the sums of products of a few doubles with nearby
    // exponents): one wide addition, no scratch limbs. The exponent gap is tested first, so
    // the shifts stay below 127 bits.
    if (a.size_ <= 2 && b.size_ <= 2 && sa < 127 && sbits < 127 && bit_length(a.data(), a.size_) + sa <= 127 &&
        bit_length(b.data(), b.size_) + sbits <= 127) {
        const Wide x = wide_of(a.data(), a.size_) << sa, y = wide_of(b.data(), b.size_) << sbits;
        Wide m = 0;
        int sign = a.sign_;
        if (a.sign_ == sb) {
            m = x + y;
        } else if (x != y) {
            m = x > y ? x - y : y - x;
            sign = x > y ? a.sign_ : sb;
        } else {
            return Dyadic();
        }
        const auto lo = static_cast<Limb>(m);
        const int tz = lo != 0 ? std::countr_zero(lo) : 64 + std::countr_zero(static_cast<Limb>(m >> 64));
        m >>= tz;
        Dyadic r;
        r.inline_[0] = static_cast<Limb>(m);
        r.inline_[1] = static_cast<Limb>(m >> 64);
        r.size_ = r.inline_[1] != 0 ? 2 : 1;
        r.exponent_ = e + tz;
        r.sign_ = sign;
        return r;
    }
    const std::size_t na = a.size_ + static_cast<std::size_t>(sa / 64) + 1;
    const std::size_t nb = b.size_ + static_cast<std::size_t>(sbits / 64) + 1;
    Scratch x(na), y(nb);
    shift_left_into(a.data(), a.size_, sa, x.data());
    shift_left_into(b.data(), b.size_, sbits, y.data());
    Dyadic r;
    r.exponent_ = e;
    if (a.sign_ == sb) {
        const std::size_t n = std::max(na, nb) + 1;
        Limb* p = r.reserve(static_cast<std::uint32_t>(n));
        add_into(x.data(), na, y.data(), nb, p);
        r.size_ = static_cast<std::uint32_t>(n);
        r.sign_ = a.sign_;
    } else {
        const int c = compare_magnitudes(x.data(), na, y.data(), nb);
        if (c == 0) return Dyadic();
        const bool a_larger = c > 0;
        const std::size_t n = a_larger ? na : nb;
        Limb* p = r.reserve(static_cast<std::uint32_t>(n));
        if (a_larger) {
            subtract_into(x.data(), na, y.data(), nb, p);
        } else {
            subtract_into(y.data(), nb, x.data(), na, p);
        }
        r.size_ = static_cast<std::uint32_t>(n);
        r.sign_ = a_larger ? a.sign_ : sb;
    }
    r.normalize();
    return r;
}

Dyadic operator+(const Dyadic& a, const Dyadic& b) { return add_magnitudes(a, b, false); }

Dyadic operator-(const Dyadic& a, const Dyadic& b) { return add_magnitudes(a, b, true); }

Dyadic operator*(const Dyadic& a, const Dyadic& b) {
    Dyadic r;
    if (a.size_ == 0 || b.size_ == 0) return r;
    if (a.size_ == 1 && b.size_ == 1) {  // two doubles' magnitudes, say: one wide product, odd
        const Wide t = static_cast<Wide>(a.data()[0]) * b.data()[0];
        r.inline_[0] = static_cast<Limb>(t);
        r.inline_[1] = static_cast<Limb>(t >> 64);
        r.size_ = r.inline_[1] != 0 ? 2 : 1;
        r.sign_ = a.sign_ * b.sign_;
        r.exponent_ = a.exponent_ + b.exponent_;
        return r;
    }
    const std::uint32_t n = a.size_ + b.size_;
    Limb* p = r.reserve(n);
    std::fill(p, p + n, Limb{0});
    const Limb* x = a.data();
    const Limb* y = b.data();
    for (std::uint32_t i = 0; i < a.size_; ++i) {
        Limb carry = 0;
        for (std::uint32_t j = 0; j < b.size_; ++j) {
            const Wide t = static_cast<Wide>(x[i]) * y[j] + p[i + j] + carry;
            p[i + j] = static_cast<Limb>(t);
            carry = static_cast<Limb>(t >> 64);
        }
        p[i + b.size_] = carry;
    }
    r.size_ = n;
    r.sign_ = a.sign_ * b.sign_;
    r.exponent_ = a.exponent_ + b.exponent_;
    r.normalize();  // odd times odd is odd: only a leading zero limb to strip
    return r;
}

int compare(const Dyadic& a, const Dyadic& b) {
    if (a.sign_ != b.sign_) return a.sign_ < b.sign_ ? -1 : 1;
    if (a.sign_ == 0) return 0;
    // Same sign: different magnitudes of two's exponent decide at once.
    const std::int64_t ea = a.exponent(), eb = b.exponent();
    if (ea != eb) return (ea < eb ? -1 : 1) * a.sign_;
    return to_int((a - b).sign());
}

Dyadic Dyadic::scaled(std::int64_t k) const {
    Dyadic d = *this;
    if (d.size_ != 0) d.exponent_ += k;
    return d;
}

double Dyadic::to_double_scaled(std::int64_t k) const {
    if (size_ == 0) return 0.0;
    const Limb* p = data();
    const Limb top = p[size_ - 1];
    const int lz = std::countl_zero(top);
    // The leading 64 bits (the rest only truncated: relative error below 2^-63), then one
    // rounding to 53 bits.
    Limb t = top << lz;
    if (lz != 0 && size_ >= 2) t |= p[size_ - 2] >> (64 - lz);
    // The bits below those 64 as one sticky bit: t has 11 bits beyond the 53 kept, so rounding t
    // is then rounding the whole magnitude (correctly, to nearest with ties to even).
    if (size_ >= 3 || (size_ == 2 && (lz == 0 || (p[0] << lz) != 0))) t |= 1;
    const std::int64_t bitlen = 64 * static_cast<std::int64_t>(size_) - lz;
    const std::int64_t scale = exponent_ + bitlen - 64 - k;
    // A result below the normal range would be rounded twice (to 53 bits, then to the
    // subnormal's fewer): rounded once from the exact value there.
    if (scale + 63 < -1022 && scale + 64 >= -1080) return nearest_double(scaled(-k), Dyadic(1.0));
    const double v = detail::times_power_of_two(static_cast<double>(t), scale);
    return sign_ < 0 ? -v : v;
}

Approx approximate(const Dyadic& x) {
    const double v = x.to_double();
    return x.fits_double() ? Approx::exact(v) : Approx::within(v, std::fabs(v) * 0x1p-53 + 0x1p-1074);
}

std::string Dyadic::to_string() const {
    if (size_ == 0) return "0";
    static const char* digits = "0123456789abcdef";
    std::string hex;
    for (std::uint32_t i = size_; i-- > 0;) {
        for (int s = 60; s >= 0; s -= 4) hex.push_back(digits[(data()[i] >> s) & 0xF]);
    }
    hex.erase(0, std::min(hex.find_first_not_of('0'), hex.size() - 1));
    return std::string(sign_ < 0 ? "-" : "") + "0x" + hex + "p" + std::to_string(exponent_);
}

}  // namespace momentlab
