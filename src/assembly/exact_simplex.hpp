#pragma once

// The bounded primal simplex method in exact rational arithmetic, Bland's rule (it cannot
// cycle): the assembly layer's exact path, started from the basis the double simplex ended at
// (so that it usually only confirms it, or repairs it in a few pivots). Phase 1 minimises the
// artificials (the double basis's own, and one more column h = -B v that takes the basic
// variables outside their bounds inside them at once when the start is not feasible: the
// single-artificial method of Chvatal, "Linear Programming", ch. 8); phase 2 the cost. Every
// iteration factors the basis exactly (SparseLu<Rational>): O(pivots x the exact factorization).

#include <optional>
#include <vector>

#include "simplex.hpp"

namespace momentlab::assembly_detail {

/// min cost . x subject to A x = b, each x_j free or 0 <= x_j <= upper_j (upper optional).
struct ExactProgram {
    std::uint32_t rows = 0;
    std::vector<SparseColumn<Rational>> columns;
    std::vector<bool> free;
    std::vector<std::optional<Rational>> upper;
    std::vector<Rational> cost;
    std::vector<Rational> rhs;
};

struct ExactOutcome {
    SimplexStatus status = SimplexStatus::Stalled;  // Optimal, Infeasible or Unbounded
    std::vector<Rational> x;                        // the program's columns
    /// Rows. Optimal: B^T y = c_B (the duals). Infeasible: phase 1's duals, a Farkas certificate:
    /// y . A_j <= 0 for x_j >= 0 (and >= 0 at its upper bound), y . A_j = 0 for free x_j, and
    /// y . b > the most y . A x can be inside the bounds.
    std::vector<Rational> y;
    Rational value;  // the optimal cost
    std::size_t pivots = 0;
};

/// Solves the program exactly, from `start` (a basis of the same program with its artificials,
/// as simplex() numbers them) when given and usable, else from the artificial basis.
[[nodiscard]] ExactOutcome exact_simplex(const ExactProgram& lp, const Basis* start);

}  // namespace momentlab::assembly_detail
