// Each contact's friction edges as exact wrenches, built once for every mode of a scene: what
// analyze and the walk of query_scene (decider.hpp, grouped_edges.hpp) make a mode's contact cone
// T of, by the contact model (contact_model.hpp). Internal to the mechanics layer.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/core/parallel.hpp"
#include "momentlab/mechanics/modes.hpp"
#include "contact_model.hpp"

namespace momentlab::detail {

/// From this many contacts the friction edges are built in two halves, and query_scene decides
/// the all-f mode beside the walk, on two threads (a thread costs tens of microseconds, a
/// contact's edges a few).
inline constexpr std::size_t kTwoThreadContacts = 20;

/// Each contact's friction edges, built once for all the modes (exact constructions; copies
/// share them): the static cone's two edges, and the kinetic ones n + mu_k t, n - mu_k t.
struct FrictionEdges {
    std::vector<std::array<ExactVector, 2>> statics;
    // Their approximations, made once for every plane that tests them (the same layout).
    std::vector<std::array<ExactVector::Approximation, 2>> statics_rounded, kinetics_rounded;
    // The kinetic edges of the contacts whose mu_k differs from mu, in order; kinetic_at[j] is
    // contact j's place among them, or -1 when mu_k = mu (its kinetic edges are the static ones:
    // not stored twice, 192 bytes a contact).
    std::vector<std::array<ExactVector, 2>> kinetics;
    std::vector<int> kinetic_at;

    // Exact constructions, a few microseconds each: two halves on two threads for large scenes
    // (unless the caller has the other thread busy).
    explicit FrictionEdges(const std::vector<Contact>& contacts, bool two_threads = true)
        : statics(contacts.size()), statics_rounded(contacts.size()), kinetic_at(contacts.size(), -1) {
        const std::size_t n = contacts.size();
        int distinct = 0;
        for (std::size_t j = 0; j < n; ++j) {
            if (!contacts[j].kinetic_is_static()) kinetic_at[j] = distinct++;
        }
        kinetics.resize(static_cast<std::size_t>(distinct));
        kinetics_rounded.resize(static_cast<std::size_t>(distinct));
        detail::for_each_index(2, two_threads && n >= kTwoThreadContacts, [&](std::size_t half) {
            for (std::size_t j = n * half / 2; j < n * (half + 1) / 2; ++j) {
                const Contact& c = contacts[j];
                statics[j] = c.friction_edges();
                statics_rounded[j] = {statics[j][0].approximation(), statics[j][1].approximation()};
                if (kinetic_at[j] >= 0) {
                    const auto k = static_cast<std::size_t>(kinetic_at[j]);
                    kinetics[k] = c.friction_edges(true);
                    kinetics_rounded[k] = {kinetics[k][0].approximation(), kinetics[k][1].approximation()};
                }
            }
        });
    }

    // Contact j's kinetic edges (n + mu_k t, n - mu_k t).
    [[nodiscard]] const std::array<ExactVector, 2>& kinetic(std::size_t j) const {
        return kinetic_at[j] < 0 ? statics[j] : kinetics[static_cast<std::size_t>(kinetic_at[j])];
    }

    // A name for each edge, so that modes can tell whether they share one: its FrictionEdge, the
    // kinetic ones named as the static ones when mu_k = mu (the same vectors).
    [[nodiscard]] int slot(std::size_t j, FrictionEdge e) const {
        const int s = static_cast<int>(e);
        return s >= 2 && kinetic_at[j] < 0 ? s - 2 : s;
    }
    // The slot of contact j's edge with letter 'r' or 'l' (its one generator).
    [[nodiscard]] int sliding_slot(std::size_t j, char letter) const {
        return slot(j, *contact_generators(letter).begin());
    }
    // The edge in slot `slot` of contact j, and its approximation.
    [[nodiscard]] const ExactVector& edge(std::size_t j, int slot) const {
        return slot < 2 ? statics[j][static_cast<std::size_t>(slot)] : kinetic(j)[static_cast<std::size_t>(slot - 2)];
    }
    [[nodiscard]] const ExactVector::Approximation& rounded(std::size_t j, int slot) const {
        if (slot < 2) return statics_rounded[j][static_cast<std::size_t>(slot)];
        const auto& pair = kinetic_at[j] < 0 ? statics_rounded[j] : kinetics_rounded[static_cast<std::size_t>(kinetic_at[j])];
        return pair[static_cast<std::size_t>(slot - 2)];
    }

    // Calls f(edge, slot) for each generator contact j adds to the contact cone T of a mode in
    // which its letter is `letter` (contact_generators). Stops at the first f that returns false.
    template <class F>
    bool for_contact(std::size_t j, char letter, F f) const {
        for (const FrictionEdge e : contact_generators(letter)) {
            const int s = slot(j, e);
            if (!f(edge(j, s), s)) return false;
        }
        return true;
    }

    // Calls f(edge) for each generator of the contact cone T of a mode.
    template <class F>
    void for_each(const Mode& mode, F f) const {
        for (std::size_t j = 0; j < statics.size(); ++j) {
            for_contact(j, mode.letters[j], [&](const ExactVector& edge, int) {
                f(edge);
                return true;
            });
        }
    }
};

}  // namespace momentlab::detail
