#include "exact_simplex.hpp"

#include <cassert>

namespace momentlab::assembly_detail {
namespace {

class ExactSimplex {
public:
    explicit ExactSimplex(const ExactProgram& lp)
        : lp_(lp), m_(lp.rows), n_(static_cast<std::uint32_t>(lp.columns.size())), h_(n_ + m_) {
        const std::uint32_t total = n_ + m_ + 1;
        upper_.assign(total, std::nullopt);
        is_free_.assign(total, false);
        for (std::uint32_t j = 0; j < n_; ++j) {
            is_free_[j] = lp.free[j];
            upper_[j] = lp.upper[j];
        }
        upper_[h_] = Rational(0);  // h is used only when the start needs it
        place_.assign(total, Place::AtLower);
        x_.assign(total, Rational(0));
        sign_.assign(m_, 1);
        basis_.assign(m_, 0);
    }

    ExactOutcome run(const Basis* start) {
        if (!(start && start_from(*start))) start_from_artificials();
        ExactOutcome out;
        // Phase 1: the artificials still free to move, and h.
        cost_.assign(n_ + m_ + 1, Rational(0));
        for (std::uint32_t j = n_; j <= h_; ++j) {
            if (!is_fixed(j)) cost_[j] = 1;
        }
        SimplexStatus s = iterate();
        assert(s == SimplexStatus::Optimal);  // phase 1 is bounded below by 0
        (void)s;
        Rational infeasibility = 0;
        for (std::uint32_t j = n_; j <= h_; ++j) infeasibility += x_[j];
        if (infeasibility > 0) {
            out.status = SimplexStatus::Infeasible;
            out.y = duals();
            return finish(std::move(out));
        }
        for (std::uint32_t j = n_; j <= h_; ++j) upper_[j] = Rational(0);
        cost_.assign(n_ + m_ + 1, Rational(0));
        for (std::uint32_t j = 0; j < n_; ++j) cost_[j] = lp_.cost[j];
        out.status = iterate();
        out.y = duals();
        return finish(std::move(out));
    }

private:
    [[nodiscard]] bool is_fixed(std::uint32_t j) const { return !is_free_[j] && upper_[j] && *upper_[j] == 0; }

    ExactOutcome finish(ExactOutcome out) {
        out.x.assign(x_.begin(), x_.begin() + n_);
        out.value = 0;
        for (std::uint32_t j = 0; j < n_; ++j) out.value += lp_.cost[j] * x_[j];
        out.pivots = pivots_;
        return out;
    }

    void for_column(std::uint32_t j, auto&& f) const {
        if (j < n_) {
            for (const SparseEntry<Rational>& e : lp_.columns[j]) f(e.index, e.value);
        } else if (j < h_) {
            f(j - n_, Rational(sign_[j - n_]));
        } else {
            for (const SparseEntry<Rational>& e : h_column_) f(e.index, e.value);
        }
    }

    bool factor() {
        std::vector<SparseColumn<Rational>> columns(m_);
        for (std::uint32_t p = 0; p < m_; ++p) {
            for_column(basis_[p], [&](std::uint32_t i, const Rational& v) {
                if (v != 0) columns[p].push_back({i, v});
            });
        }
        if (!order_.empty() && lu_.factor(columns, order_, true)) return true;
        std::vector<Pivot> diagonal;  // no order known: rows and positions in turn, searched
        for (std::uint32_t p = 0; p < m_; ++p) {
            diagonal.push_back({columns[p].empty() ? p : columns[p].front().index, p});
        }
        if (!lu_.factor(columns, diagonal, true)) return false;
        order_ = lu_.pivots();
        return true;
    }

    void compute_x() {
        std::vector<Rational> r = lp_.rhs;
        for (std::uint32_t j = 0; j <= h_; ++j) {
            if (place_[j] == Place::Basic || x_[j] == 0) continue;
            for_column(j, [&](std::uint32_t i, const Rational& v) { r[i] -= v * x_[j]; });
        }
        const std::vector<Rational> xb = lu_.solve(std::move(r));
        for (std::uint32_t p = 0; p < m_; ++p) x_[basis_[p]] = xb[p];
    }

    std::vector<Rational> duals() const {
        std::vector<Rational> c(m_);
        for (std::uint32_t p = 0; p < m_; ++p) c[p] = cost_[basis_[p]];
        return lu_.solve_transposed(std::move(c));
    }

    void set_nonbasic_values() {
        for (std::uint32_t j = 0; j <= h_; ++j) {
            if (place_[j] == Place::AtUpper) x_[j] = *upper_[j];
            if (place_[j] == Place::AtLower || place_[j] == Place::AtZero) x_[j] = 0;
        }
    }

    bool start_from(const Basis& start) {
        basis_ = start.basic;
        for (std::uint32_t j = 0; j < n_ + m_; ++j) place_[j] = start.place[j];
        place_[h_] = Place::AtLower;
        for (std::uint32_t i = 0; i < m_; ++i) {
            sign_[i] = start.artificial_sign[i];
            // Artificials out of the basis stay out.
            upper_[n_ + i] = place_[n_ + i] == Place::Basic ? std::nullopt : std::optional<Rational>(0);
            if (place_[n_ + i] != Place::Basic) place_[n_ + i] = Place::AtLower;
        }
        for (std::uint32_t j = 0; j < n_; ++j) {  // a place that the exact bounds do not allow
            if (place_[j] == Place::AtUpper && !upper_[j]) place_[j] = is_free_[j] ? Place::AtZero : Place::AtLower;
            if (place_[j] == Place::AtLower && is_free_[j]) place_[j] = Place::AtZero;
        }
        set_nonbasic_values();
        if (!factor()) return false;
        compute_x();
        bool flipped = false;
        for (std::uint32_t p = 0; p < m_; ++p) {
            const std::uint32_t j = basis_[p];
            if (j >= n_ && j < h_ && x_[j] < 0) {
                sign_[j - n_] = static_cast<signed char>(-sign_[j - n_]);
                x_[j] = -x_[j];
                flipped = true;
            }
        }
        if (flipped && !factor()) return false;
        // The basic structural variables outside their bounds: v = +1 below, -1 above.
        std::vector<Rational> v(m_, Rational(0));
        Rational theta = 0;
        std::uint32_t worst = m_;
        for (std::uint32_t p = 0; p < m_; ++p) {
            const std::uint32_t j = basis_[p];
            if (j >= n_ || is_free_[j]) continue;
            Rational distance = 0;
            if (x_[j] < 0) {
                v[p] = 1;
                distance = -x_[j];
            } else if (upper_[j] && x_[j] > *upper_[j]) {
                v[p] = -1;
                distance = x_[j] - *upper_[j];
            }
            if (distance > theta) {
                theta = distance;
                worst = p;
            }
        }
        if (worst == m_) return true;
        // h = -B v, at theta: x_B + theta v is within the bounds (or the start is given up).
        for (std::uint32_t p = 0; p < m_; ++p) {
            if (v[p] == 0) continue;
            const std::uint32_t j = basis_[p];
            const Rational moved = x_[j] + theta * v[p];
            if (moved < 0 || (upper_[j] && moved > *upper_[j])) return false;
        }
        std::vector<Rational> h(m_, Rational(0));
        for (std::uint32_t p = 0; p < m_; ++p) {
            if (v[p] == 0) continue;
            for_column(basis_[p], [&](std::uint32_t i, const Rational& a) { h[i] -= a * v[p]; });
        }
        h_column_.clear();
        for (std::uint32_t i = 0; i < m_; ++i) {
            if (h[i] != 0) h_column_.push_back({i, h[i]});
        }
        for (std::uint32_t p = 0; p < m_; ++p) {
            if (v[p] != 0) x_[basis_[p]] += theta * v[p];
        }
        const std::uint32_t out = basis_[worst];
        place_[out] = v[worst] > 0 ? Place::AtLower : Place::AtUpper;
        x_[out] = v[worst] > 0 ? Rational(0) : *upper_[out];
        basis_[worst] = h_;
        place_[h_] = Place::Basic;
        upper_[h_] = std::nullopt;
        x_[h_] = theta;
        order_.clear();
        return factor();
    }

    void start_from_artificials() {
        order_.clear();
        h_column_.clear();
        upper_[h_] = Rational(0);
        place_[h_] = Place::AtLower;
        for (std::uint32_t j = 0; j < n_; ++j) place_[j] = is_free_[j] ? Place::AtZero : Place::AtLower;
        for (std::uint32_t i = 0; i < m_; ++i) {
            basis_[i] = n_ + i;
            place_[n_ + i] = Place::Basic;
            upper_[n_ + i] = std::nullopt;
            sign_[i] = 1;
        }
        set_nonbasic_values();
        factor();
        compute_x();
        for (std::uint32_t i = 0; i < m_; ++i) {
            if (x_[n_ + i] < 0) {
                sign_[i] = -1;
                x_[n_ + i] = -x_[n_ + i];
            }
        }
        factor();
    }

    SimplexStatus iterate() {
        for (;;) {
            if (!factor()) return SimplexStatus::Stalled;  // cannot happen: pivots keep B regular
            compute_x();
            const std::vector<Rational> y = duals();
            // Bland: the first improving column.
            std::uint32_t entering = h_ + 1;
            int direction = 0;
            for (std::uint32_t j = 0; j <= h_ && entering > h_; ++j) {
                if (place_[j] == Place::Basic || is_fixed(j)) continue;
                Rational d = cost_[j];
                for_column(j, [&](std::uint32_t i, const Rational& a) { d -= y[i] * a; });
                if (d < 0 && (place_[j] == Place::AtLower || place_[j] == Place::AtZero)) direction = 1;
                if (d > 0 && (place_[j] == Place::AtUpper || place_[j] == Place::AtZero)) direction = -1;
                if (direction != 0) entering = j;
            }
            if (entering > h_) return SimplexStatus::Optimal;
            std::vector<Rational> a(m_, Rational(0));
            for_column(entering, [&](std::uint32_t i, const Rational& v) { a[i] += v; });
            const std::vector<Rational> alpha = lu_.solve(std::move(a));
            std::uint32_t leaving = m_;
            Rational step;
            for (std::uint32_t p = 0; p < m_; ++p) {
                if (alpha[p] == 0) continue;
                const std::uint32_t j = basis_[p];
                const Rational r = direction > 0 ? alpha[p] : Rational(-alpha[p]);
                std::optional<Rational> ratio;
                if (r > 0 && !is_free_[j]) ratio = x_[j] / r;
                if (r < 0 && upper_[j]) ratio = (*upper_[j] - x_[j]) / -r;
                if (!ratio) continue;
                if (leaving == m_ || *ratio < step || (*ratio == step && j < basis_[leaving])) {
                    leaving = p;
                    step = *ratio;
                }
            }
            const bool bounded_entering = !is_free_[entering] && upper_[entering];
            if (bounded_entering && (leaving == m_ || *upper_[entering] <= step)) {
                place_[entering] = direction > 0 ? Place::AtUpper : Place::AtLower;
                x_[entering] = direction > 0 ? *upper_[entering] : Rational(0);
                ++pivots_;
                continue;
            }
            if (leaving == m_) return SimplexStatus::Unbounded;
            const std::uint32_t out = basis_[leaving];
            const Rational r = direction > 0 ? alpha[leaving] : Rational(-alpha[leaving]);
            place_[out] = r > 0 ? Place::AtLower : Place::AtUpper;
            x_[out] = r > 0 ? Rational(0) : *upper_[out];
            if (out >= n_) {  // an artificial (or h) that leaves stays out
                upper_[out] = Rational(0);
                x_[out] = 0;
                place_[out] = Place::AtLower;
            }
            basis_[leaving] = entering;
            place_[entering] = Place::Basic;
            ++pivots_;
        }
    }

    const ExactProgram& lp_;
    std::uint32_t m_, n_, h_;
    std::vector<std::optional<Rational>> upper_;
    std::vector<bool> is_free_;
    std::vector<Place> place_;
    std::vector<Rational> x_, cost_;
    std::vector<signed char> sign_;
    std::vector<std::uint32_t> basis_;
    SparseColumn<Rational> h_column_;
    SparseLu<Rational> lu_;
    std::vector<Pivot> order_;
    std::size_t pivots_ = 0;
};

}  // namespace

ExactOutcome exact_simplex(const ExactProgram& lp, const Basis* start) { return ExactSimplex(lp).run(start); }

}  // namespace momentlab::assembly_detail
