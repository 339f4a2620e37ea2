#pragma once

// The linear programs of the assembly layer, decided exactly: "is there an x with A x = b,
// x_j >= 0 (x_j free for some j), and x_j > 0 for the strict j?" and "how large can c . x be?".
// A program is given twice, with the same columns in the same order: as enclosures (Interval:
// each entry an interval holding the exact value, built from the scene's numbers in interval
// arithmetic; cheap) and, on demand, exactly (Rational). The decision (Chvatal, "Linear
// Programming"; Applegate, Cook, Dash and Espinoza, "Exact solutions to linear programming
// problems", 2007, for the idea of exact answers from floating-point bases):
//   1. the double simplex on the midpoints, with a margin t: x_j = mu_j + t for the strict j,
//      t maximised in [0, 1] (columns and rows scaled by powers of two, exactly);
//   2. its answer certified in interval arithmetic: a point (the basis's solution with the
//      nonbasic variables at their bounds: the equations hold exactly by construction, and the
//      intervals show the signs; the basis solved by interval elimination, else enclosed by
//      preconditioning, enclose_solution below), or a Farkas vector y (y = B^-T c_B: the
//      intervals show the signs of y . A_j and y . b); a sign is read only from an interval
//      that excludes 0;
//   3. otherwise the exact simplex from that basis (exact_simplex.hpp), which decides and gives
//      the exact point or y.
// Every answer is exact for the numbers of the exact program; floating point only guides.

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "sparse_lu.hpp"

namespace momentlab::assembly_detail {

template <class T>
struct Program {
    std::uint32_t rows = 0;
    std::vector<SparseColumn<T>> columns;
    std::vector<bool> free;    // per column: x_j free (else x_j >= 0)
    std::vector<bool> strict;  // per column: asked x_j > 0 (only for x_j >= 0)
    std::vector<T> rhs;        // per row

    /// A new column; returns its index.
    std::uint32_t add(SparseColumn<T> column, bool free_variable = false, bool strict_variable = false) {
        columns.push_back(std::move(column));
        free.push_back(free_variable);
        strict.push_back(strict_variable && !free_variable);
        return static_cast<std::uint32_t>(columns.size() - 1);
    }
};

/// Builds the exact program, the same columns in the same order as the enclosures.
using ExactBuilder = std::function<Program<Rational>()>;

enum class Feasibility { Infeasible, Feasible, StrictlyFeasible };

struct FeasibilityAnswer {
    /// StrictlyFeasible: a point with every strict x_j > 0 (with no strict column: any point).
    /// Feasible: a point, and none with the strict x_j all > 0.
    Feasibility status = Feasibility::Infeasible;
    /// Per column: the values of an exact point (rounded), when feasible.
    std::vector<double> point;
    /// Per row, when infeasible: y with y . A_j <= 0 for x_j >= 0, y . A_j = 0 for free x_j and
    /// y . b > 0 (rounded; the exact y exists and was checked).
    std::vector<double> farkas;
    bool exact_path = false;  ///< decided by the exact simplex (not by the intervals)
};

[[nodiscard]] FeasibilityAnswer decide(const Program<Interval>& enclosures, const ExactBuilder& exact);

struct Optimum {
    enum class Status { Infeasible, Unbounded, Optimal };
    Status status = Status::Infeasible;
    Rational value;             ///< max of the objective, exactly (Optimal)
    std::vector<double> point;  ///< an optimal point, rounded
};

/// max sum of coefficient * x_j over the program (strictness ignored), exactly: the double
/// simplex's basis confirmed or repaired by the exact simplex.
[[nodiscard]] Optimum maximize(const Program<Interval>& enclosures, const ExactBuilder& exact,
                               const std::vector<std::pair<std::uint32_t, int>>& objective);

/// An enclosure of the solution of B x = b for every square B (by columns) and b inside the
/// intervals, or none when B cannot be shown regular this way (or has more than 2000 rows): the
/// inverse of B's midpoint as a preconditioner and a norm bound on the error, without the
/// growth of interval elimination. O(m^2 + m nnz(B)) time, m^2 doubles.
[[nodiscard]] std::optional<std::vector<Interval>> enclose_solution(const std::vector<SparseColumn<Interval>>& columns,
                                                                    const std::vector<Interval>& rhs);

/// How the decisions went (for tests and benchmarks): those certified by the intervals, and
/// those that took the exact simplex, since the thread started.
struct LpCounts {
    std::size_t certified = 0;
    std::size_t exact = 0;
};
[[nodiscard]] LpCounts& lp_counts();

}  // namespace momentlab::assembly_detail
