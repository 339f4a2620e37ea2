#pragma once

// Scaling of the assembly layer's linear programs (linear_program.cpp): powers of two for the
// columns, the rows and the right-hand side, which change no sign; the scaled program in the form
// both simplex methods take, with the margin column t of the strict columns; the double program
// that guides them; and the way back to the program's own variables and rows.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

#include "exact_simplex.hpp"
#include "interval.hpp"
#include "linear_program.hpp"
#include "simplex.hpp"

namespace momentlab::assembly_detail {

// The power of two that brings |x| into [0.5, 1).
inline int scale_of(double largest) {
    if (!(largest > 0.0) || !std::isfinite(largest)) return 0;
    int e = 0;
    (void)std::frexp(largest, &e);
    return -e;
}

inline Interval scaled(const Interval& a, int k) {
    if (k == 0 || is_exact_zero(a)) return a;
    Interval r{std::ldexp(a.lo, k), std::ldexp(a.hi, k)};
    // ldexp is exact unless the result leaves the normal range: then widen.
    const auto normal = [](double x) { return x == 0.0 ? false : std::isnormal(x); };
    if (!normal(r.lo) || !normal(r.hi)) r = {next_down(r.lo), next_up(r.hi)};
    return r;
}

// Powers of two for the columns, the rows and the right-hand side (choices only: they change no
// sign): columns first, each largest entry into [0.5, 1), then the rows, then b.
struct Scaling {
    std::vector<int> column, row;
    int rhs = 0;
};

inline Scaling scaling_of(const Program<Interval>& p) {
    Scaling s;
    s.column.assign(p.columns.size(), 0);
    s.row.assign(p.rows, 0);
    for (std::size_t j = 0; j < p.columns.size(); ++j) {
        double largest = 0.0;
        for (const SparseEntry<Interval>& e : p.columns[j]) largest = std::max(largest, std::abs(e.value.mid()));
        s.column[j] = scale_of(largest);
    }
    std::vector<double> row_largest(p.rows, 0.0);
    for (std::size_t j = 0; j < p.columns.size(); ++j) {
        for (const SparseEntry<Interval>& e : p.columns[j]) {
            row_largest[e.index] = std::max(row_largest[e.index], std::ldexp(std::abs(e.value.mid()), s.column[j]));
        }
    }
    double rhs_largest = 0.0;
    for (std::uint32_t i = 0; i < p.rows; ++i) {
        s.row[i] = scale_of(row_largest[i]);
        rhs_largest = std::max(rhs_largest, std::ldexp(std::abs(p.rhs[i].mid()), s.row[i]));
    }
    s.rhs = scale_of(rhs_largest);
    return s;
}

// The scaled program in the form both simplex methods take: the program's columns (mu_j for the
// strict ones), then t when some column is strict: its column the sum of the strict columns.
template <class T>
struct Scaled {
    std::uint32_t rows = 0;
    std::vector<SparseColumn<T>> columns;
    std::vector<bool> free;
    std::vector<T> rhs;
    std::optional<std::uint32_t> t;
};

template <class T>
T scale_value(const T& v, int k) {
    if constexpr (std::is_same_v<T, Interval>) {
        return scaled(v, k);
    } else {
        return times_power_of_two(v, k);
    }
}

inline bool is_zero_value(const Interval& v) { return is_exact_zero(v); }
inline bool is_zero_value(const Rational& v) { return v == 0; }

template <class T>
Scaled<T> scale(const Program<T>& p, const Scaling& s, bool with_margin) {
    Scaled<T> out;
    out.rows = p.rows;
    out.free = p.free;
    out.columns.resize(p.columns.size());
    std::vector<T> t_column(p.rows, T(0.0));
    bool any_strict = false;
    for (std::size_t j = 0; j < p.columns.size(); ++j) {
        for (const SparseEntry<T>& e : p.columns[j]) {
            T v = scale_value(e.value, s.row[e.index] + s.column[j]);
            if (with_margin && p.strict[j]) t_column[e.index] += v;
            out.columns[j].push_back({e.index, std::move(v)});
        }
        any_strict = any_strict || (with_margin && p.strict[j]);
    }
    for (std::uint32_t i = 0; i < p.rows; ++i) out.rhs.push_back(scale_value(p.rhs[i], s.row[i] + s.rhs));
    if (any_strict) {
        SparseColumn<T> column;
        for (std::uint32_t i = 0; i < p.rows; ++i) {
            if (!is_zero_value(t_column[i])) column.push_back({i, t_column[i]});
        }
        out.t = static_cast<std::uint32_t>(out.columns.size());
        out.columns.push_back(std::move(column));
        out.free.push_back(false);
    }
    return out;
}

// The t bound: a margin of at most 1 (scaled units) is asked.
constexpr double kMarginCap = 1.0;

inline DoubleProgram guidance(const Scaled<Interval>& s, const std::vector<double>& cost) {
    DoubleProgram d;
    d.rows = s.rows;
    d.columns.resize(s.columns.size());
    for (std::size_t j = 0; j < s.columns.size(); ++j) {
        for (const SparseEntry<Interval>& e : s.columns[j]) d.columns[j].push_back({e.index, e.value.mid()});
        d.lower.push_back(s.free[j] ? -kInfinity : 0.0);
        d.upper.push_back(s.t && j == *s.t ? kMarginCap : kInfinity);
    }
    d.cost = cost;
    for (const Interval& b : s.rhs) d.rhs.push_back(b.mid());
    return d;
}

inline std::vector<double> unscale_point(const std::vector<double>& x, const Scaled<Interval>& s, const Scaling& sc,
                                  const Program<Interval>& p) {
    std::vector<double> point(p.columns.size());
    const double t = s.t ? x[*s.t] : 0.0;
    for (std::size_t j = 0; j < p.columns.size(); ++j) {
        const double v = (s.t && p.strict[j]) ? x[j] + t : x[j];
        point[j] = std::ldexp(v, sc.column[j] - sc.rhs);
    }
    return point;
}

inline std::vector<double> unscale_duals(const std::vector<double>& y, const Scaling& sc) {
    std::vector<double> out(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) out[i] = std::ldexp(y[i], sc.row[i]);
    return out;
}

inline ExactProgram exact_program(const Scaled<Rational>& s, const std::vector<Rational>& cost) {
    ExactProgram e;
    e.rows = s.rows;
    e.columns = s.columns;
    e.free = s.free;
    e.upper.assign(s.columns.size(), std::nullopt);
    if (s.t) e.upper[*s.t] = Rational(1);
    e.cost = cost;
    e.rhs = s.rhs;
    return e;
}

inline bool homogeneous(const Scaled<Interval>& s) {
    return std::all_of(s.rhs.begin(), s.rhs.end(), [](const Interval& b) { return is_exact_zero(b); });
}

}  // namespace momentlab::assembly_detail
