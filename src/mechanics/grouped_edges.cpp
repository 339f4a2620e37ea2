// GroupedEdges (grouped_edges.hpp): a long face's closed contacts' edges by force, each group
// given by its edges of least and greatest torque.
#include "grouped_edges.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace momentlab::detail {

// Follows the walk: every cell it visits, in order (the all-f cells too).
void GroupedEdges::next_cell(const WalkCell& cell) {
    if (cell.first || cell.face != face_) {
        start(cell);
    } else if (active_) {
        for (int t : cell.changed) {
            const auto position = static_cast<std::size_t>(t);
            set_alive(position, letters_[position], false);
            letters_[position] = cell.letters[position];
            set_alive(position, letters_[position], true);
        }
    }
    if (!active_) return;
    reduced_.clear();
    for (const std::set<int>& alive : alive_) {
        if (alive.empty()) continue;
        add_reduced(order_[static_cast<std::size_t>(*alive.begin())]);
        if (alive.size() > 1) add_reduced(order_[static_cast<std::size_t>(*alive.rbegin())]);
    }
}

void GroupedEdges::start(const WalkCell& cell) {
    face_ = cell.face;
    active_ = false;
    if (cell.closed.size() < kGroupFace) return;
    edge_list_.clear();
    at_.assign(cell.closed.size() * 4, -1);
    std::map<std::pair<double, double>, std::size_t> groups;
    for (std::size_t t = 0; t < cell.closed.size(); ++t) {
        const auto j = static_cast<std::size_t>(cell.closed[t]);
        for (int slot : {0, 1, edges_.sliding_slot(j, 'l'), edges_.sliding_slot(j, 'r')}) {
            if (at_[t * 4 + static_cast<std::size_t>(slot)] >= 0) continue;
            Edge e{edges_.edge(j, slot).negated(), edges_.rounded(j, slot), static_cast<int>(j), slot, 0};
            e.rounded.approx = -e.rounded.approx;
            // Its force: the vector's first two coordinates, doubles as stored or as the
            // factors of a wrench() give them (else the face is not grouped).
            Vec2 point, d;
            int sign = 0;
            if (!e.vector.is_constructed()) {
                d = e.vector.value().head<2>();
            } else if (e.vector.force(point, d, sign)) {
                d *= sign;
            } else {
                return;
            }
            d = d.array() + 0.0;  // (-0 as 0)
            const auto [it, added] = groups.emplace(std::pair{d.x(), d.y()}, groups.size());
            if (added && groups.size() > kGroups) return;
            e.group = it->second;
            at_[t * 4 + static_cast<std::size_t>(slot)] = static_cast<int>(edge_list_.size());
            edge_list_.push_back(std::move(e));
        }
    }
    // Each group in the order of its torques: for one force D, det(w_a, w_b, (-D.y, D.x, 0))
    // = (tau_a - tau_b) |D|^2.
    order_.resize(edge_list_.size());
    std::iota(order_.begin(), order_.end(), 0);
    std::vector<ExactVector> across(groups.size());
    for (const auto& [d, g] : groups) across[g] = ExactVector::input(Vec3(-d.second, d.first, 0.0));
    std::sort(order_.begin(), order_.end(), [&](int a, int b) {
        const Edge &x = edge_list_[static_cast<std::size_t>(a)], &y = edge_list_[static_cast<std::size_t>(b)];
        if (x.group != y.group) return x.group < y.group;
        return det_sign(x.vector, y.vector, across[x.group]) == Sign::Negative;
    });
    for (std::size_t r = 0; r < order_.size(); ++r) edge_list_[static_cast<std::size_t>(order_[r])].rank = static_cast<int>(r);
    alive_.assign(groups.size(), {});
    closed_.assign(cell.closed.begin(), cell.closed.end());
    letters_.assign(cell.letters.begin(), cell.letters.end());
    for (std::size_t t = 0; t < letters_.size(); ++t) set_alive(t, letters_[t], true);
    active_ = true;
}

// Adds (or removes) the generators that position t has with `letter`.
void GroupedEdges::set_alive(std::size_t t, char letter, bool alive) {
    const auto mark = [&](int slot) {
        const Edge& e = edge_list_[static_cast<std::size_t>(at_[t * 4 + static_cast<std::size_t>(slot)])];
        std::set<int>& set = alive_[e.group];
        if (alive) {
            set.insert(e.rank);
        } else {
            set.erase(e.rank);
        }
    };
    edges_.for_contact(static_cast<std::size_t>(closed_[t]), letter, [&](const ExactVector&, int slot) {
        mark(slot);
        return true;
    });
}

void GroupedEdges::add_reduced(int index) {
    const Edge& e = edge_list_[static_cast<std::size_t>(index)];
    reduced_.push_back({&e.vector, e.rounded, false, e.contact, e.slot, nullptr});
}

}  // namespace momentlab::detail
