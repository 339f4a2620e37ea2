#include "linear_program.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "exact_simplex.hpp"
#include "scaling.hpp"

namespace momentlab::assembly_detail {
namespace {

// The basis's columns as intervals (artificials: sign * e_i).
std::vector<SparseColumn<Interval>> basis_columns(const Scaled<Interval>& s, const Basis& basis) {
    const auto n = static_cast<std::uint32_t>(s.columns.size());
    std::vector<SparseColumn<Interval>> columns(s.rows);
    for (std::uint32_t p = 0; p < s.rows; ++p) {
        const std::uint32_t j = basis.basic[p];
        if (j < n) {
            columns[p] = s.columns[j];
        } else {
            columns[p].push_back({j - n, Interval(static_cast<double>(basis.artificial_sign[j - n]))});
        }
    }
    return columns;
}

std::vector<SparseColumn<double>> middles_of(const std::vector<SparseColumn<Interval>>& columns) {
    std::vector<SparseColumn<double>> middles(columns.size());
    for (std::size_t p = 0; p < columns.size(); ++p) {
        for (const SparseEntry<Interval>& e : columns[p]) middles[p].push_back({e.index, e.value.mid()});
    }
    return middles;
}

// The basis factored in interval arithmetic along the pivots a double factorization of its
// midpoints chooses. The widths grow with the elimination (the wrapping effect), so that on a
// few hundred rows a pivot's interval often holds 0: then none.
std::optional<SparseLu<Interval>> interval_factor(const Scaled<Interval>& s, const Basis& basis) {
    const std::vector<SparseColumn<Interval>> columns = basis_columns(s, basis);
    const std::vector<SparseColumn<double>> middles = middles_of(columns);
    SparseLu<double> guide;
    if (!guide.factor(middles)) return std::nullopt;
    SparseLu<Interval> lu;
    if (!lu.factor(columns, guide.pivots())) return std::nullopt;
    return lu;
}

Interval magnitude(const Interval& a) { return Interval(std::max(std::abs(a.lo), std::abs(a.hi))); }

// The largest basis solved by preconditioning (its m x m approximate inverse is stored).
constexpr std::uint32_t kPreconditionedRows = 2000;

Interval dot(const std::vector<Interval>& y, const SparseColumn<Interval>& column) {
    Interval s(0.0);
    for (const SparseEntry<Interval>& e : column) s += y[e.index] * e.value;
    return s;
}

// Enclosures of every variable of the basis's point (the nonbasic ones at their bounds), or none
// when an artificial is in the basis other than exactly 0 or the basis cannot be solved: by
// interval elimination, or `preconditioned` (enclose_solution).
std::optional<std::vector<Interval>> enclose_point(const Scaled<Interval>& s, const SimplexResult& r, bool preconditioned) {
    const auto n = static_cast<std::uint32_t>(s.columns.size());
    std::optional<SparseLu<Interval>> lu;
    if (!preconditioned) {
        lu = interval_factor(s, r.basis);
        if (!lu) return std::nullopt;
    }
    std::vector<Interval> values(n, Interval(0.0));
    std::vector<Interval> rhs = s.rhs;
    for (std::uint32_t j = 0; j < n; ++j) {
        if (r.basis.place[j] == Place::AtUpper) {  // only t has an upper bound
            values[j] = Interval(kMarginCap);
            for (const SparseEntry<Interval>& e : s.columns[j]) rhs[e.index] -= e.value * values[j];
        }
    }
    std::vector<Interval> xb;
    if (lu) {
        xb = lu->solve(std::move(rhs));
    } else if (auto solved = enclose_solution(basis_columns(s, r.basis), rhs)) {
        xb = std::move(*solved);
    } else {
        return std::nullopt;
    }
    for (std::uint32_t p = 0; p < s.rows; ++p) {
        const std::uint32_t j = r.basis.basic[p];
        if (j >= n) {
            if (!is_exact_zero(xb[p])) return std::nullopt;
        } else {
            values[j] = xb[p];
        }
    }
    return values;
}

// y = B^-T c_B in intervals, with c the costs (per column of s; artificials' cost given apart).
std::optional<std::vector<Interval>> enclose_duals(const Scaled<Interval>& s, const Basis& basis,
                                                   const std::vector<double>& cost, double artificial_cost) {
    const auto n = static_cast<std::uint32_t>(s.columns.size());
    const std::optional<SparseLu<Interval>> lu = interval_factor(s, basis);
    if (!lu) return std::nullopt;
    std::vector<Interval> c(s.rows);
    for (std::uint32_t p = 0; p < s.rows; ++p) {
        const std::uint32_t j = basis.basic[p];
        c[p] = Interval(j < n ? cost[j] : artificial_cost);
    }
    return lu->solve_transposed(std::move(c));
}

// A Farkas vector with room: max tau over y . A_j + tau + sigma_j = 0 (sigma_j >= 0) for every
// column, y . b = 1, tau in [0, 1], in doubles; a y with tau > 0 has y . A_j < 0 for every column
// with room to spare, so its rounding is checked in intervals (each y_i a double, exactly). Only
// for programs without free columns (y . A_j = 0 cannot be checked on a rounded y). This is the
// certificate when the basis's own y is degenerate: columns with y . A_j exactly 0, whose
// intervals hold 0.
std::optional<std::vector<double>> farkas_with_room(const Scaled<Interval>& s) {
    const auto n = static_cast<std::uint32_t>(s.columns.size());
    for (std::uint32_t j = 0; j < n; ++j) {
        if (s.free[j]) return std::nullopt;
    }
    const std::uint32_t skip = s.t ? *s.t : n;
    DoubleProgram d;
    d.rows = 0;
    std::vector<std::uint32_t> row_of(n, 0);
    for (std::uint32_t j = 0; j < n; ++j) {
        if (j != skip) row_of[j] = d.rows++;
    }
    const std::uint32_t normalisation = d.rows++;
    d.rhs.assign(d.rows, 0.0);
    d.rhs[normalisation] = 1.0;
    d.columns.resize(s.rows + 1);
    for (std::uint32_t j = 0; j < n; ++j) {  // y_i: column i holds A_ij in row j
        if (j == skip) continue;
        for (const SparseEntry<Interval>& e : s.columns[j]) d.columns[e.index].push_back({row_of[j], e.value.mid()});
    }
    for (std::uint32_t i = 0; i < s.rows; ++i) {
        if (!is_exact_zero(s.rhs[i])) d.columns[i].push_back({normalisation, s.rhs[i].mid()});
        std::sort(d.columns[i].begin(), d.columns[i].end(), [](const auto& a, const auto& b) { return a.index < b.index; });
    }
    for (std::uint32_t j = 0; j < n; ++j) {  // tau, then the slacks
        if (j != skip) d.columns[s.rows].push_back({row_of[j], 1.0});
    }
    for (std::uint32_t j = 0; j < n; ++j) {
        if (j != skip) d.columns.push_back({{row_of[j], 1.0}});
    }
    d.lower.assign(d.columns.size(), 0.0);
    d.upper.assign(d.columns.size(), kInfinity);
    for (std::uint32_t i = 0; i < s.rows; ++i) d.lower[i] = -kInfinity;
    d.upper[s.rows] = 1.0;
    d.cost.assign(d.columns.size(), 0.0);
    d.cost[s.rows] = -1.0;
    const SimplexResult r = simplex(d);
    if (r.status != SimplexStatus::Optimal || !(r.x[s.rows] > 1e-9)) return std::nullopt;
    std::vector<Interval> y;
    for (std::uint32_t i = 0; i < s.rows; ++i) y.emplace_back(r.x[i]);
    SparseColumn<Interval> b;
    for (std::uint32_t i = 0; i < s.rows; ++i) b.push_back({i, s.rhs[i]});
    if (!dot(y, b).positive()) return std::nullopt;
    for (std::uint32_t j = 0; j < n; ++j) {
        if (j != skip && !dot(y, s.columns[j]).negative()) return std::nullopt;
    }
    std::vector<double> out(r.x.begin(), r.x.begin() + s.rows);
    return out;
}

// The rows whose dual is not negligible, when they are fewer than all (a guess: the decision on
// them is exact).
std::optional<std::vector<std::uint32_t>> dual_support(const std::vector<double>& y, std::uint32_t rows) {
    double largest = 0.0;
    for (double v : y) largest = std::max(largest, std::abs(v));
    std::vector<std::uint32_t> kept;
    for (std::uint32_t i = 0; i < rows; ++i) {
        if (std::abs(y[i]) > 1e-9 * largest) kept.push_back(i);
    }
    if (kept.empty() || kept.size() == rows) return std::nullopt;
    return kept;
}

// The program on the given rows only, without the columns left empty.
template <class T>
Program<T> restricted(const Program<T>& p, const std::vector<std::uint32_t>& rows) {
    std::vector<std::int64_t> index(p.rows, -1);
    for (std::size_t k = 0; k < rows.size(); ++k) index[rows[k]] = static_cast<std::int64_t>(k);
    Program<T> out;
    out.rows = static_cast<std::uint32_t>(rows.size());
    for (std::uint32_t i : rows) out.rhs.push_back(p.rhs[i]);
    for (std::size_t j = 0; j < p.columns.size(); ++j) {
        SparseColumn<T> column;
        for (const SparseEntry<T>& e : p.columns[j]) {
            if (index[e.index] >= 0) column.push_back({static_cast<std::uint32_t>(index[e.index]), e.value});
        }
        if (!column.empty()) out.add(std::move(column), p.free[j], p.strict[j]);
    }
    return out;
}

}  // namespace

// Without interval elimination: R the inverse of B's midpoint in doubles (its columns
// solved with a double LU), x~ = R mid(b); when alpha = ||I - R B|| < 1 (infinity norm, in
// interval arithmetic), every such B is regular and ||x - x~|| <= ||R (b - B x~)|| / (1 - alpha),
// since B^-1 = (R B)^-1 R and ||(R B)^-1|| <= 1 / (1 - alpha) (Rump, "Verification methods:
// rigorous results using floating-point arithmetic", Acta Numerica 19, 2010, section 10).
// O(m^2 + m nnz(B)) work and m^2 doubles.
std::optional<std::vector<Interval>> enclose_solution(const std::vector<SparseColumn<Interval>>& columns,
                                                      const std::vector<Interval>& rhs) {
    const auto m = static_cast<std::uint32_t>(columns.size());
    if (m == 0 || m > kPreconditionedRows) return std::nullopt;
    SparseLu<double> lu;
    if (!lu.factor(middles_of(columns))) return std::nullopt;
    std::vector<double> r(static_cast<std::size_t>(m) * m);  // r[p m + i]: row p (a position), column i (a row of B)
    for (std::uint32_t i = 0; i < m; ++i) {
        std::vector<double> unit(m, 0.0);
        unit[i] = 1.0;
        const std::vector<double> column = lu.solve(std::move(unit));
        for (std::uint32_t p = 0; p < m; ++p) r[static_cast<std::size_t>(p) * m + i] = column[p];
    }
    const auto at = [&](std::uint32_t p, std::uint32_t i) { return Interval(r[static_cast<std::size_t>(p) * m + i]); };
    std::vector<Interval> row_sum(m, Interval(0.0));  // of |I - R B|
    for (std::uint32_t q = 0; q < m; ++q) {
        for (std::uint32_t p = 0; p < m; ++p) {
            Interval c(p == q ? 1.0 : 0.0);
            for (const SparseEntry<Interval>& e : columns[q]) c = c - at(p, e.index) * e.value;
            row_sum[p] = row_sum[p] + magnitude(c);
        }
    }
    double alpha = 0.0;  // (a NaN anywhere fails these comparisons: then none)
    for (const Interval& v : row_sum) {
        if (!(v.hi < 1.0)) return std::nullopt;
        alpha = std::max(alpha, v.hi);
    }
    std::vector<double> middle(m);
    for (std::uint32_t i = 0; i < m; ++i) middle[i] = rhs[i].mid();
    const std::vector<double> x = lu.solve(std::move(middle));
    if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) return std::nullopt;
    std::vector<Interval> residual = rhs;  // b - B x~
    for (std::uint32_t q = 0; q < m; ++q) {
        for (const SparseEntry<Interval>& e : columns[q]) residual[e.index] = residual[e.index] - e.value * Interval(x[q]);
    }
    double beta = 0.0;  // ||R (b - B x~)||
    for (std::uint32_t p = 0; p < m; ++p) {
        Interval z(0.0);
        for (std::uint32_t i = 0; i < m; ++i) z = z + at(p, i) * residual[i];
        const double size = magnitude(z).hi;
        if (!std::isfinite(size)) return std::nullopt;
        beta = std::max(beta, size);
    }
    const Interval bound = Interval(beta) / (Interval(1.0) - Interval(alpha));
    if (!std::isfinite(bound.hi)) return std::nullopt;
    std::vector<Interval> out;
    out.reserve(m);
    for (std::uint32_t q = 0; q < m; ++q) out.push_back(Interval(x[q]) + Interval(-bound.hi, bound.hi));
    return out;
}

LpCounts& lp_counts() {
    thread_local LpCounts counts;
    return counts;
}

FeasibilityAnswer decide(const Program<Interval>& enclosures, const ExactBuilder& exact) {
    const Scaling sc = scaling_of(enclosures);
    const Scaled<Interval> s = scale(enclosures, sc, true);
    const auto n = static_cast<std::uint32_t>(s.columns.size());
    std::vector<double> cost(n, 0.0);
    if (s.t) cost[*s.t] = -1.0;
    const SimplexResult r = simplex(guidance(s, cost));
    FeasibilityAnswer answer;
    if (r.status == SimplexStatus::Infeasible) {
        // Farkas: phase 1's y (costs 1 on the artificials): y . A_j <= 0 at x_j >= 0 (exactly 0
        // for the basic columns, by construction), y . b > 0.
        if (const auto y = enclose_duals(s, r.basis, std::vector<double>(n, 0.0), 1.0)) {
            bool holds = dot(*y, [&] {
                             SparseColumn<Interval> b;
                             for (std::uint32_t i = 0; i < s.rows; ++i) b.push_back({i, s.rhs[i]});
                             return b;
                         }()).positive();
            for (std::uint32_t j = 0; j < n && holds; ++j) {
                if (r.basis.place[j] == Place::Basic || (s.t && j == *s.t)) continue;
                const Interval ya = dot(*y, s.columns[j]);
                holds = s.free[j] ? is_exact_zero(ya) : ya.nonpositive();
            }
            if (holds) {
                ++lp_counts().certified;
                std::vector<double> mid;
                for (const Interval& v : *y) mid.push_back(v.mid());
                answer.status = Feasibility::Infeasible;
                answer.farkas = unscale_duals(mid, sc);
                return answer;
            }
        }
        if (const auto y = farkas_with_room(s)) {
            ++lp_counts().certified;
            answer.status = Feasibility::Infeasible;
            answer.farkas = unscale_duals(*y, sc);
            return answer;
        }
    } else if (r.status == SimplexStatus::Optimal) {
        const bool margin = !s.t || r.x[*s.t] > 1e-12;
        for (const bool preconditioned : {false, true}) {
            if (!margin) break;
            // A point: every strict variable > 0, every other bounded one >= 0.
            if (const auto v = enclose_point(s, r, preconditioned)) {
                const Interval t = s.t ? (*v)[*s.t] : Interval(0.0);
                bool holds = true;
                for (std::uint32_t j = 0; j < enclosures.columns.size() && holds; ++j) {
                    if (enclosures.free[j]) continue;
                    holds = s.t && enclosures.strict[j] ? ((*v)[j] + t).positive() : (*v)[j].nonnegative();
                }
                if (holds) {
                    ++lp_counts().certified;
                    std::vector<double> mid;
                    for (const Interval& x : *v) mid.push_back(x.mid());
                    answer.status = Feasibility::StrictlyFeasible;
                    answer.point = unscale_point(mid, s, sc, enclosures);
                    return answer;
                }
            }
        }
        if (!margin && homogeneous(s)) {
            // max t <= y . b = 0 when every reduced cost has its sign (x = 0 is the point).
            if (const auto y = enclose_duals(s, r.basis, cost, 0.0)) {
                bool holds = true;
                for (std::uint32_t j = 0; j < n && holds; ++j) {
                    if (r.basis.place[j] == Place::Basic) continue;
                    const Interval d = Interval(cost[j]) - dot(*y, s.columns[j]);
                    holds = s.free[j] ? is_exact_zero(d) : d.nonnegative();
                }
                if (holds) {
                    ++lp_counts().certified;
                    answer.status = Feasibility::Feasible;
                    answer.point.assign(enclosures.columns.size(), 0.0);
                    return answer;
                }
            }
            // The duals are degenerate (reduced costs exactly 0 that the intervals cannot sign):
            // the rows the duals use, alone, are a relaxation; without a strict point there is
            // none here either (a strict point here is one there), and its certificate is often
            // not degenerate.
            if (const auto rows = dual_support(r.y, s.rows)) {
                const FeasibilityAnswer relaxed =
                    decide(restricted(enclosures, *rows), [&] { return restricted(exact(), *rows); });
                if (relaxed.status == Feasibility::Feasible) {
                    answer.status = Feasibility::Feasible;
                    answer.point.assign(enclosures.columns.size(), 0.0);
                    answer.exact_path = relaxed.exact_path;
                    return answer;
                }
            }
        }
    }
    // The exact path, from the double simplex's basis.
    ++lp_counts().exact;
    answer.exact_path = true;
    const Scaled<Rational> e = scale(exact(), sc, true);
    std::vector<Rational> exact_cost(n, Rational(0));
    if (e.t) exact_cost[*e.t] = -1;
    const bool usable = r.status != SimplexStatus::Stalled && r.basis.basic.size() == s.rows;
    const ExactOutcome o = exact_simplex(exact_program(e, exact_cost), usable ? &r.basis : nullptr);
    if (o.status == SimplexStatus::Infeasible) {
        std::vector<double> y;
        for (const Rational& v : o.y) y.push_back(approximate(v));
        answer.status = Feasibility::Infeasible;
        answer.farkas = unscale_duals(y, sc);
        return answer;
    }
    std::vector<double> x;
    for (const Rational& v : o.x) x.push_back(approximate(v));
    answer.status = (!e.t || o.x[*e.t] > 0) ? Feasibility::StrictlyFeasible : Feasibility::Feasible;
    answer.point = unscale_point(x, s, sc, enclosures);
    return answer;
}

Optimum maximize(const Program<Interval>& enclosures, const ExactBuilder& exact,
                 const std::vector<std::pair<std::uint32_t, int>>& objective) {
    const Scaling sc = scaling_of(enclosures);
    const Scaled<Interval> s = scale(enclosures, sc, false);
    const auto n = static_cast<std::uint32_t>(s.columns.size());
    std::vector<double> cost(n, 0.0);
    std::vector<Rational> exact_cost(n, Rational(0));
    for (const auto& [j, c] : objective) {
        cost[j] = -std::ldexp(static_cast<double>(c), sc.column[j]);  // min -c . x in the scaled variables
        exact_cost[j] = -times_power_of_two(Rational(c), sc.column[j]);
    }
    const SimplexResult r = simplex(guidance(s, cost));
    ++lp_counts().exact;
    const Scaled<Rational> e = scale(exact(), sc, false);
    const bool usable = r.status != SimplexStatus::Stalled && r.basis.basic.size() == s.rows;
    const ExactOutcome o = exact_simplex(exact_program(e, exact_cost), usable ? &r.basis : nullptr);
    Optimum out;
    if (o.status == SimplexStatus::Infeasible) return out;
    if (o.status == SimplexStatus::Unbounded) {
        out.status = Optimum::Status::Unbounded;
        return out;
    }
    out.status = Optimum::Status::Optimal;
    // The scaled cost is -c_j 2^{c_j} on x'_j = x_j 2^{s - c_j}: value' = -(c . x) 2^s.
    out.value = times_power_of_two(Rational(-o.value), -sc.rhs);
    std::vector<double> x;
    for (const Rational& v : o.x) x.push_back(approximate(v));
    out.point = unscale_point(x, s, sc, enclosures);
    return out;
}

}  // namespace momentlab::assembly_detail
