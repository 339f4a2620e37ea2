// Rank 3, pointed, seen in a chart: when a direction d has d . g > 0 for every generator
// (exactly), the cone is pointed and its extreme rays are the vertices of the convex hull of
// the points g / (d . g) of the plane d . x = 1, where the orientation of three points is the
// sign of det(a, b, c). Andrew's monotone chain finds them after sorting the points by two
// coordinates of that plane, both exact: X, where X(a) < X(b) iff det(e, a, b) > 0 for an e
// with e . d = 0 exactly, then Y along e (b = a + t e in the chart iff a x b is t times a
// positive multiple of a x e). The frame (X, Y) turns the way det does, so the chain comes out
// counter-clockwise. d is a floating-point guess (the mean of the generators' directions); the
// sort starts from floating-point keys and an insertion pass repairs it. Every sign here is
// exact: taken from the rounded chart points where their certified error bounds decide it
// (chart_point), else from the exact predicate on the generators. Nothing is decided here when
// the guess fails (some d . g <= 0), when the repair runs long, or when the hull is flat (rank
// 2): the pivot path then builds the cone. Parallel generators are one point of the chart; the
// one given first stands for them. A cone of a few generators costs a few floating-point
// operations per generator and no allocation beyond its own representation.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

#include "cone_build.hpp"
#include "cone_parts.hpp"
#include "scratch.hpp"

// Private to the geometry layer: hidden from the shared library's interface.
namespace momentlab {
namespace [[gnu::visibility("hidden")]] geometry_detail {

namespace {

template <class G>
Sign dot_with(const G& a, const Vec3& d) {
    if constexpr (std::is_same_v<G, Vec3>) {
        return dot_sign(a, d);
    } else {
        return a.dot_sign(d);
    }
}

template <class G>
G as_generator(const Vec3& v) {
    if constexpr (std::is_same_v<G, Vec3>) {
        return v;
    } else {
        return in(v);
    }
}

// Up to this many generators (their items and the chain fit in a Scratch on the stack); the
// pivot path, tuned for millions, takes bigger cones.
constexpr std::size_t kChartLimit = 128;

struct ChartItem {
    double x, y;  // the point's chart coordinates, rounded: keys for the sort
    double err;   // |x - true x| and |y - true y| are at most err (+inf: decide exactly)
    int index;
    bool same;  // after the exact pass: parallel to the item before it
};

// A certified approximation of a generator: the generator is a positive multiple of a + t with
// |t_i| <= err_i (its chart point is that of a + t: the chart is blind to positive scaling).
inline void certified(const Vec3& v, Vec3& a, Vec3& err) {
    a = v;
    err = Vec3::Zero();
}
inline void certified(const ExactVector& v, Vec3& a, Vec3& err) {
    const ExactVector::Approximation p = v.approximation();
    const bool known = p.err.allFinite();
    a = known ? p.approx : v.value();  // without a bound, the rounded value for the keys
    err = known ? p.err : Vec3::Constant(std::numeric_limits<double>::infinity());
}

// The chart point (f . v, e . v) / (d . v) of a generator, rounded, with a bound on its error,
// and whether d . v > 0 is certified. d, e and f are integer vectors below 2^44 (exact); the frame
// holds |d| and max(|e|, |f|) coordinate by coordinate (one bound serves both coordinates of the
// point). With a = the approximation and t its error, c . a evaluated in doubles errs by at most
// 3u sum |c_i a_i| (u = 2^-53; taken as 4u), and c . t is at most sum |c_i| t_i; below the
// normal range each product errs by at most 2^-1075 more (the absolute 2^-1060). For X = f . v
// and w = d . v with errors E_X, E_w, and w >= w_lo = w^ - E_w > 0,
//     X^/w^ - X/w = (dX - x dw) / w^,   |x| <= (|X^| + E_X) / w_lo,
// and x^ = X^ * fl(1/w^) adds at most 3u |x^|. Each bound is rounded up by the factor 1 + 2^-40
// (a few dozen roundings of 1 + u each) and, where it is a result, by an absolute 2^-1000
// (results below the normal range). tests/geometry/test_cone_laws.cpp, ChartFilters..., fails
// when the bounds are taken 64 times smaller.
struct ChartFrame {
    Vec3 d, e, f;
    Vec3 abs_d, abs_ef;  // |d|, max(|e|, |f|)
};
template <bool kWithError>
ChartItem chart_point(const Vec3& a, const Vec3& t, const ChartFrame& frame, int index, bool& in_front) {
    constexpr double kU = 0x1p-53;
    const Vec3 aa = a.cwiseAbs();
    const double w = frame.d.dot(a), big_x = frame.f.dot(a), big_y = frame.e.dot(a);
    double e_w = 4 * kU * frame.abs_d.dot(aa);
    double e_xy = 4 * kU * frame.abs_ef.dot(aa);  // both E_X and E_Y
    if constexpr (kWithError) {
        e_w += frame.abs_d.dot(t);
        e_xy += frame.abs_ef.dot(t);
    }
    e_w = e_w * (1 + 0x1p-40) + 0x1p-1060;
    e_xy = e_xy * (1 + 0x1p-40) + 0x1p-1060;
    const double w_lo = w - e_w;
    const double r = 1 / w;
    ChartItem item{big_x * r, big_y * r, std::numeric_limits<double>::infinity(), index, false};
    in_front = w_lo > 0;  // false for NaN (an infinite error)
    if (in_front) {
        const double big = std::max(std::fabs(big_x), std::fabs(big_y));
        const double err = (3 * kU * std::max(std::fabs(item.x), std::fabs(item.y)) + r * (e_xy + (big + e_xy) * (e_w / w_lo))) *
                               (1 + 0x1p-40) +
                           0x1p-1000;
        if (err < std::numeric_limits<double>::infinity()) item.err = err;  // not NaN
    }
    return item;
}

}  // namespace

template <class G>
bool pointed_by_chart(std::span<const G> g, bool facets, Parts& out) {
    const std::size_t n = g.size();
    if (n < 3 || n > kChartLimit || !ConeBuilder::use_chart()) return false;
    // d: the mean of the generators' directions, rounded to integers below 2^20 (it moves by
    // about 2^-20 rad), so that e below is an integer vector and the determinants that tie
    // (exactly zero, frequent for integer generators) are decided in integers rather than
    // expansions.
    auto rounded = [](const Vec3& mean, Vec3& to) {
        const double top = mean.cwiseAbs().maxCoeff();
        if (!(top > 0) || !std::isfinite(top)) return false;
        const Vec3 scaled = mean * (0x1p20 / top);
        if (!scaled.allFinite()) return false;  // top subnormal: 2^20 / top overflows
        // (|scaled_i| <= 2^20: the conversion is exact and needs no call to lround.)
        for (int i = 0; i < 3; ++i) to[i] = static_cast<double>(static_cast<std::int64_t>(scaled[i] + (scaled[i] < 0 ? -0.5 : 0.5)));
        return true;
    };
    // The chart of d: e = u x d for u = 2 e_k + e_k+1, k the axis where d is smallest (e . d = 0
    // exactly: e's coordinates are integers below 3 * 2^20; u is never parallel to d, whose
    // coordinate k is its smallest where u's is its largest, so e is not small beside d; and a
    // u off the axes leaves no two corners of an axis-aligned integer cone at one X, a tie the
    // exact predicates would decide), f = e x d (exact: integers below 2^44), and each
    // generator's point (f . v, e . v) / (d . v) with its error bound. False unless d . v > 0 for
    // every generator (certified by the bound, or else exactly).
    Vec3 d;
    ChartFrame frame;
    Scratch scratch;
    ScratchVector<ChartItem> items(&scratch);
    items.reserve(n);
    auto in_front = [&] {
        int k = 0;
        for (int i = 1; i < 3; ++i) {
            if (std::fabs(d[i]) < std::fabs(d[k])) k = i;
        }
        frame.d = d;
        frame.e = (2 * Vec3::Unit(k) + Vec3::Unit((k + 1) % 3)).cross(d);
        frame.f = frame.e.cross(d);
        frame.abs_d = frame.d.cwiseAbs();
        frame.abs_ef = frame.e.cwiseAbs().cwiseMax(frame.f.cwiseAbs());
        items.clear();
        for (std::size_t i = 0; i < n; ++i) {
            Vec3 a, t;
            certified(g[i], a, t);
            bool front = false;
            items.push_back(chart_point<!std::is_same_v<G, Vec3>>(a, t, frame, static_cast<int>(i), front));
            if (!front && dot_with(g[i], d) != Sign::Positive) return false;
        }
        return true;
    };
    auto direction = [](const G& v) -> Vec3 { return approx(v) / approx(v).cwiseAbs().sum(); };
    Vec3 mean = Vec3::Zero();
    for (const G& v : g) mean += direction(v);
    if (!rounded(mean, d)) return false;
    if (!in_front()) {
        // The mean need not have every generator in front of it (wrenches whose torques
        // outweigh their forces): a few perceptron passes move it towards each one behind it.
        for (int pass = 0; pass < 4; ++pass) {
            bool moved = false;
            for (const G& v : g) {
                const Vec3 u = direction(v);
                if (!(mean.dot(u) > 0x1p-40 * mean.cwiseAbs().sum())) {
                    mean += u;
                    moved = true;
                }
            }
            if (!moved) break;
        }
        if (!rounded(mean, d) || !in_front()) return false;
    }
    // Keys that overflowed or vanished (coordinates near 2^+-1000) would not order: the sort
    // needs a strict weak order, and such cones are rare enough for the pivot path.
    for (const ChartItem& item : items) {
        if (!std::isfinite(item.x) || !std::isfinite(item.y)) return false;
    }
    const G eg = as_generator<G>(frame.e);
    std::sort(items.begin(), items.end(),
              [](const ChartItem& a, const ChartItem& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    // before(a, b): Positive if a comes first; Zero for parallel generators. det(e, a, b) is
    // (d . a)(d . b) |e|^2 (x_b - x_a) (the chart's coordinates): the keys decide where they
    // differ by more than their errors.
    auto before = [&](const ChartItem& ia, const ChartItem& ib) {
        const double gap = ib.x - ia.x, tolerance = (ia.err + ib.err) * (1 + 0x1p-40);
        if (gap > tolerance) return Sign::Positive;
        if (-gap > tolerance) return Sign::Negative;
        const G& a = g[static_cast<std::size_t>(ia.index)];
        const G& b = g[static_cast<std::size_t>(ib.index)];
        const Sign s = det_sign(eg, a, b);
        if (s != Sign::Zero) return s;
        // The same X: along e. a is not parallel to e (d . a > 0 = d . e).
        for (int axis = 0; axis < 3; ++axis) {
            const Sign ae = cross_component_sign(a, eg, axis);
            if (ae != Sign::Zero) return cross_component_sign(a, b, axis) * ae;
        }
        return Sign::Zero;  // unreachable
    };
    std::size_t moves = 0;
    const std::size_t budget = 4 * n + 16;
    for (std::size_t i = 1; i < n; ++i) {
        for (std::size_t j = i; j > 0;) {
            const Sign c = before(items[j - 1], items[j]);
            if (++moves > budget) return false;
            if (c != Sign::Negative) {
                // Parallel generators are one point of the chart, and stay next to each other.
                items[j].same = c == Sign::Zero;
                break;
            }
            std::swap(items[j], items[j - 1]);
            --j;
        }
    }
    // One item per point: of parallel generators the one given first, as every
    // cycle starts at the extreme generator given first (pointed_from_cycle).
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (items[i].same && m > 0) {
            items[m - 1].index = std::min(items[m - 1].index, items[i].index);
        } else {
            items[m++] = items[i];
        }
    }
    // Andrew's monotone chain: the lower chain left to right, then the upper one back, on
    // positions in `items`. det(a, b, c) is (d . a)(d . b)(d . c) |f|^2 times the orientation of
    // the three chart points, which the rounded points decide where it exceeds what their
    // errors and its own evaluation can move it (Shewchuk's bound (3u + 16u^2)(|l| + |r|) for
    // the points as rounded, then the first and second order terms of their errors).
    // First a bound for every triple at once: with the points in a box of sides W_x, W_y and
    // errors below E, |l| + |r| <= 2 W_x W_y, |b_x| + |b_y| <= W_x + W_y (rounding is monotone),
    // and eb, ec <= 2E.
    double x_lo = items[0].x, x_hi = x_lo, y_lo = items[0].y, y_hi = y_lo, most = 0;
    for (std::size_t i = 0; i < m; ++i) {
        x_lo = std::min(x_lo, items[i].x);
        x_hi = std::max(x_hi, items[i].x);
        y_lo = std::min(y_lo, items[i].y);
        y_hi = std::max(y_hi, items[i].y);
        most = std::max(most, items[i].err);
    }
    const double w_x = x_hi - x_lo, w_y = y_hi - y_lo;
    const double every = (0x1.0000000002p-51 * 2 * w_x * w_y + (4 * most * (w_x + w_y) + 8 * most * most)) * (1 + 0x1p-40) + 0x1p-1000;
    ScratchVector<int> hull(2 * m, 0, &scratch);
    std::size_t h = 0;
    // The triple's own bound, else the exact sign (rare: kept out of the chain's loops).
    auto turns_left_slowly = [&](const ChartItem& a, const ChartItem& b, const ChartItem& c) __attribute__((noinline)) {
        const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
        const double l = bx * cy, r = by * cx, value = l - r;
        const double eb = a.err + b.err, ec = a.err + c.err;
        const double bound = 0x1.0000000002p-51 * (std::fabs(l) + std::fabs(r)) +
                             (ec * (std::fabs(bx) + std::fabs(by)) + eb * (std::fabs(cx) + std::fabs(cy)) + 2 * eb * ec) *
                                 (1 + 0x1p-40) +
                             0x1p-1000;
        if (std::fabs(value) > bound) return value > 0;  // never for a NaN bound
        return det_sign(g[static_cast<std::size_t>(a.index)], g[static_cast<std::size_t>(b.index)],
                        g[static_cast<std::size_t>(c.index)]) == Sign::Positive;
    };
    auto turns_left = [&](int pa, int pb, int pc) {
        const ChartItem& a = items[static_cast<std::size_t>(pa)];
        const ChartItem& b = items[static_cast<std::size_t>(pb)];
        const ChartItem& c = items[static_cast<std::size_t>(pc)];
        const double value = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (std::fabs(value) > every) return value > 0;  // never for a NaN bound
        return turns_left_slowly(a, b, c);
    };
    for (std::size_t i = 0; i < m; ++i) {
        while (h >= 2 && !turns_left(hull[h - 2], hull[h - 1], static_cast<int>(i))) --h;
        hull[h++] = static_cast<int>(i);
    }
    for (std::size_t i = m - 1, lower = h + 1; i > 0; --i) {
        while (h >= lower && !turns_left(hull[h - 2], hull[h - 1], static_cast<int>(i - 1))) --h;
        hull[h++] = static_cast<int>(i - 1);
    }
    for (std::size_t i = 0; i < h; ++i) hull[i] = items[static_cast<std::size_t>(hull[i])].index;
    --h;  // the first point again
    if (h < 3) return false;
    ++ConeBuilder::stats().by_chart;
    pointed_from_cycle(g, std::span<const int>(hull.data(), h), facets, out);
    return true;
}

template bool pointed_by_chart<Vec3>(std::span<const Vec3>, bool, Parts&);
template bool pointed_by_chart<ExactVector>(std::span<const ExactVector>, bool, Parts&);

}  // namespace geometry_detail
}  // namespace momentlab
