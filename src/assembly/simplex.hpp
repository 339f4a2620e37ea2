#pragma once

// The bounded primal simplex method in doubles (Dantzig, "Linear Programming and Extensions";
// Chvatal, "Linear Programming", ch. 8 and 24): the floating-point guidance of the assembly
// layer's linear programs. It decides nothing: its final basis is certified by interval
// arithmetic or repaired by the exact simplex (exact_lp.hpp). Revised, with a sparse LU of the
// basis refactored every 64 pivots and product-form updates in between; Dantzig's pricing,
// Harris's two-pass ratio test, Bland's rule after long degenerate runs.

#include <cstdint>
#include <limits>
#include <vector>

#include "sparse_lu.hpp"

namespace momentlab::assembly_detail {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// min cost . x subject to A x = b, lower <= x <= upper (lower 0 or -inf, upper finite or +inf).
struct DoubleProgram {
    std::uint32_t rows = 0;
    std::vector<SparseColumn<double>> columns;
    std::vector<double> lower, upper, cost;
    std::vector<double> rhs;
};

/// Where a variable sits.
enum class Place : std::uint8_t { Basic, AtLower, AtUpper, AtZero };

/// A basis of the program with its artificial columns: columns 0 .. n-1 are the program's,
/// n + i is row i's artificial, sign * e_i.
struct Basis {
    std::vector<std::uint32_t> basic;          // column of each basis position
    std::vector<Place> place;                  // per column (n + m of them)
    std::vector<signed char> artificial_sign;  // per row
};

enum class SimplexStatus { Optimal, Infeasible, Unbounded, Stalled };

struct SimplexResult {
    SimplexStatus status = SimplexStatus::Stalled;
    Basis basis;                // the last basis (of phase 1 when infeasible)
    std::vector<double> x;      // per column, artificials included
    std::vector<double> y;      // duals of the last phase: B^T y = c_B (phase 1: the artificials' costs)
    double phase_one_value = 0.0;
    std::size_t pivots = 0;
};

/// Phase 1 (the sum of the artificials), then phase 2 (cost). Free columns enter the basis first.
[[nodiscard]] SimplexResult simplex(const DoubleProgram& lp);

}  // namespace momentlab::assembly_detail
