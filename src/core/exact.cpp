// Exact vectors (core/exact.hpp). Each kind keeps or makes a certified approximation (the
// vector scaled by a power of two, rounded, with a bound on each coordinate's error), which the
// predicates' filter adaptor (core/predicates.hpp) reads; where it cannot decide, the exact
// stages of exact_predicates.cpp take over. The predicates' homogeneity (each is linear in each
// operand) is what lets every operand carry its own power of two.
#include "momentlab/core/exact.hpp"

#include "power_of_two.hpp"

#include <bit>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <utility>

namespace momentlab {
namespace {

constexpr double kU = kUnitRoundoff;
constexpr double kUnderflow = 0x1p-1000;  // an absolute floor of the approximations' error bounds
constexpr double kInf = std::numeric_limits<double>::infinity();

// e with m = f 2^e, f in [0.5, 1), for finite m > 0: what std::frexp gives, read from the bits
// of a normal number (std::frexp is a library call, and the approximations call it for every
// exact sign).
int binary_exponent(double m) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &m, sizeof bits);  // (std::bit_cast: not in the WebAssembly build's library)
    const auto biased = static_cast<int>((bits >> 52) & 0x7FF);
    if (biased != 0) return biased - 1022;
    int e = 0;
    std::frexp(m, &e);  // a denormal
    return e;
}

// v 2^k, coordinate by coordinate.
Vec3 times_power_of_two(const Vec3& v, int k) {
    return Vec3(detail::times_power_of_two(v.x(), k), detail::times_power_of_two(v.y(), k),
                detail::times_power_of_two(v.z(), k));
}

// v scaled by a power of two so that its largest coordinate lies in [1, 2).
Vec3 scaled_by_power_of_two(const Vec3& v) {
    const double m = v.cwiseAbs().maxCoeff();
    if (m == 0.0 || !std::isfinite(m)) return v;
    return times_power_of_two(v, 1 - binary_exponent(m));
}

// Stein's binary gcd: shifts and subtractions, no division (a facet of integer generators is
// divided by the gcd of its coordinates in every construction).
std::uint64_t binary_gcd(std::uint64_t a, std::uint64_t b) {
    if (a == 0) return b;
    if (b == 0) return a;
    const int shift = std::countr_zero(a | b);
    a >>= std::countr_zero(a);
    do {
        b >>= std::countr_zero(b);
        if (a > b) std::swap(a, b);
        b -= a;
    } while (b != 0);
    return a << shift;
}

// For display: integer vectors are divided by the gcd of their coordinates (exact), others are
// left as they are unless far from 1, then scaled by a power of two. Neither changes the
// direction.
Vec3 readable(const Vec3& v) {
    // |v_i| < 2^53 first, so that the conversion to a 64-bit integer is defined and exact for
    // integers (a conversion instead of std::floor, which is a call without SSE4.1).
    const double limit = 0x1p53;
    bool integral = true;
    for (int i = 0; i < 3 && integral; ++i) {
        integral = std::fabs(v[i]) < limit && static_cast<double>(static_cast<long long>(v[i])) == v[i];
    }
    if (integral) {
        std::uint64_t g = 0;
        for (int i = 0; i < 3; ++i) g = binary_gcd(g, static_cast<std::uint64_t>(std::llabs(static_cast<long long>(v[i]))));
        if (g > 1) return v / static_cast<double>(g);
        return v;
    }
    const double m = v.cwiseAbs().maxCoeff();
    return m > 0x1p-64 && m < 0x1p64 ? v : scaled_by_power_of_two(v);
}

double norm1(const Vec3& v) { return std::fabs(v.x()) + std::fabs(v.y()) + std::fabs(v.z()); }

// An approximation whose coordinates err by at most err_i: the filters' magnitudes for it
// (Approx::within, coordinate by coordinate).
ExactVector::Approximation with_error(const Vec3& a, const Vec3& err) {
    ExactVector::Approximation out{a, err, {}};
    for (int i = 0; i < 3; ++i) out.magnitude[i] = Approx::within(a[i], err[i]).magnitude;
    return out;
}

// The error of a coordinate rounded to nearest with relative error below 2^-52 (below 2^-51 of
// the rounded value), and an absolute floor for what falls below the normal range.
Vec3 rounding_error(const Vec3& a, double floor) {
    return Vec3(0x1p-51 * std::fabs(a.x()) + floor, 0x1p-51 * std::fabs(a.y()) + floor, 0x1p-51 * std::fabs(a.z()) + floor);
}

ExactVector::Approximation input_approximation(const Vec3& v) {
    const double m = v.cwiseAbs().maxCoeff();
    // Doubles are their own approximation; they are scaled by a power of two only where their
    // products could leave the normal range (a sign is the same at every positive scale).
    if (m >= 0x1p-64 && m <= 0x1p64) return {v, Vec3::Zero(), v.cwiseAbs()};
    if (m == 0.0) return {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    const int e = binary_exponent(m);
    Vec3 a, err = Vec3::Zero();
    for (int i = 0; i < 3; ++i) {
        a[i] = detail::times_power_of_two(v[i], 1 - e);
        if (detail::times_power_of_two(a[i], e - 1) != v[i]) err[i] = kUnderflow;  // a tiny coordinate lost bits
    }
    return with_error(a, err);
}

ExactVector::Approximation exact_approximation(const Exact3& v) {
    std::int64_t top = std::numeric_limits<std::int64_t>::min();
    for (const Dyadic& x : v) {
        if (!x.is_zero()) top = std::max(top, x.exponent());
    }
    if (top == std::numeric_limits<std::int64_t>::min()) return {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    // Each coordinate rounded with relative error below 2^-52 on a scale where the largest is
    // in [1, 2); coordinates below the double range flush to 0 (error below 2^-1022).
    const Vec3 a(v[0].to_double_scaled(top), v[1].to_double_scaled(top), v[2].to_double_scaled(top));
    return with_error(a, rounding_error(a, 0x1p-1021));
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Dyadic vectors.

Exact2 exact(const Vec2& v) { return {Dyadic(v.x()), Dyadic(v.y())}; }

Exact3 exact(const Vec3& v) { return {Dyadic(v.x()), Dyadic(v.y()), Dyadic(v.z())}; }

ExactMatrix exact(const Mat3& m) {
    return {exact(Vec3(m.row(0).transpose())), exact(Vec3(m.row(1).transpose())), exact(Vec3(m.row(2).transpose()))};
}

Dyadic dot(const Exact3& a, const Exact3& b) { return Dot{}(a, b); }

Exact3 cross(const Exact3& a, const Exact3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Dyadic det(const Exact3& a, const Exact3& b, const Exact3& c) { return Det{}(a, b, c); }

Dyadic cross2(const Exact2& a, const Exact2& b) { return a[0] * b[1] - a[1] * b[0]; }

Exact3 operator+(const Exact3& a, const Exact3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

Exact3 operator-(const Exact3& a, const Exact3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Exact3 operator-(const Exact3& a) { return {-a[0], -a[1], -a[2]}; }

Exact3 operator*(const Dyadic& s, const Exact3& a) { return {s * a[0], s * a[1], s * a[2]}; }

Exact3 operator*(const ExactMatrix& m, const Exact3& a) { return {dot(m[0], a), dot(m[1], a), dot(m[2], a)}; }

Exact2 operator+(const Exact2& a, const Exact2& b) { return {a[0] + b[0], a[1] + b[1]}; }

Exact2 operator-(const Exact2& a, const Exact2& b) { return {a[0] - b[0], a[1] - b[1]}; }

Exact2 operator*(const Dyadic& s, const Exact2& a) { return {s * a[0], s * a[1]}; }

bool is_zero(const Exact3& a) { return a[0].is_zero() && a[1].is_zero() && a[2].is_zero(); }

Vec3 to_double(const Exact3& a) { return Vec3(a[0].to_double(), a[1].to_double(), a[2].to_double()); }

Vec2 to_double(const Exact2& a) { return Vec2(a[0].to_double(), a[1].to_double()); }

Exact3 wrench_through(const Exact2& p, const Exact2& d) { return {d[0], d[1], cross2(p, d)}; }

// ---------------------------------------------------------------------------------------------
// ExactVector.

ExactVector::ExactVector(const Vec3& u, const Vec3& v, int sign)
    : u_(u), v_(v), sign_(sign >= 0 ? 1 : -1), kind_(Kind::Cross) {
    // The plain product is exact for small integers; if it overflows (or underflows to zero),
    // scaling the factors first by powers of two keeps it finite for any finite input. (The sum
    // of the magnitudes is NaN or infinite when a coordinate is: the test catches both.)
    Vec3 raw = u.cross(v);
    const double s = std::fabs(raw.x()) + std::fabs(raw.y()) + std::fabs(raw.z());
    if (!(s > 0x1p-900 && s < 0x1p900)) raw = scaled_by_power_of_two(u).cross(scaled_by_power_of_two(v));
    value_ = readable(raw);
    if (sign_ < 0) value_ = -value_;
}

ExactVector ExactVector::cross(const ExactVector& u, const ExactVector& v, int sign) {
    if (u.kind_ == Kind::Input && v.kind_ == Kind::Input) return cross(u.value_, v.value_, sign);
    Exact3 c = momentlab::cross(u.exact(), v.exact());
    return from_exact(sign >= 0 ? c : -c);
}

ExactVector ExactVector::from_exact(const Exact3& e) {
    if (e[0].fits_double() && e[1].fits_double() && e[2].fits_double()) return input(to_double(e));
    return computed(e);
}

ExactVector ExactVector::wrench(const Vec2& p, const Vec2& d) {
    Exact3 e = wrench_through(momentlab::exact(p), momentlab::exact(d));
    if (e[2].fits_double()) return input(Vec3(d.x(), d.y(), e[2].to_double()));
    // The value as computed() gives it; outside the readable range, computed() itself.
    const Vec3 plain = to_double(e);
    const double m = plain.cwiseAbs().maxCoeff();
    if (!(plain.allFinite() && m > 0x1p-64 && m < 0x1p64)) return computed(std::move(e));
    // (p.y, -p.x, 1) x (d.y, -d.x, 0) = (d.x, d.y, p.x d.y - p.y d.x): negations, products by
    // 0 and 1, all exact.
    ExactVector out;
    out.kind_ = Kind::Cross;
    out.u_ = Vec3(p.y(), -p.x(), 1.0);
    out.v_ = Vec3(d.y(), -d.x(), 0.0);
    out.value_ = readable(plain);
    out.keep_approximation_shift(plain);
    return out;
}

namespace {

// n words in one shared allocation (with its count): an array of a few fixed sizes, seen
// through an aliasing pointer to its first word. (std::make_shared<T[]>(n) would do it for any
// n, but the C++ library of the WebAssembly build predates it.)
template <std::size_t N>
std::shared_ptr<Dyadic::Limb> shared_array() {
    auto owner = std::make_shared<std::array<Dyadic::Limb, N>>();
    Dyadic::Limb* first = owner->data();
    return {std::move(owner), first};
}

std::shared_ptr<Dyadic::Limb> shared_words(std::size_t n) {
    if (n <= 8) return shared_array<8>();
    if (n <= 12) return shared_array<12>();
    if (n <= 16) return shared_array<16>();
    if (n <= 24) return shared_array<24>();
    return std::shared_ptr<Dyadic::Limb>(new Dyadic::Limb[n], std::default_delete<Dyadic::Limb[]>());
}

}  // namespace

ExactVector ExactVector::computed(Exact3 e) {
    ExactVector out;
    out.kind_ = Kind::Computed;
    const Approximation approximation = exact_approximation(e);
    // The value on its own scale when that is readable, else on the approximation's.
    const Vec3 plain = to_double(e);
    out.value_ = plain.allFinite() && plain.cwiseAbs().maxCoeff() > 0x1p-64 && plain.cwiseAbs().maxCoeff() < 0x1p64
                     ? readable(plain)
                     : approximation.approx;
    // The approximation is kept in the object itself (u_ and v_, unused by this kind):
    // predicates read it without following the pointer, which on a cone of 10^5 constructed
    // generators is a cache miss per predicate.
    out.u_ = approximation.approx;
    out.v_ = approximation.magnitude;
    // Packed: words 0-2 the binary exponents, 3-5 each coordinate's limb count times 4 plus its
    // sign + 1, then the limbs. A coordinate of a friction edge or of a ray of A has two or
    // three limbs, so the block is about half of three Dyadic objects (six inline limbs each).
    std::size_t limbs = 0;
    for (const Dyadic& x : e) limbs += x.limbs().size();
    std::shared_ptr<Dyadic::Limb> block = shared_words(6 + limbs);
    Dyadic::Limb* w = block.get();
    std::size_t at = 6;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto l = e[i].limbs();
        w[i] = static_cast<Dyadic::Limb>(e[i].binary_exponent());
        w[3 + i] = (static_cast<Dyadic::Limb>(l.size()) << 2) | static_cast<Dyadic::Limb>(to_int(e[i].sign()) + 1);
        std::copy(l.begin(), l.end(), w + at);
        at += l.size();
    }
    out.computed_ = std::move(block);
    return out;
}

Exact3 ExactVector::exact() const {
    switch (kind_) {
        case Kind::Input: return momentlab::exact(value_);
        case Kind::Cross: {
            // A wrench (wrench()): (a, b, 1) x (c, e, 0) = (-e, c, a e - b c), two products.
            const Exact3 c =
                u_.z() == 1.0 && v_.z() == 0.0
                    ? Exact3{Dyadic(-v_.y()), Dyadic(v_.x()),
                             Dyadic(u_.x()) * Dyadic(v_.y()) - Dyadic(u_.y()) * Dyadic(v_.x())}
                    : momentlab::cross(momentlab::exact(u_), momentlab::exact(v_));
            return sign_ > 0 ? c : -c;
        }
        case Kind::Computed: {
            // Stored coordinate k (from_) starts after the limbs of those before it.
            const Dyadic::Limb* block = computed_.get();
            std::array<std::size_t, 3> start{6, 0, 0};
            start[1] = start[0] + static_cast<std::size_t>(block[3] >> 2);
            start[2] = start[1] + static_cast<std::size_t>(block[4] >> 2);
            Exact3 out;
            for (std::size_t i = 0; i < 3; ++i) {
                const int from = from_[i];
                const auto k = static_cast<std::size_t>(std::abs(from) - 1);
                const Sign stored = static_cast<Sign>(static_cast<int>(block[3 + k] & 3) - 1);
                const std::size_t size = static_cast<std::size_t>(block[3 + k] >> 2);
                out[i] = Dyadic::from_limbs((from < 0) == (sign_ > 0) ? -stored : stored, {block + start[k], size},
                                            static_cast<std::int64_t>(block[k]));
            }
            return out;
        }
    }
    return {};
}

namespace {

// The certified approximation of sign (p x q) for stored p, q is its product in doubles times
// 2^scale: |fl(fl(a) - fl(b)) - (a - b)| <= (2u + u^2)(|a| + |b|) + 2^-1074 per coordinate (the
// last term for products below the normal range), scaled so that the largest |a| + |b| lies in
// [1, 2). No scale when that largest is outside [2^-900, 2^900].
struct CrossScale {
    int scale;
    Vec3 sums;  // |a| + |b| of each coordinate, in doubles
};

std::optional<CrossScale> cross_scale(const Vec3& p, const Vec3& q) {
    const Vec3 b(std::fabs(p.y() * q.z()) + std::fabs(p.z() * q.y()), std::fabs(p.z() * q.x()) + std::fabs(p.x() * q.z()),
                 std::fabs(p.x() * q.y()) + std::fabs(p.y() * q.x()));
    const double m = b.maxCoeff();
    if (!(m >= 0x1p-900 && m <= 0x1p900)) return std::nullopt;
    return CrossScale{1 - binary_exponent(m), b};
}

// The absolute error, on the scale 2^scale, of products below the normal range: 2^(scale - 1072)
// (twice 2^-1074, doubled for the rounding of |a| + |b|), never below 2^-1000 (so never a
// subnormal number, which costs the processor about a hundred cycles per operation).
double underflow_at(int scale) { return scale <= 72 ? kUnderflow : detail::times_power_of_two(1.0, scale - 1072); }

ExactVector::Approximation cross_approximation(const Vec3& p, const Vec3& q, int sign) {
    const std::optional<CrossScale> s = cross_scale(p, q);
    if (!s) return {Vec3::Zero(), Vec3::Constant(kInf), Vec3::Constant(kInf)};
    // (2u + u^2)(|a| + |b|) <= 2^-51 fl(|a| + |b|): the sum in doubles errs by at most 2u.
    return with_error(times_power_of_two(p.cross(q) * static_cast<double>(sign), s->scale),
                      times_power_of_two(s->sums, s->scale - 51) + Vec3::Constant(underflow_at(s->scale)));
}

}  // namespace

void ExactVector::keep_approximation_shift(const Vec3& base) {
    // base is the wrench's exact value rounded coordinate by coordinate (relative error below
    // 2^-52). The shift is the power of two that takes value_ to base on the scale where the
    // largest |a| + |b| is in [1, 2), if one does exactly (value_ is base scaled for reading,
    // unless it was divided by an integer gcd).
    const std::optional<CrossScale> scale = cross_scale(u_, v_);
    if (!scale) return;
    const Vec3 target = times_power_of_two(base, scale->scale);
    const double mv = value_.cwiseAbs().maxCoeff(), mt = target.cwiseAbs().maxCoeff();
    if (mv == 0.0 || mt == 0.0) {
        if (mv == 0.0 && mt == 0.0) approx_shift_ = 0;
        return;
    }
    const int shift = binary_exponent(mt) - binary_exponent(mv);
    if (times_power_of_two(value_, shift) == target) approx_shift_ = static_cast<std::int16_t>(shift);
}

ExactVector::Approximation ExactVector::approximation() const {
    switch (kind_) {
        case Kind::Input: return input_approximation(value_);
        case Kind::Cross:
            if (approx_shift_ != kNoShift) {
                // Each coordinate rounded from the exact one (relative error below 2^-52), on a
                // scale that takes it below 2^65: a coordinate below the normal range erred by
                // at most 2^-1074 before that scaling.
                const Vec3 a = times_power_of_two(value_, approx_shift_);
                return with_error(a, rounding_error(a, 0x1p-990));
            }
            return cross_approximation(u_, v_, sign_);
        case Kind::Computed: {
            // u_ the approximation, v_ its magnitudes (exact_approximation).
            const Vec3 a = sign_ > 0 ? u_ : Vec3(-u_);
            return {a, rounding_error(a, 0x1p-1021), v_};
        }
    }
    return {};
}

bool ExactVector::same_construction(const ExactVector& other) const {
    if (kind_ != other.kind_) return false;
    switch (kind_) {
        case Kind::Input: return value_ == other.value_ || value_ == -other.value_;
        case Kind::Cross: return u_ == other.u_ && v_ == other.v_;
        case Kind::Computed: return computed_ == other.computed_ && from_ == other.from_;
    }
    return false;
}

ExactVector::Filter ExactVector::filter() const {
    const Approximation a = approximation();
    // |(v/2^k - approx) . w| <= sum_i err_i |w_i| <= (sum_i err_i) max |w_i|.
    const double err = a.err.sum();
    if (!(err < kInf)) return {a.approx, kInf};
    return {a.approx, (err + 3.01 * kU * norm1(a.approx)) * (1 + 0x1p-40)};
}

Sign ExactVector::dot_sign(const Vec3& w) const { return momentlab::dot_sign(*this, ExactVector::input(w)); }

Sign ExactVector::dot_sign(const ExactVector& other) const { return momentlab::dot_sign(*this, other); }

ExactVector ExactVector::negated() const {
    ExactVector e = *this;
    e.value_ = -value_;
    e.sign_ = static_cast<signed char>(-sign_);
    return e;
}

ExactVector ExactVector::signed_permuted(const Mat3& p) const {
    if (kind_ == Kind::Computed) {
        // Coordinates moved and negated: no arithmetic, and the stored numbers are shared (only
        // the map from them, from_, changes); the approximation moves with them.
        ExactVector e = *this;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                if (p(i, j) == 0.0) continue;
                assert(p(i, j) == 1.0 || p(i, j) == -1.0);
                const signed char f = from_[static_cast<std::size_t>(j)];
                e.from_[static_cast<std::size_t>(i)] = static_cast<signed char>(p(i, j) < 0 ? -f : f);
            }
        }
        e.value_ = p * value_;
        e.u_ = p * u_;
        e.v_ = p.cwiseAbs() * v_;  // the magnitudes move with their coordinates
        return e;
    }
    ExactVector e = *this;
    e.value_ = p * value_;
    if (kind_ == Kind::Cross) {
        // P (u x v) = det(P) (P u x P v) for orthogonal P.
        e.u_ = p * u_;
        e.v_ = p * v_;
        e.sign_ = static_cast<signed char>(sign_ * (p.determinant() > 0 ? 1 : -1));
    }
    return e;
}

ExactVector ExactVector::transformed(const ExactMatrix& m) const { return from_exact(m * exact()); }

bool ExactVector::force(Vec2& point, Vec2& direction, int& sign) const {
    if (kind_ != Kind::Cross || u_.z() != 1.0 || v_.z() != 0.0) return false;
    // (a, b, 1) x (c, e, 0) = (-e, c, a e - b c): the force (-e, c) through (-b, a).
    point = Vec2(-u_.y(), u_.x());
    direction = Vec2(-v_.y(), v_.x());
    sign = sign_;
    return true;
}

ExactVector::Approximation approximation(const Exact3& b) { return exact_approximation(b); }

}  // namespace momentlab
