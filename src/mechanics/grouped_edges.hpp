// The contacts' part of E on long faces of few distinct forces, reduced to two generators per
// force (used by the walk's deciders, decider.hpp). Internal to the mechanics layer.
#pragma once

#include <cstddef>
#include <set>
#include <vector>

#include "friction_edges.hpp"
#include "generators.hpp"
#include "mode_walk.hpp"

namespace momentlab::detail {

// The contacts' part of E (the generators -edge) of the cells of one long face, reduced: on a 2-D
// face of A every closed contact has its normal wrench orthogonal to the face, so the closed
// contacts share one normal line, and their edges with one force (the same doubles: contacts of
// one mu on a floor) differ only in torque. The cone of such a group is spanned by its edges of
// least and greatest torque. Each group keeps its edges in the order of their torques and the
// ranks of the edges the cell has, updated with the contacts that changed (O(log n) each), so
// that a cell's -T is given by at most two generators a group instead of one or two a contact.
// Shared by the deciders of a batch; used on faces of at least kGroupFace closed contacts whose
// edges are forces in at most kGroups groups.
class GroupedEdges {
public:
    static constexpr std::size_t kGroupFace = 16;
    static constexpr std::size_t kGroups = 8;

    explicit GroupedEdges(const FrictionEdges& edges) : edges_(edges) {}

    // Follows the walk: every cell it visits, in order (the all-f cells too).
    void next_cell(const WalkCell& cell);

    // The cell's contact generators reduced, or null when its face is not grouped.
    [[nodiscard]] const std::vector<Generator>* generators() const { return active_ ? &reduced_ : nullptr; }

private:
    struct Edge {
        ExactVector vector;  // -edge
        ExactVector::Approximation rounded;
        int contact, slot;
        std::size_t group;
        int rank = 0;  // its place in order_ (its group's edges are consecutive there)
    };

    void start(const WalkCell& cell);

    // Adds (or removes) the generators that position t has with `letter`.
    void set_alive(std::size_t t, char letter, bool alive);

    void add_reduced(int index);

    const FrictionEdges& edges_;
    std::size_t face_ = static_cast<std::size_t>(-1);
    bool active_ = false;
    std::vector<Edge> edge_list_;
    std::vector<int> at_;     // position t's edge in slot s: edge_list_[at_[4 t + s]] (-1: none)
    std::vector<int> order_;  // the edges by group, then by torque
    std::vector<std::set<int>> alive_;  // per group, the ranks of the cell's edges
    std::vector<int> closed_;            // the face's closed contacts
    std::vector<char> letters_;          // the letters of the face's previous cell
    std::vector<Generator> reduced_;
};

}  // namespace momentlab::detail
