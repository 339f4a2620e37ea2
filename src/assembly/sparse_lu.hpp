#pragma once

// Sparse LU factorization of a square matrix given by columns, right-looking, in one of three
// number types: double (the simplex's guidance; pivots chosen by Markowitz's rule with threshold
// partial pivoting), Interval (the certificates: the same pivot sequence, every entry an
// enclosure of the exact one) and Rational (the exact path: the same sequence while its pivots
// are non-zero, another non-zero of the column where one is not). Solves B x = b (column
// positions) and B^T y = c (rows). O(m + f) memory and O(sum over steps of the pivot row's and
// column's lengths) time for m rows and f entries after fill (Duff, Erisman and Reid, "Direct
// Methods for Sparse Matrices", ch. 7).

#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "interval.hpp"

namespace momentlab::assembly_detail {

template <class T>
struct SparseEntry {
    std::uint32_t index;
    T value;
};

template <class T>
using SparseColumn = std::vector<SparseEntry<T>>;

/// Where each elimination step pivots: row and column (a position of the factored matrix).
struct Pivot {
    std::uint32_t row, col;
};

namespace lu_detail {
inline bool usable(double v) { return v != 0.0 && std::isfinite(v); }
inline bool usable(const Interval& v) { return !v.holds_zero(); }
inline bool usable(const Rational& v) { return v != 0; }
inline double magnitude(double v) { return std::abs(v); }
}  // namespace lu_detail

template <class T>
class SparseLu {
public:
    /// Factors the m x m matrix whose column j is columns[j] (entries' index: the row). With
    /// `order` empty the pivots are chosen (double only); otherwise they follow `order`, and a
    /// step whose pivot is not usable (zero, or an interval holding 0) takes another usable
    /// entry of the same column when `search` (Rational), else the factorization fails. Returns
    /// false for a matrix found singular (no usable pivot in some column).
    bool factor(std::span<const SparseColumn<T>> columns, std::span<const Pivot> order = {}, bool search = false) {
        const auto m = static_cast<std::uint32_t>(columns.size());
        m_ = m;
        // (The per-row and per-step lists keep their room from one factorization to the next: a
        // simplex refactors its basis many times.)
        for (auto* lists : {&rows_, &lower_, &upper_}) {
            if (lists->size() < m) lists->resize(m);
            for (auto& list : *lists) list.clear();
        }
        if (col_rows_.size() < m) col_rows_.resize(m);
        for (auto& list : col_rows_) list.clear();
        col_count_.assign(m, 0);
        pivots_.clear();
        pivots_.reserve(m);
        for (std::uint32_t j = 0; j < m; ++j) {
            for (const SparseEntry<T>& e : columns[j]) {
                rows_[e.index].push_back({j, e.value});
                col_rows_[j].push_back(e.index);
                ++col_count_[j];
            }
        }
        row_done_.assign(m, false);
        col_done_.assign(m, false);
        position_.assign(m, -1);
        for (std::uint32_t k = 0; k < m; ++k) {
            std::optional<Pivot> p;
            if (order.empty()) {
                p = choose_pivot();
            } else {
                p = order[k];
                if (row_done_[p->row] || col_done_[p->col] || !usable_at(p->row, p->col)) {
                    p = search ? pivot_in_column(order[k].col) : std::nullopt;
                }
            }
            if (!p) return false;
            eliminate(*p);
        }
        return true;
    }

    [[nodiscard]] const std::vector<Pivot>& pivots() const { return pivots_; }

    /// x with B x = b: b indexed by row, the result by column position.
    [[nodiscard]] std::vector<T> solve(std::vector<T> b) const {
        std::vector<T> x;
        solve(b, x);
        return x;
    }
    /// The same into x (b is overwritten): no allocation once x has room.
    void solve(std::vector<T>& b, std::vector<T>& x) const {
        for (std::size_t k = 0; k < pivots_.size(); ++k) {
            const T& pivot_value = b[pivots_[k].row];
            for (const SparseEntry<T>& l : lower_[k]) b[l.index] -= l.value * pivot_value;
        }
        x.assign(m_, T(0.0));
        for (std::size_t k = pivots_.size(); k-- > 0;) {
            T s = b[pivots_[k].row];
            const std::vector<SparseEntry<T>>& u = upper_[k];
            for (std::size_t i = 1; i < u.size(); ++i) s -= u[i].value * x[u[i].index];
            x[pivots_[k].col] = s / u[0].value;
        }
    }

    /// y with B^T y = c: c indexed by column position, the result by row.
    [[nodiscard]] std::vector<T> solve_transposed(std::vector<T> c) const {
        std::vector<T> z;
        solve_transposed(c, z);
        return z;
    }
    /// The same into z (c is overwritten).
    void solve_transposed(std::vector<T>& c, std::vector<T>& z) const {
        z.assign(m_, T(0.0));
        for (std::size_t k = 0; k < pivots_.size(); ++k) {
            const std::vector<SparseEntry<T>>& u = upper_[k];
            const T v = c[pivots_[k].col] / u[0].value;
            for (std::size_t i = 1; i < u.size(); ++i) c[u[i].index] -= u[i].value * v;
            z[pivots_[k].row] = v;
        }
        for (std::size_t k = pivots_.size(); k-- > 0;) {
            T& zr = z[pivots_[k].row];
            for (const SparseEntry<T>& l : lower_[k]) zr -= l.value * z[l.index];
        }
    }

    /// Entries of L and U (the work of a solve).
    [[nodiscard]] std::size_t size() const {
        std::size_t s = 0;
        for (std::size_t k = 0; k < pivots_.size(); ++k) s += lower_[k].size() + upper_[k].size();
        return s;
    }

private:
    [[nodiscard]] const T* entry(std::uint32_t row, std::uint32_t col) const {
        for (const SparseEntry<T>& e : rows_[row]) {
            if (e.index == col) return &e.value;
        }
        return nullptr;
    }
    [[nodiscard]] bool usable_at(std::uint32_t row, std::uint32_t col) const {
        const T* v = entry(row, col);
        return v != nullptr && lu_detail::usable(*v);
    }

    // The first usable entry of an active column in an active row.
    [[nodiscard]] std::optional<Pivot> pivot_in_column(std::uint32_t col) const {
        if (col_done_[col]) return std::nullopt;
        for (std::uint32_t r : col_rows_[col]) {
            if (!row_done_[r] && usable_at(r, col)) return Pivot{r, col};
        }
        return std::nullopt;
    }

    // Markowitz: the active column with the fewest entries, and in it, among the entries at
    // least a tenth of the column's largest, the one of the shortest row (double only).
    [[nodiscard]] std::optional<Pivot> choose_pivot() const {
        if constexpr (!std::is_same_v<T, double>) {
            return std::nullopt;
        } else {
            std::uint32_t best_col = m_;
            for (std::uint32_t j = 0; j < m_; ++j) {
                if (!col_done_[j] && (best_col == m_ || col_count_[j] < col_count_[best_col])) best_col = j;
            }
            if (best_col == m_) return std::nullopt;
            double largest = 0.0;
            for (std::uint32_t r : col_rows_[best_col]) {
                if (row_done_[r]) continue;
                if (const double* v = entry(r, best_col)) largest = std::max(largest, std::abs(*v));
            }
            if (!(largest > 1e-300) || !std::isfinite(largest)) return std::nullopt;
            std::optional<Pivot> best;
            std::size_t best_length = 0;
            for (std::uint32_t r : col_rows_[best_col]) {
                if (row_done_[r]) continue;
                const double* v = entry(r, best_col);
                if (v == nullptr || std::abs(*v) < 0.1 * largest) continue;
                if (!best || rows_[r].size() < best_length) {
                    best = Pivot{r, best_col};
                    best_length = rows_[r].size();
                }
            }
            return best;
        }
    }

    void eliminate(const Pivot& p) {
        const std::size_t k = pivots_.size();
        // The pivot row becomes U's row k (their buffers swapped: the row keeps U's old room).
        std::vector<SparseEntry<T>>& pivot_row = upper_[k];
        pivot_row.swap(rows_[p.row]);
        rows_[p.row].clear();
        // The pivot first in U's row.
        for (std::size_t i = 0; i < pivot_row.size(); ++i) {
            if (pivot_row[i].index == p.col) {
                std::swap(pivot_row[0], pivot_row[i]);
                break;
            }
        }
        const T pivot_value = pivot_row[0].value;
        row_done_[p.row] = true;
        col_done_[p.col] = true;
        for (const SparseEntry<T>& e : pivot_row) --col_count_[e.index];
        std::vector<SparseEntry<T>>& lower = lower_[k];  // (cleared by factor)
        for (std::uint32_t r : col_rows_[p.col]) {
            if (row_done_[r]) continue;
            std::vector<SparseEntry<T>>& row = rows_[r];
            std::size_t at = row.size();
            for (std::size_t i = 0; i < row.size(); ++i) {
                if (row[i].index == p.col) {
                    at = i;
                    break;
                }
            }
            if (at == row.size()) continue;  // listed twice, already done
            const T l = row[at].value / pivot_value;
            row[at] = std::move(row.back());
            row.pop_back();
            --col_count_[p.col];
            lower.push_back({r, l});
            for (std::size_t i = 0; i < row.size(); ++i) position_[row[i].index] = static_cast<std::int64_t>(i);
            for (std::size_t i = 1; i < pivot_row.size(); ++i) {
                const SparseEntry<T>& u = pivot_row[i];
                const std::int64_t q = position_[u.index];
                if (q >= 0) {
                    row[static_cast<std::size_t>(q)].value -= l * u.value;
                } else {
                    row.push_back({u.index, T(0.0) - l * u.value});
                    position_[u.index] = static_cast<std::int64_t>(row.size() - 1);
                    col_rows_[u.index].push_back(r);
                    ++col_count_[u.index];
                }
            }
            for (const SparseEntry<T>& e : row) position_[e.index] = -1;
        }
        pivots_.push_back(p);
    }

    std::uint32_t m_ = 0;
    std::vector<std::vector<SparseEntry<T>>> rows_;
    std::vector<std::vector<std::uint32_t>> col_rows_;
    std::vector<std::uint32_t> col_count_;
    std::vector<bool> row_done_, col_done_;
    std::vector<std::int64_t> position_;
    std::vector<Pivot> pivots_;
    // Step k < pivots_.size() (the lists beyond are room kept for the next factorization):
    std::vector<std::vector<SparseEntry<T>>> lower_;  // (row, multiplier)
    std::vector<std::vector<SparseEntry<T>>> upper_;  // the pivot row, pivot first: (col, value)
};

}  // namespace momentlab::assembly_detail
