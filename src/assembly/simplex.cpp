#include "simplex.hpp"

#include <algorithm>
#include <cmath>

namespace momentlab::assembly_detail {
namespace {

// Tolerances of the guidance only (the problem is scaled so that its entries are near 1):
// a wrong call here costs time on the exact path, never a wrong answer.
constexpr double kPrimalTolerance = 1e-9;
constexpr double kDualTolerance = 1e-9;
constexpr double kPivotTolerance = 1e-9;
constexpr double kInfeasibleSum = 1e-7;
constexpr std::size_t kRefactorEvery = 64;
constexpr std::size_t kDegenerateRun = 50;

// One exchange of the product-form update: the basis's column `position` replaced, with the
// entering column's alpha there (`pivot`) and at the other positions (entries begin .. end of
// the eta file's one list).
struct Eta {
    std::uint32_t position;
    double pivot;
    std::size_t begin, end;
};

class Simplex {
public:
    explicit Simplex(const DoubleProgram& lp) : lp_(lp), m_(lp.rows), n_(static_cast<std::uint32_t>(lp.columns.size())) {
        lower_ = lp.lower;
        upper_ = lp.upper;
        lower_.resize(n_ + m_, 0.0);
        upper_.resize(n_ + m_, kInfinity);
        basis_.basic.resize(m_);
        basis_.place.resize(n_ + m_);
        basis_.artificial_sign.assign(m_, 1);
        x_.assign(n_ + m_, 0.0);
        for (std::uint32_t j = 0; j < n_; ++j) {
            if (std::isfinite(lower_[j])) {
                basis_.place[j] = Place::AtLower;
                x_[j] = lower_[j];
            } else if (std::isfinite(upper_[j])) {
                basis_.place[j] = Place::AtUpper;
                x_[j] = upper_[j];
            } else {
                basis_.place[j] = Place::AtZero;
            }
        }
        for (std::uint32_t i = 0; i < m_; ++i) {
            basis_.basic[i] = n_ + i;
            basis_.place[n_ + i] = Place::Basic;
        }
    }

    SimplexResult run() {
        SimplexResult result;
        if (!refactor()) return stalled();
        recompute_x();
        bool flipped = false;
        for (std::uint32_t i = 0; i < m_; ++i) {  // artificials start non-negative
            if (x_[n_ + i] < 0.0) {
                basis_.artificial_sign[i] = -1;
                x_[n_ + i] = -x_[n_ + i];
                flipped = true;
            }
        }
        if (flipped && !refactor()) return stalled();
        if (!crash_free_columns()) return stalled();
        cost_.assign(n_ + m_, 0.0);
        for (std::uint32_t i = 0; i < m_; ++i) cost_[n_ + i] = 1.0;
        SimplexStatus phase_one = iterate();
        double sum = 0.0;
        for (std::uint32_t i = 0; i < m_; ++i) sum += x_[n_ + i];
        result.phase_one_value = sum;
        if (phase_one == SimplexStatus::Stalled) return stalled();
        if (sum > kInfeasibleSum) {
            result.status = SimplexStatus::Infeasible;
            return finish(std::move(result));
        }
        for (std::uint32_t i = 0; i < m_; ++i) upper_[n_ + i] = 0.0;  // artificials fixed at 0
        if (!drive_out_artificials()) return stalled();
        std::fill(cost_.begin(), cost_.end(), 0.0);
        std::copy(lp_.cost.begin(), lp_.cost.end(), cost_.begin());
        result.status = iterate();
        return finish(std::move(result));
    }

private:
    SimplexResult stalled() {
        SimplexResult r;
        r.status = SimplexStatus::Stalled;
        r.basis = basis_;
        r.pivots = pivots_;
        return r;
    }

    SimplexResult finish(SimplexResult r) {
        std::vector<double> c(m_);
        for (std::uint32_t p = 0; p < m_; ++p) c[p] = cost_[basis_.basic[p]];
        r.y = btran(std::move(c));
        r.basis = basis_;
        r.x = x_;
        r.pivots = pivots_;
        return r;
    }

    // Column j as sparse entries (an artificial: sign * e_i).
    void for_column(std::uint32_t j, auto&& f) const {
        if (j < n_) {
            for (const SparseEntry<double>& e : lp_.columns[j]) f(e.index, e.value);
        } else {
            f(j - n_, static_cast<double>(basis_.artificial_sign[j - n_]));
        }
    }

    bool refactor() {
        basis_columns_.resize(m_);
        for (std::uint32_t p = 0; p < m_; ++p) {
            basis_columns_[p].clear();
            for_column(basis_.basic[p], [&](std::uint32_t i, double v) { basis_columns_[p].push_back({i, v}); });
        }
        etas_.clear();
        eta_entries_.clear();
        return lu_.factor(basis_columns_);
    }

    void recompute_x() {
        std::vector<double> r = lp_.rhs;
        for (std::uint32_t j = 0; j < n_ + m_; ++j) {
            if (basis_.place[j] == Place::Basic || x_[j] == 0.0) continue;
            for_column(j, [&](std::uint32_t i, double v) { r[i] -= v * x_[j]; });
        }
        const std::vector<double> xb = ftran(std::move(r));
        for (std::uint32_t p = 0; p < m_; ++p) x_[basis_.basic[p]] = xb[p];
    }

    // B^-1 by_row into v (by_row overwritten; no allocation once the buffers have room).
    void ftran(std::vector<double>& by_row, std::vector<double>& v) const {
        lu_.solve(by_row, v);
        for (const Eta& e : etas_) {
            const double vp = v[e.position] / e.pivot;
            v[e.position] = vp;
            if (vp != 0.0) {
                for (std::size_t k = e.begin; k < e.end; ++k) v[eta_entries_[k].index] -= eta_entries_[k].value * vp;
            }
        }
    }
    std::vector<double> ftran(std::vector<double> by_row) const {
        std::vector<double> v;
        ftran(by_row, v);
        return v;
    }

    // B^-T by_position into y (by_position overwritten).
    void btran(std::vector<double>& by_position, std::vector<double>& y) const {
        for (auto e = etas_.rbegin(); e != etas_.rend(); ++e) {
            double s = by_position[e->position];
            for (std::size_t k = e->begin; k < e->end; ++k) s -= eta_entries_[k].value * by_position[eta_entries_[k].index];
            by_position[e->position] = s / e->pivot;
        }
        lu_.solve_transposed(by_position, y);
    }
    std::vector<double> btran(std::vector<double> by_position) const {
        std::vector<double> y;
        btran(by_position, y);
        return y;
    }

    std::vector<double> column_by_row(std::uint32_t j) const {
        std::vector<double> a(m_, 0.0);
        for_column(j, [&](std::uint32_t i, double v) { a[i] += v; });
        return a;
    }

    void exchange(std::uint32_t position, std::uint32_t entering, const std::vector<double>& alpha) {
        Eta eta{position, alpha[position], eta_entries_.size(), 0};
        for (std::uint32_t i = 0; i < m_; ++i) {
            if (i != position && alpha[i] != 0.0) eta_entries_.push_back({i, alpha[i]});
        }
        eta.end = eta_entries_.size();
        etas_.push_back(eta);
        basis_.basic[position] = entering;
        basis_.place[entering] = Place::Basic;
        ++pivots_;
    }

    // Free columns replace artificials before phase 1 (they never leave), then the artificials
    // take the signs that make them non-negative.
    bool crash_free_columns() {
        bool any = false;
        for (std::uint32_t j = 0; j < n_; ++j) {
            if (basis_.place[j] != Place::AtZero) continue;
            const std::vector<double> alpha = ftran(column_by_row(j));
            std::uint32_t best = m_;
            double largest = 0.0;
            for (std::uint32_t p = 0; p < m_; ++p) {
                if (basis_.basic[p] >= n_ && std::abs(alpha[p]) > largest) {
                    largest = std::abs(alpha[p]);
                    best = p;
                }
            }
            if (best == m_ || largest < 1e-7) continue;
            const std::uint32_t leaving = basis_.basic[best];
            exchange(best, j, alpha);
            basis_.place[leaving] = Place::AtLower;
            x_[leaving] = 0.0;
            upper_[leaving] = 0.0;
            any = true;
            if (etas_.size() >= kRefactorEvery && !refactor()) return false;
        }
        if (!any) return true;
        if (!refactor()) return false;
        recompute_x();
        bool flipped = false;
        for (std::uint32_t p = 0; p < m_; ++p) {
            const std::uint32_t j = basis_.basic[p];
            if (j >= n_ && x_[j] < 0.0) {
                basis_.artificial_sign[j - n_] = static_cast<signed char>(-basis_.artificial_sign[j - n_]);
                flipped = true;
            }
        }
        if (flipped) {
            if (!refactor()) return false;
            recompute_x();
        }
        return true;
    }

    // After phase 1 the artificials left in the basis are near 0: each is exchanged, where it can
    // be, for the program's column with the largest entry in its row of B^-1 A (a degenerate
    // pivot), so that the final basis's point satisfies A x = b with no artificial in it.
    bool drive_out_artificials() {
        bool any = false;
        for (std::uint32_t p = 0; p < m_; ++p) {
            if (basis_.basic[p] < n_) continue;
            std::vector<double> unit(m_, 0.0);
            unit[p] = 1.0;
            const std::vector<double> rho = btran(std::move(unit));
            std::uint32_t best = n_;
            double largest = 1e-7;
            for (std::uint32_t j = 0; j < n_; ++j) {
                if (basis_.place[j] == Place::Basic || lower_[j] == upper_[j]) continue;
                double a = 0.0;
                for_column(j, [&](std::uint32_t i, double v) { a += rho[i] * v; });
                if (std::abs(a) > largest) {
                    largest = std::abs(a);
                    best = j;
                }
            }
            if (best == n_) continue;
            const std::uint32_t out = basis_.basic[p];
            exchange(p, best, ftran(column_by_row(best)));
            basis_.place[out] = Place::AtLower;
            x_[out] = 0.0;
            any = true;
            if (etas_.size() >= kRefactorEvery && !refactor()) return false;
        }
        if (any) {
            if (!refactor()) return false;
            recompute_x();
        }
        return true;
    }

    SimplexStatus iterate() {
        const std::size_t limit = 20 * static_cast<std::size_t>(m_ + n_) + 1000;
        std::size_t degenerate = 0;
        for (std::size_t iteration = 0; iteration < limit; ++iteration) {
            if (etas_.size() >= kRefactorEvery) {
                if (!refactor()) return SimplexStatus::Stalled;
                recompute_x();
            }
            const bool bland = degenerate > kDegenerateRun;
            std::vector<double>& cb = work_;
            cb.resize(m_);
            for (std::uint32_t p = 0; p < m_; ++p) cb[p] = cost_[basis_.basic[p]];
            std::vector<double>& y = y_;
            btran(cb, y);
            // Pricing.
            std::uint32_t entering = n_ + m_;
            double best = 0.0, direction = 0.0;
            for (std::uint32_t j = 0; j < n_ + m_; ++j) {
                const Place place = basis_.place[j];
                if (place == Place::Basic || lower_[j] == upper_[j]) continue;
                double d = cost_[j];
                for_column(j, [&](std::uint32_t i, double v) { d -= y[i] * v; });
                double dir = 0.0;
                if (place == Place::AtLower && d < -kDualTolerance) dir = 1.0;
                if (place == Place::AtUpper && d > kDualTolerance) dir = -1.0;
                if (place == Place::AtZero && std::abs(d) > kDualTolerance) dir = d < 0.0 ? 1.0 : -1.0;
                if (dir == 0.0) continue;
                if (std::abs(d) > best) {
                    best = std::abs(d);
                    entering = j;
                    direction = dir;
                    if (bland) break;
                }
            }
            if (entering == n_ + m_) return SimplexStatus::Optimal;
            std::vector<double>& column = work_;
            column.assign(m_, 0.0);
            for_column(entering, [&](std::uint32_t i, double v) { column[i] += v; });
            std::vector<double>& alpha = alpha_;
            ftran(column, alpha);
            // Harris's ratio test: the largest |alpha| among the steps within the tolerant minimum.
            double bound_with_tolerance = kInfinity;
            for (std::uint32_t p = 0; p < m_; ++p) {
                const double r = direction * alpha[p];
                if (std::abs(alpha[p]) <= kPivotTolerance) continue;
                const std::uint32_t j = basis_.basic[p];
                if (r > 0.0 && std::isfinite(lower_[j])) {
                    bound_with_tolerance = std::min(bound_with_tolerance, (x_[j] - lower_[j] + kPrimalTolerance) / r);
                } else if (r < 0.0 && std::isfinite(upper_[j])) {
                    bound_with_tolerance = std::min(bound_with_tolerance, (upper_[j] + kPrimalTolerance - x_[j]) / -r);
                }
            }
            const double range = upper_[entering] - lower_[entering];
            if (!std::isfinite(bound_with_tolerance) && !std::isfinite(range)) return SimplexStatus::Unbounded;
            std::uint32_t leaving = m_;
            double step = kInfinity, largest = 0.0;
            for (std::uint32_t p = 0; p < m_; ++p) {
                const double r = direction * alpha[p];
                if (std::abs(alpha[p]) <= kPivotTolerance) continue;
                const std::uint32_t j = basis_.basic[p];
                double ratio = kInfinity;
                if (r > 0.0 && std::isfinite(lower_[j])) ratio = (x_[j] - lower_[j]) / r;
                if (r < 0.0 && std::isfinite(upper_[j])) ratio = (upper_[j] - x_[j]) / -r;
                if (ratio > bound_with_tolerance) continue;
                const bool better = bland ? (leaving == m_ || j < basis_.basic[leaving]) : std::abs(alpha[p]) > largest;
                if (better) {
                    largest = std::abs(alpha[p]);
                    leaving = p;
                    step = std::max(ratio, 0.0);
                }
            }
            if (std::isfinite(range) && range <= step) {  // the entering variable goes to its other bound
                for (std::uint32_t p = 0; p < m_; ++p) x_[basis_.basic[p]] -= range * direction * alpha[p];
                x_[entering] = direction > 0.0 ? upper_[entering] : lower_[entering];
                basis_.place[entering] = direction > 0.0 ? Place::AtUpper : Place::AtLower;
                degenerate = 0;
                continue;
            }
            if (leaving == m_) return SimplexStatus::Unbounded;
            degenerate = step < 1e-12 ? degenerate + 1 : 0;
            for (std::uint32_t p = 0; p < m_; ++p) x_[basis_.basic[p]] -= step * direction * alpha[p];
            x_[entering] += step * direction;
            const std::uint32_t out = basis_.basic[leaving];
            const double r = direction * alpha[leaving];
            if (r > 0.0) {
                x_[out] = lower_[out];
                basis_.place[out] = Place::AtLower;
            } else {
                x_[out] = upper_[out];
                basis_.place[out] = Place::AtUpper;
            }
            if (out >= n_) {  // an artificial that leaves stays out
                upper_[out] = 0.0;
                x_[out] = 0.0;
                basis_.place[out] = Place::AtLower;
            }
            exchange(leaving, entering, alpha);
        }
        return SimplexStatus::Stalled;
    }

    const DoubleProgram& lp_;
    std::uint32_t m_, n_;
    std::vector<double> lower_, upper_, cost_, x_;
    Basis basis_;
    SparseLu<double> lu_;
    std::vector<Eta> etas_;
    std::vector<SparseEntry<double>> eta_entries_;
    std::vector<SparseColumn<double>> basis_columns_;  // (room for refactor)
    std::vector<double> work_, y_, alpha_;              // (room for each iteration's vectors)
    std::size_t pivots_ = 0;
};

}  // namespace

SimplexResult simplex(const DoubleProgram& lp) { return Simplex(lp).run(); }

}  // namespace momentlab::assembly_detail
