// A cell's generators as the walk's deciders see them (decider.hpp, grouped_edges.hpp): named so
// that the next cell can tell whether it has them too, with their approximations. Internal to
// the mechanics layer.
#pragma once

#include <vector>

#include "momentlab/core/exact.hpp"

namespace momentlab::detail {

// A generator of some mode's E, named so that another mode can tell whether it has it too:
// contact j's friction edge `slot` (FrictionEdges::slot), negated, or
// the image M r of a twist r (contact < 0).
struct Piece {
    int contact = -1;
    int slot = 0;
    Exact3 twist{};
};

// A cell's twists rounded once (their certified approximations), for every plane and every
// wrench of a batch that tests them: made at the first test in a cell, dropped at the next cell.
class TwistFilters {
public:
    void next_cell() { ready_ = false; }
    const std::vector<ExactVector::Approximation>& of(const std::vector<Exact3>& closure) {
        if (!ready_) {
            approximations_.clear();
            for (const Exact3& g : closure) approximations_.push_back(approximation(g));
            ready_ = true;
        }
        return approximations_;
    }

private:
    bool ready_ = false;
    std::vector<ExactVector::Approximation> approximations_;
};

// A generator of a cell's E: -edge for a contact's edge (negate), M r for a twist r; its
// vector's approximation kept for the scans that test it.
struct Generator {
    const ExactVector* vector;
    ExactVector::Approximation rounded;
    bool negate;
    int contact, slot;    // its name: contact j's edge in `slot`,
    const Exact3* twist;  // or (contact < 0) the twist r
    [[nodiscard]] Piece piece() const { return contact < 0 ? Piece{-1, 0, *twist} : Piece{contact, slot, {}}; }
};

}  // namespace momentlab::detail
