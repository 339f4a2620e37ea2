// analyze and query (mechanics/analysis.hpp): every mode's F, T and E, and the modes whose
// closed E holds an applied wrench.
#include "momentlab/mechanics/analysis.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include "momentlab/core/parallel.hpp"
#include "momentlab/geometry/force_sets.hpp"
#include "checks.hpp"
#include "mode_walk.hpp"
#include "../geometry/held_cone.hpp"

namespace momentlab {

void detail::check_body(const Scene& scene, const char* who) {
    if (!scene.body) throw std::invalid_argument(std::string(who) + ": the scene needs a body (mass, com, inertia)");
    const Body& b = *scene.body;
    const bool inertia_ok = b.radius_of_gyration ? *b.radius_of_gyration > 0.0 && std::isfinite(*b.radius_of_gyration)
                                                 : b.inertia > 0.0 && std::isfinite(b.inertia);
    if (!b.com.allFinite() || !(b.mass > 0.0) || !std::isfinite(b.mass) || !inertia_ok) {
        throw std::invalid_argument(std::string(who) +
                                    ": the body needs a finite com, 0 < mass < inf and 0 < inertia < inf (or radius of gyration)");
    }
}

namespace {

// The inertia at the origin, or none when quasi-static (checks the body as analyze documents).
std::optional<ExactMatrix> inertia_of(const Scene& scene, const AnalysisOptions& options, const char* who) {
    if (options.quasi_static) return std::nullopt;
    detail::check_body(scene, who);
    return inertia_at_origin(*scene.body);
}

// From this many contacts the friction edges are built in two halves, and query_scene decides
// the all-f mode beside the walk, on two threads (a thread costs tens of microseconds, a
// contact's edges a few).
constexpr std::size_t kTwoThreadContacts = 20;
// A batch's walk of a large scene goes in up to this many parts of consecutive faces, handed to
// the two threads one at a time (the work is far from even over the faces).
constexpr std::size_t kWalkParts = 32;

// Each contact's friction edges, built once for all the modes (exact constructions; copies
// share them): the static cone's two edges, and the kinetic ones n + mu_k t, n - mu_k t.
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
            if (contacts[j].mu_kinetic != contacts[j].mu) kinetic_at[j] = distinct++;
        }
        kinetics.resize(static_cast<std::size_t>(distinct));
        kinetics_rounded.resize(static_cast<std::size_t>(distinct));
        detail::for_each_index(2, two_threads && n >= kTwoThreadContacts, [&](std::size_t half) {
            for (std::size_t j = n * half / 2; j < n * (half + 1) / 2; ++j) {
                const Contact& c = contacts[j];
                statics[j] = friction_cone_edges(c.point, c.normal, c.mu);
                statics_rounded[j] = {statics[j][0].approximation(), statics[j][1].approximation()};
                if (kinetic_at[j] >= 0) {
                    const auto k = static_cast<std::size_t>(kinetic_at[j]);
                    kinetics[k] = friction_cone_edges(c.point, c.normal, c.mu_kinetic);
                    kinetics_rounded[k] = {kinetics[k][0].approximation(), kinetics[k][1].approximation()};
                }
            }
        });
    }

    // Contact j's kinetic edges (n + mu_k t, n - mu_k t).
    [[nodiscard]] const std::array<ExactVector, 2>& kinetic(std::size_t j) const {
        return kinetic_at[j] < 0 ? statics[j] : kinetics[static_cast<std::size_t>(kinetic_at[j])];
    }

    // A name for each edge, so that modes can tell whether they share one: 0, 1 the static
    // edges; 2, 3 the kinetic ones (0, 1 again when mu_k = mu). The slot of contact j's edge
    // with letter 'r' or 'l':
    [[nodiscard]] int sliding_slot(std::size_t j, char letter) const {
        const int side = letter == 'r' ? 1 : 0;
        return kinetic_at[j] < 0 ? side : side + 2;
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
    // which its letter is `letter`: both static edges of f, n - mu_k t of r (friction opposes
    // sliding along +t), n + mu_k t of l, none of s. Stops at the first f that returns false.
    template <class F>
    bool for_contact(std::size_t j, char letter, F f) const {
        switch (letter) {
            case 'f': return f(statics[j][0], 0) && f(statics[j][1], 1);
            case 'r': return f(kinetic(j)[1], sliding_slot(j, letter));
            case 'l': return f(kinetic(j)[0], sliding_slot(j, letter));
            default: return true;
        }
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

}  // namespace

std::vector<ModeForces> analyze(const Scene& scene, const AnalysisOptions& options) {
    const std::optional<ExactMatrix> m = inertia_of(scene, options, "analyze");
    const ModeSet modes = enumerate_modes(scene.contacts, options.progress);
    const FrictionEdges edges(scene.contacts);
    // The modes are independent: on two threads when there is enough to do (about n letters of
    // work per mode; below 2000 letters a thread costs more than it saves).
    const std::size_t count = modes.modes.size();
    std::vector<ModeForces> out(count);
    std::atomic<std::size_t> done{0};
    const std::thread::id caller = std::this_thread::get_id();
    detail::for_each_index(count, count * scene.contacts.size() >= 2000, [&](std::size_t i) {
        // Progress from the calling thread only (the callback need not be thread-safe).
        if (options.progress && std::this_thread::get_id() == caller) options.progress("force sets of the modes", done, count);
        const Mode& mode = modes.modes[i];
        std::vector<ExactVector> contact_generators;
        edges.for_each(mode, [&](const ExactVector& g) { contact_generators.push_back(g); });
        ModeForces f{mode, m ? mode.twists.linear_image(*m) : Cone(), Cone::from_generators(contact_generators), Cone()};
        // Quasi-static: no inertia, F = {0}, so E = -T (the applied wrench balances the contacts').
        f.applied = m ? sum(f.total, f.contact.negated()) : f.contact.negated();
        out[i] = std::move(f);
        ++done;
    });
    return out;
}

namespace {

// A generator of some mode's E, named so that another mode can tell whether it has it too:
// contact j's friction edge `slot` (FrictionEdges::for_contact), negated, or
// the image M r of a twist r (contact < 0).
struct Piece {
    int contact = -1;
    int slot = 0;
    Exact3 twist{};
};

// adj(m) w for a 3 x 3 matrix given by its rows: the columns of adj(m) are r1 x r2, r2 x r0,
// r0 x r1, so that m adj(m) = det(m) I.
Exact3 adjugate_times(const ExactMatrix& m, const Exact3& w) {
    return w[0] * cross(m[1], m[2]) + w[1] * cross(m[2], m[0]) + w[2] * cross(m[0], m[1]);
}

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
    void next_cell(const detail::WalkCell& cell) {
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

    void start(const detail::WalkCell& cell) {
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
    void set_alive(std::size_t t, char letter, bool alive) {
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

    void add_reduced(int index) {
        const Edge& e = edge_list_[static_cast<std::size_t>(index)];
        reduced_.push_back({&e.vector, e.rounded, false, e.contact, e.slot, nullptr});
    }

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

// Decides, cell after cell of the walk (mode_walk.hpp), whether e lies in the cell's
// E = M cl(cell) + (-T), with certificates kept from the cells before:
//  - the current plane h (h . e < 0) that held every generator of the previous cell's E: along
//    a face's walk only the contacts whose letters changed, and the cell's twists, are checked;
//  - up to eight earlier planes, checked against every generator (on faces of few contacts);
//  - up to eight triplets of named generators whose cone holds e: a cell that has all three
//    holds e.
// A certificate that the contacts which changed broke is mended, with a few scans of the cell's
// generators (O(closed contacts) predicates each, where testing e against E sorts them):
//  - a triangle that lost one generator takes another of the cell's in its place; else, about a
//    generator p it kept (or any, when it kept none), the plane through p and e crosses an edge
//    (x, y) of E beyond e, and e is in cone(p, x, y): that edge is found as a bridge is;
//  - a plane broken by a generator g turns about g: onto a generator the broken plane went
//    through, else onto one of the two generators x whose plane through g leaves every generator
//    on one side (a gift-wrapping step each way).
// Every mended certificate is checked exactly. Along a face whose every step changes an extreme
// generator (contacts on a line with their normals along it) they decide the cells that would
// each need E.
// A cell no certificate decides has e tested against its E (cone_holds: its extreme rays, no
// facets), which gives the next certificate.
class Decider {
public:
    Decider(const Cone& a, const std::optional<ExactMatrix>& m, const FrictionEdges& edges, const Vec3& e)
        : a_(a), m_(m), edges_(edges), e_(e), wrench_(ExactVector::input(e)) {}

    [[nodiscard]] std::size_t built() const { return built_; }
    [[nodiscard]] std::size_t tested() const { return tested_; }
    [[nodiscard]] std::size_t mended() const { return mended_; }
    [[nodiscard]] std::size_t scanned() const { return scanned_; }
    [[nodiscard]] std::size_t grouped() const { return grouped_; }

    // `filters` holds this cell's twists rounded (shared by the deciders of a batch).
    // `groups`, when given, follows the walk (its reduced generators are this cell's).
    bool member(const detail::WalkCell& cell, TwistFilters& filters, const GroupedEdges* groups = nullptr) {
        cell_ = &cell;
        filters_ = &filters;
        groups_ = groups ? groups->generators() : nullptr;
        const bool answer = decide();
        last_face_ = cell.face;
        last_member_ = answer;
        if (answer) current_valid_ = false;  // no plane holds a cone that holds e
        return answer;
    }

private:
    static constexpr std::size_t kCache = 8;
    static constexpr std::size_t kSmallFace = 32;  // closed contacts for a full check of cached planes
    // Closed contacts from which a broken certificate is mended rather than built again: below,
    // testing e against E costs about what a mend's fixed part does (the twists' images and a
    // plane's M^T h in Dyadic numbers), and its facets hold for longer (on the tangent family of
    // 10^5 contacts, faces of 1-3 closed contacts, mending every certificate made five wrenches
    // of a batch take 5.8 s instead of 1.0 s).
    static constexpr std::size_t kMendFace = 16;
    static constexpr int kWideSteps = 32;  // Gilbert steps for a wide plane

    // A separating plane h (h . e < 0), with M^T h: h . (M g) = (M^T h) . g, so that the cell's
    // twists g are checked as they are, with no image M g made (unused when quasi-static).
    // A plane found through two generators u, v keeps them: h = sign (u x v), and h . y is
    // sign det(u, v, y), whose filters know wrenches of forces (exact zeros of parallel forces
    // among them); sign is 0 for a plane given by h alone.
    // Each vector is kept with its approximation (rh, rpulled, ru, rv), rounded once for every
    // generator the plane is tested against.
    struct Plane {
        ExactVector h, pulled;
        ExactVector u, v;
        ExactVector::Approximation rh, rpulled, ru, rv;
        int sign = 0;
    };
    // dot_sign(a, b) with the filter inline: the planes' tests make half a million of them on
    // the tangent family of 10^4 contacts, nearly all decided by the filter.
    template <class B>
    static Sign dot_filtered(const ExactVector& a, const B& b, const ExactVector::Approximation& pa,
                             const ExactVector::Approximation& pb) {
        Sign s = Sign::Zero;
        return dot_sign_by_approximations(pa, pb, s) ? s : dot_sign(a, b, pa, pb);
    }
    static Sign side(const Plane& p, const ExactVector& y, const ExactVector::Approximation& ry) {
        if (p.sign == 0) return dot_filtered(p.h, y, p.rh, ry);
        const Sign s = det_sign(p.u, p.v, y, p.ru, p.rv, ry);
        return p.sign > 0 ? s : -s;
    }
    Plane plane_of(const ExactVector& h) const {
        Plane p;
        p.h = h;
        p.rh = h.approximation();
        if (m_) {
            const Exact3 x = h.exact();
            const ExactMatrix& m = *m_;
            p.pulled = ExactVector::from_exact(x[0] * m[0] + x[1] * m[1] + x[2] * m[2]);
            p.rpulled = p.pulled.approximation();
        }
        return p;
    }

    bool holds_images(const Plane& p) const {
        if (!m_) return true;
        const std::vector<Exact3>& closure = *cell_->closure;
        const std::vector<ExactVector::Approximation>& rounded = filters_->of(closure);
        for (std::size_t i = 0; i < closure.size(); ++i) {
            if (dot_filtered(p.pulled, closure[i], p.rpulled, rounded[i]) == Sign::Negative) return false;
        }
        return true;
    }
    // h holds the generators (-edge) that the contact at position t adds.
    bool holds_position(const Plane& p, std::size_t t) const {
        const auto j = static_cast<std::size_t>(cell_->closed[t]);
        return edges_.for_contact(j, cell_->letters[t], [&](const ExactVector& edge, int slot) {
            return side(p, edge, edges_.rounded(j, slot)) != Sign::Positive;
        });
    }
    // h holds the cell's generators other than the twists' images: every closed contact's, or
    // the reduced ones of a grouped face (the same cone).
    bool holds_edges(const Plane& p) const {
        if (!groups_) {
            for (std::size_t t = 0; t < cell_->closed.size(); ++t) {
                if (!holds_position(p, t)) return false;
            }
            return true;
        }
        return std::all_of(groups_->begin(), groups_->end(),
                           [&](const Generator& g) { return side(p, *g.vector, g.rounded) != Sign::Negative; });
    }
    // h holds every generator of the cell's E.
    bool holds_cell(const Plane& p) const { return holds_images(p) && holds_edges(p); }

    char letter_of_contact(int j) const {
        const auto it = std::lower_bound(cell_->closed.begin(), cell_->closed.end(), j);
        if (it == cell_->closed.end() || *it != j) return 's';
        return cell_->letters[static_cast<std::size_t>(it - cell_->closed.begin())];
    }

    bool has_piece(const Piece& p) const {
        if (p.contact < 0) {  // the same twist among the cell's generators (along a face they recur as they are)
            return std::any_of(cell_->closure->begin(), cell_->closure->end(), [&](const Exact3& g) { return g == p.twist; });
        }
        const char letter = letter_of_contact(p.contact);
        if (letter == 'f') return p.slot < 2;
        return (letter == 'r' || letter == 'l') && p.slot == edges_.sliding_slot(static_cast<std::size_t>(p.contact), letter);
    }

    bool decide() {
        if (is_zero(e_)) return true;  // in every closed cone
        if (cell_->closed.empty()) {
            // The interior of a full-dimensional A, where no contact touches: E = M A, and e is in
            // it when adj(M) e is in A (M is positive definite: adj(M) = det(M) M^-1, det > 0).
            // Quasi-static, E = {0}.
            current_valid_ = false;
            return m_ && a_.has(ExactVector::from_exact(adjugate_times(*m_, exact(e_))));
        }
        const auto inside = std::find_if(triangles_.begin(), triangles_.end(), [&](const std::array<Piece, 3>& t) {
            return has_piece(t[0]) && has_piece(t[1]) && has_piece(t[2]);
        });
        if (inside != triangles_.end()) {
            std::rotate(triangles_.begin(), inside, inside + 1);
            return true;
        }
        // The current plane: along a face's walk, only what changed since the previous cell.
        if (current_) {
            bool holds = holds_images(*current_);
            // (A cell the caller skips, one that joins the all-f mode, changes only contacts the
            // next cell of its face lists again; a new face starts over.)
            if (holds && current_valid_ && !cell_->first && cell_->face == last_face_) {
                for (int t : cell_->changed) holds = holds && holds_position(*current_, static_cast<std::size_t>(t));
            } else if (holds) {
                holds = holds_edges(*current_);  // (the images were checked above)
            }
            current_valid_ = holds;
            if (holds) return false;
        }
        if (cell_->closed.size() <= kSmallFace || groups_) {  // (a grouped face: a few generators)
            const auto found = std::find_if(planes_.begin(), planes_.end(), [&](const Plane& p) { return holds_cell(p); });
            if (found != planes_.end()) {
                current_ = *found;
                current_valid_ = true;
                std::rotate(planes_.begin(), found, found + 1);
                return false;
            }
        }
        if (groups_) {  // a few generators in place of the face's: no mend needed
            collect_images();
            for (const Generator& g : *groups_) generators_.push_back(g);
        } else {
            collect_generators();
        }
        if (!groups_ && cell_->closed.size() >= kMendFace) {
            scanned_ += generators_.size();
            if (const std::optional<bool> answer = mend()) {
                ++mended_;
                return *answer;
            }
        }
        if (std::optional<Plane> plane = wide_plane()) {
            keep_plane(std::move(*plane));
            return false;
        }
        return build();
    }

    // A mended certificate, the previous cell's kind first: the answer it gives, if one is.
    std::optional<bool> mend() {
        if (last_member_ && mend_triangle()) return true;
        if (mend_plane()) return false;
        if (!last_member_ && mend_triangle()) return true;
        return std::nullopt;
    }

    // The cell's generators: the twists' images, then each closed contact's edges (position t's
    // from first_[t]).
    void collect_generators() {
        collect_images();
        first_.clear();
        for (std::size_t t = 0; t < cell_->closed.size(); ++t) {
            first_.push_back(generators_.size());
            const int j = cell_->closed[t];
            edges_.for_contact(static_cast<std::size_t>(j), cell_->letters[t], [&](const ExactVector& edge, int slot) {
                generators_.push_back({&edge, edges_.rounded(static_cast<std::size_t>(j), slot), true, j, slot, nullptr});
                return true;
            });
        }
        first_.push_back(generators_.size());
    }
    // The twists' images, the first generators of the cell.
    void collect_images() {
        images_.clear();
        generators_.clear();
        if (!m_) return;
        for (const Exact3& r : *cell_->closure) images_.push_back(ExactVector::from_exact(r).transformed(*m_));
        for (std::size_t i = 0; i < images_.size(); ++i) {
            generators_.push_back({&images_[i], images_[i].approximation(), false, -1, 0, &(*cell_->closure)[i]});
        }
    }
    // det(a, b, c) for a, b given with their approximations and c a generator.
    static Sign det_of(const ExactVector& a, const ExactVector::Approximation& pa, const ExactVector& b,
                       const ExactVector::Approximation& pb, const Generator& c) {
        const Sign s = det_sign(a, b, *c.vector, pa, pb, c.rounded);
        return c.negate ? -s : s;
    }
    static Sign det_of(const Generator& a, const Generator& b, const Generator& c) {
        const Sign s = det_of(*a.vector, a.rounded, *b.vector, b.rounded, c);
        return a.negate != b.negate ? -s : s;
    }
    ExactVector vector_of(const Piece& p) const {
        if (p.contact < 0) return ExactVector::from_exact(p.twist).transformed(*m_);
        return edges_.edge(static_cast<std::size_t>(p.contact), p.slot).negated();
    }

    // The latest triangle, some of its pieces gone. With two left, a and b in the triangle's
    // cyclic order, a generator x of the cell in place of the third holds e when det(a, b, x) > 0,
    // det(e, b, x) >= 0 and det(a, e, x) >= 0 (det(e, a, b) >= 0 held before and does not involve
    // x). Else the bridge over e about each piece left, or about the cell's first generator when
    // none is (or E had no triangle: it was not pointed).
    bool mend_triangle() {
        std::array<Piece, 3> left{};
        std::size_t count = 0, gone = 0;
        if (!triangles_.empty()) {
            const std::array<Piece, 3>& t = triangles_.front();
            for (std::size_t k = 0; k < 3; ++k) {
                if (has_piece(t[k])) {
                    left[count++] = t[k];
                } else {
                    gone = k;
                }
            }
            // (in the triangle's cyclic order after the piece gone)
            if (count == 2 && gone == 1) std::swap(left[0], left[1]);
        }
        std::array<ExactVector, 2> kept;
        std::array<ExactVector::Approximation, 2> rounded;
        for (std::size_t k = 0; k < std::min<std::size_t>(count, 2); ++k) {
            kept[k] = vector_of(left[k]);
            rounded[k] = kept[k].approximation();
        }
        if (count == 2) {
            const ExactVector &a = kept[0], &b = kept[1];
            const ExactVector::Approximation re = wrench_.approximation();
            const auto completes = [&](const Generator& x) {
                return det_of(a, rounded[0], b, rounded[1], x) == Sign::Positive &&
                       det_of(wrench_, re, b, rounded[1], x) != Sign::Negative &&
                       det_of(a, rounded[0], wrench_, re, x) != Sign::Negative;
            };
            // (the contacts that changed first: along a face's walk the piece lost is theirs)
            const Generator* x = changed_generator(completes);
            if (!x) {
                const auto found = std::find_if(generators_.begin(), generators_.end(), completes);
                if (found != generators_.end()) x = &*found;
            }
            if (x) {
                keep_triangle({x->piece(), left[0], left[1]});
                return true;
            }
        }
        for (std::size_t k = 0; k < std::min<std::size_t>(count, 2); ++k) {
            if (bridge(kept[k], rounded[k], left[k])) return true;
        }
        if (count > 0 || generators_.empty()) return false;
        const Generator& first = generators_.front();
        const ExactVector p = first.negate ? first.vector->negated() : *first.vector;
        return bridge(p, p.approximation(), first.piece());
    }
    // A mended triangle in place of the latest one.
    void keep_triangle(const std::array<Piece, 3>& t) {
        if (triangles_.empty()) {
            triangles_.push_back(t);
        } else {
            triangles_.front() = t;
        }
    }

    // e in cone(p, x, y) for a generator p of the cell: the plane through p and e splits the
    // other generators into two sides, and e is in cone(p, x, y) for x, y on either side when the
    // plane through x and y leaves p and e on one side. The pair that leaves the most there is the
    // edge of E that the plane crosses beyond e; it is found as the bridge of two sets is, each
    // taken as the tangent from the other in turn (a few rounds, each one scan of the cell's
    // generators), and the triangle is then checked exactly.
    bool bridge(const ExactVector& p, const ExactVector::Approximation& rp, const Piece& name) {
        constexpr int kRounds = 4;
        const Generator pg{&p, rp, false, 0, 0, nullptr};
        const Generator eg{&wrench_, wrench_.approximation(), false, 0, 0, nullptr};
        sides_.clear();
        const Generator* x = nullptr;  // det(p, e, x) > 0
        const Generator* y = nullptr;  // det(p, e, y) < 0
        // About p, x and y start as the generators nearest e on either side: the plane through
        // them crosses the ray of e (not its opposite) if any such plane does.
        for (const Generator& g : generators_) {
            sides_.push_back(det_of(pg, eg, g));
            if (sides_.back() == Sign::Positive && (!x || det_of(pg, g, *x) == Sign::Positive)) x = &g;
            if (sides_.back() == Sign::Negative && (!y || det_of(pg, g, *y) == Sign::Negative)) y = &g;
        }
        if (!x || !y || det_of(pg, *x, *y) != Sign::Negative) return false;
        // The tangent from `from` to the generators on side `on`: z replaces `to` when the plane
        // through from and to has z and p on opposite sides.
        const auto tangent = [&](const Generator& from, const Generator*& to, Sign on) {
            bool moved = false;
            Sign at_p = det_of(from, *to, pg);
            for (std::size_t i = 0; i < generators_.size(); ++i) {
                const Generator& z = generators_[i];
                if (sides_[i] != on || &z == to || at_p == Sign::Zero) continue;
                if (det_of(from, *to, z) == -at_p) {
                    to = &z;
                    at_p = det_of(from, *to, pg);
                    moved = true;
                }
            }
            return moved;
        };
        for (int round = 0; round < kRounds; ++round) {
            const bool moved_y = tangent(*x, y, Sign::Negative);
            const bool moved_x = tangent(*y, x, Sign::Positive);
            if (!moved_x && !moved_y) break;
        }
        // e in cone(p, x, y): o = det(p, x, y) != 0, and det(e, x, y), det(p, e, y), det(p, x, e)
        // each of o's sign or 0.
        const Sign o = det_of(*x, *y, pg);
        if (o == Sign::Zero || det_of(*x, *y, eg) == -o || det_of(pg, eg, *y) == -o || det_of(pg, eg, *x) == o) return false;
        keep_triangle(o == Sign::Positive ? std::array<Piece, 3>{name, x->piece(), y->piece()}
                                          : std::array<Piece, 3>{name, y->piece(), x->piece()});
        return true;
    }

    // The first generator of a contact that changed since the previous cell (of this face) for
    // which `test` holds, if any.
    template <class Test>
    const Generator* changed_generator(Test test) const {
        if (cell_->first || cell_->face != last_face_) return nullptr;
        for (int t : cell_->changed) {
            const auto position = static_cast<std::size_t>(t);
            for (std::size_t i = first_[position]; i < first_[position + 1]; ++i) {
                if (test(generators_[i])) return &generators_[i];
            }
        }
        return nullptr;
    }

    // The current plane, broken by a generator g of the cell (one of the contacts that changed,
    // if any does): of the planes through g and another generator x, the two with every generator
    // on one side (found as gift wrapping finds its next edge, then checked exactly), one with e
    // strictly on the other side is the cell's plane.
    bool mend_plane() {
        if (!current_ || generators_.size() < 2) return false;
        const auto breaks = [&](const Generator& x) {
            const Sign s = side(*current_, *x.vector, x.rounded);
            return (x.negate ? -s : s) == Sign::Negative;
        };
        const Generator* g = changed_generator(breaks);
        if (!g) {
            const auto found = std::find_if(generators_.begin(), generators_.end(), breaks);
            if (found == generators_.end()) return false;
            g = &*found;
        }
        // The plane through g and x, turned so that e is on its negative side, when every
        // generator is on the other: h = side (g x x), h . y = side det(g, x, y) >= 0, h . e < 0.
        const Generator eg{&wrench_, wrench_.approximation(), false, 0, 0, nullptr};
        const auto through = [&](const Generator& x) {
            const Sign side = -det_of(*g, x, eg);
            if (side == Sign::Zero) return false;
            if (!std::all_of(generators_.begin(), generators_.end(), [&](const Generator& y) { return det_of(*g, x, y) != -side; })) {
                return false;
            }
            const int sign = (side == Sign::Positive ? 1 : -1) * (g->negate != x.negate ? -1 : 1);
            Plane plane = plane_of(ExactVector::cross(*g->vector, *x.vector, sign));
            plane.u = *g->vector;
            plane.v = *x.vector;
            plane.ru = g->rounded;
            plane.rv = x.rounded;
            plane.sign = sign;
            keep_plane(std::move(plane));
            return true;
        };
        // First about the generators the broken plane went through (the plane turns about one of
        // them along a face's walk), then about every generator: hi with det(g, hi, y) >= 0 for
        // every generator y if any has, lo with det(g, lo, y) <= 0 (one scan for both).
        if (current_->sign != 0) {
            const Plane old = *current_;
            if (through(Generator{&old.u, old.ru, false, 0, 0, nullptr}) || through(Generator{&old.v, old.rv, false, 0, 0, nullptr})) {
                return true;
            }
        }
        const Generator* hi = nullptr;
        const Generator* lo = nullptr;
        for (const Generator& y : generators_) {
            if (!hi) {
                if (!parallel(*g->vector, *y.vector)) hi = lo = &y;
                continue;
            }
            if (det_of(*g, *hi, y) == Sign::Negative) hi = &y;
            if (det_of(*g, *lo, y) == Sign::Positive) lo = &y;
        }
        return hi && (through(*hi) || through(*lo));
    }

    // e against E (its extreme rays from its generators); a new certificate either way.
    bool build() {
        ++built_;
        if (groups_) ++grouped_;
        // The cell's generators as collect_generators lists them (each named there, for a
        // triangle that needs it).
        std::vector<ExactVector> generators;
        generators.reserve(generators_.size());
        for (const Generator& g : generators_) generators.push_back(g.negate ? g.vector->negated() : *g.vector);
        // Its facets are not built: only the one that separates, if any (cone_holds).
        tested_ += generators.size();
        const Held held = cone_holds(generators, e_);
        if (held.member) {
            if (held.triangle) remember_triangle(*held.triangle, generators);
            return true;
        }
        // A facet or equation of E with h . e < 0 (one exists: e is outside E).
        keep_plane(plane_of(held.separator));
        return false;
    }

    // A plane h in doubles with h . e < 0 and h . g >= 0 for every generator g of the cell, kept
    // only when exactly checked: near the widest such plane, found in doubles as the point x of
    // the hull of -e/|e| and the g/|g| nearest the origin (max over |h| = 1 of the least
    // h . p is |x|, at h = x/|x|), by a few steps of Gilbert's algorithm. A facet of E has
    // generators on it, which the generators of the next cell, turned a little, may cross; on
    // the cradle of 10^5 contacts such planes made one walk build E 8 times as often.
    std::optional<Plane> wide_plane() const {
        // (e scaled by a power of two first, so that |e|^2 neither underflows nor overflows)
        const double largest = e_.cwiseAbs().maxCoeff();
        if (!(largest > 0) || !std::isfinite(largest)) return std::nullopt;
        const Vec3 e = e_ * std::ldexp(1.0, -std::ilogb(largest));
        std::vector<Vec3>& points = points_;
        points.clear();
        points.push_back(-e / e.norm());
        for (const Generator& g : generators_) {
            const Vec3& a = g.rounded.approx;
            const double norm = a.norm();
            if (!(norm > 0) || !std::isfinite(norm)) continue;  // (zero, or out of range: the check decides)
            points.push_back(g.negate ? Vec3(-a / norm) : Vec3(a / norm));
        }
        // Each coordinate times a power of two s_k that brings its largest |p_k| to [1, 2), then
        // each point back to unit length: a scene 2^-40 long has torques 2^-40 times its forces,
        // and in the points as they are the widest plane's margin is about 2^-40 (turned down
        // below: one query on the tangent of 10^5 contacts then built E from 2 x 10^5 edges).
        // x found among the scaled points gives h = S x (h . g = x . S g, exactly).
        Vec3 scale = Vec3::Ones();
        for (int k = 0; k < 3; ++k) {
            double top = 0;
            for (const Vec3& p : points) top = std::max(top, std::fabs(p[k]));
            if (top > 0 && std::isnormal(top)) scale[k] = std::ldexp(1.0, -std::ilogb(top));
        }
        if (scale != Vec3::Ones()) {
            for (Vec3& p : points) {
                p = p.cwiseProduct(scale);
                p /= p.norm();
            }
        }
        Vec3 x = points.front();
        for (int step = 0; step < kWideSteps; ++step) {
            const Vec3* nearest = &points.front();
            double least = x.dot(*nearest);
            for (const Vec3& p : points) {
                const double d = x.dot(p);
                if (d < least) {
                    least = d;
                    nearest = &p;
                }
            }
            const double xx = x.squaredNorm();
            if (least >= 0.9 * xx) break;  // within 10% of the widest margin
            const Vec3 d = *nearest - x;
            x += std::clamp(-x.dot(d) / d.squaredNorm(), 0.0, 1.0) * d;
        }
        if (!(x.squaredNorm() > 1e-20)) return std::nullopt;
        const Vec3 h = x.cwiseProduct(scale);
        if (!h.allFinite()) return std::nullopt;
        Plane plane = plane_of(ExactVector::input(h));
        if (dot_sign(plane.h, wrench_) != Sign::Negative || !holds_cell(plane)) return std::nullopt;
        return plane;
    }

    // p as the current plane, and first in the cache.
    void keep_plane(Plane p) {
        current_ = std::move(p);
        current_valid_ = true;
        planes_.insert(planes_.begin(), *current_);
        if (planes_.size() > kCache) planes_.pop_back();
    }

    // Keeps three generators of E whose cone holds e (corners: indices into generators, which
    // are generators_ made vectors), named.
    void remember_triangle(const std::array<std::size_t, 3>& corners, const std::vector<ExactVector>& generators) {
        std::array<Piece, 3> t;
        for (std::size_t corner = 0; corner < 3; ++corner) t[corner] = generators_[corners[corner]].piece();
        // Kept only when exactly checked: det(a, b, c) > 0 and w on the inner side of each face.
        const ExactVector &a = generators[corners[0]], &b = generators[corners[1]], &c = generators[corners[2]];
        if (det_sign(a, b, c) == Sign::Positive && det_sign(wrench_, b, c) != Sign::Negative &&
            det_sign(a, wrench_, c) != Sign::Negative && det_sign(a, b, wrench_) != Sign::Negative) {
            triangles_.insert(triangles_.begin(), t);
            if (triangles_.size() > kCache) triangles_.pop_back();
        }
    }

    const Cone& a_;
    const std::optional<ExactMatrix>& m_;
    const FrictionEdges& edges_;
    Vec3 e_;
    ExactVector wrench_;
    const detail::WalkCell* cell_ = nullptr;
    TwistFilters* filters_ = nullptr;
    const std::vector<Generator>* groups_ = nullptr;  // the cell's -T reduced, when its face is grouped
    std::optional<Plane> current_;
    bool current_valid_ = false;  // the current plane held every generator of the previous cell
    bool last_member_ = false;    // the previous cell's answer
    std::vector<ExactVector> images_;     // this cell's M r
    std::vector<Generator> generators_;  // this cell's generators (for the mends and build)
    std::vector<std::size_t> first_;     // position t's first generator in generators_
    std::vector<Sign> sides_;            // a bridge's side of each generator
    mutable std::vector<Vec3> points_;   // wide_plane's unit vectors
    std::size_t last_face_ = static_cast<std::size_t>(-1);  // that cell's face
    std::vector<Plane> planes_;
    std::vector<std::array<Piece, 3>> triangles_;
    std::size_t built_ = 0;
    std::size_t tested_ = 0;  // generators of the E's tested
    std::size_t mended_ = 0;   // cells decided by a mended certificate
    std::size_t scanned_ = 0;  // generators of the cells whose certificate a mend tried
    std::size_t grouped_ = 0;  // cells decided with a grouped face's generators
};

// The all-f mode's E once its closure (the twists of the cells merged into it) is known: the
// images M g of those twists and -T of every contact fixed; kept for membership tests only
// (its extreme rays, not its 2n facets, when it is pointed and full-dimensional).
HeldCone fixed_applied(const std::optional<ExactMatrix>& m, const FrictionEdges& edges, const std::vector<Exact3>& closure) {
    std::vector<ExactVector> generators;
    generators.reserve((m ? closure.size() : 0) + 2 * edges.statics.size());
    if (m) {
        for (const Exact3& g : closure) generators.push_back(ExactVector::from_exact(g).transformed(*m));
    }
    for (const auto& pair : edges.statics) {
        for (const ExactVector& edge : pair) generators.push_back(edge.negated());
    }
    return HeldCone(std::move(generators));
}

}  // namespace

struct SceneQuestions::State {
    State(const Scene& scene, const AnalysisOptions& options)
        : m(inertia_of(scene, options, "query_scene")),
          n((detail::check_contacts(scene.contacts), scene.contacts.size())),
          progress(options.progress) {
        // The walk's set-up (A, its faces and their closed contacts) and the friction edges
        // need nothing of each other: on two threads for large scenes.
        const bool large = n >= kTwoThreadContacts;
        std::optional<detail::ModeWalk> w;
        std::optional<FrictionEdges> e;
        detail::for_each_index(2, large, [&](std::size_t task) {
            if (task == 0) {
                w.emplace(scene.contacts);
            } else {
                e.emplace(scene.contacts, !large);
            }
        });
        walk = std::move(*w);
        edges = std::move(*e);
    }

    std::optional<ExactMatrix> m;
    std::size_t n;
    detail::ModeWalk walk{{}};
    FrictionEdges edges{{}};
    Progress progress;
    // After the first answer: the twists of the cells that join the all-f mode; from the second,
    // that mode's E (built once; every answer then tests e against it).
    std::shared_ptr<const std::vector<Exact3>> fixed_closure;
    std::optional<HeldCone> fixed_cone;
};

SceneQuestions::SceneQuestions(const Scene& scene, const AnalysisOptions& options)
    : state_(std::make_unique<State>(scene, options)) {}
SceneQuestions::~SceneQuestions() = default;
SceneQuestions::SceneQuestions(SceneQuestions&&) noexcept = default;
SceneQuestions& SceneQuestions::operator=(SceneQuestions&&) noexcept = default;

std::size_t SceneQuestions::modes_at_least() const { return state_->walk.modes_at_least(); }

SceneAnswer SceneQuestions::answer(const Vec3& e) { return std::move(answer(std::span<const Vec3>(&e, 1)).front()); }

std::vector<SceneAnswer> SceneQuestions::answer(std::span<const Vec3> wrenches) {
    std::vector<SceneAnswer> answers;
    answers.reserve(wrenches.size());
    answer(wrenches, [&](SceneAnswer&& a) { answers.push_back(std::move(a)); });
    return answers;
}

void SceneQuestions::answer(std::span<const Vec3> wrenches, const std::function<void(SceneAnswer&&)>& take) {
    for (const Vec3& e : wrenches) {
        if (!e.allFinite()) throw std::invalid_argument("query_scene: the wrench must be finite");
    }
    State& s = *state_;
    const std::size_t n = s.n;
    const std::size_t q = wrenches.size();
    const detail::ModeWalk& walk = s.walk;
    const std::optional<ExactMatrix>& m = s.m;
    // The all-f mode (xi = 0 and the cells whose letters are all 'f') is decided apart, when its
    // closure is complete; the others as the walk meets them. Its E holds -T for every contact
    // fixed (2n generators): decided as one task, at the first answer first without the twists
    // of merged cells (a wrench in that smaller cone is in E whatever they are). The faces are
    // walked in parts of consecutive faces, each part a task with certificates of its own (so
    // that what a part finds does not depend on which thread took the parts before it); the
    // tasks share two threads, handed out one at a time: on the cradle of 10^5 contacts the
    // first half of the faces took 1.04 s and the second 0.15 s. Every wrench of the batch has
    // its own deciders (their certificates are the wrench's) and sees every cell of the one walk. A mode that a wrench produces is kept as the walk gives it
    // (its closed contacts and their letters, not n letters), once for all the wrenches that
    // produce it: a batch holds its answers' letters only one answer at a time.
    struct Kept {
        bool whole;               // letters holds all n letters (no bigger than the closed ones)
        std::vector<int> closed;  // else the closed contacts
        std::string letters;      // and their letters
        std::vector<Exact3> closure;  // empty for the interior of A (no contact closed): A itself
    };
    struct Member {
        std::size_t face, index;           // index within the face (0: the all-f mode)
        std::shared_ptr<Kept> mode;  // null for the all-f mode
    };
    struct Part {
        std::vector<std::vector<Member>> members;  // per wrench
        std::vector<std::size_t> built, tested, mended, scanned, grouped;  // per wrench
        std::vector<Exact3> fixed_closure;
        std::size_t closed_letters = 0;
    };
    const bool large = n >= kTwoThreadContacts;
    std::vector<Part> parts(large ? std::clamp<std::size_t>(walk.faces(), 1, kWalkParts) : 1);
    std::atomic<std::size_t> faces_done{0};
    std::vector<std::size_t> counts(walk.faces());
    std::vector<int> everyone(n);
    std::iota(everyone.begin(), everyone.end(), 0);
    const std::vector<char> fixed(n, letter(ContactMode::Fixed));
    std::vector<Decider> fixed_deciders;
    fixed_deciders.reserve(q);
    for (const Vec3& e : wrenches) fixed_deciders.emplace_back(walk.feasible_twists(), m, s.edges, e);
    const auto fixed_member = [&](std::size_t k, const std::vector<Exact3>& closure) {
        detail::WalkCell cell;
        cell.closure = &closure;
        cell.closed = everyone;
        cell.letters = fixed;
        TwistFilters filters;
        return fixed_deciders[k].member(cell, filters);
    };
    std::vector<char> fixed_holds(q, 0);
    std::optional<HeldCone> fixed_edges;  // a first batch's E of the all-f mode without the twists
    bool fixed_built = false;
    std::size_t fixed_tested = 0;
    // The twists of the cells that join the all-f mode are the same at every answer: collected
    // at the first only.
    const bool closure_known = s.fixed_closure != nullptr;
    const std::thread::id caller = std::this_thread::get_id();
    detail::for_each_index(1 + parts.size(), large, [&](std::size_t task) {
        if (task == 0) {
            if (closure_known && n > 0) {  // a later answer: the mode's E, built once
                if (!s.fixed_cone) {
                    s.fixed_cone = fixed_applied(m, s.edges, *s.fixed_closure);
                    fixed_built = true;
                    fixed_tested = (m ? s.fixed_closure->size() : 0) + 2 * n;
                }
                for (std::size_t k = 0; k < q; ++k) fixed_holds[k] = s.fixed_cone->holds(wrenches[k]).member;
            } else if (q == 1 || n == 0) {
                for (std::size_t k = 0; k < q; ++k) fixed_holds[k] = fixed_member(k, {});
            } else {  // a first batch: the cone of the fixed edges alone, built once for all
                fixed_edges.emplace(fixed_applied(m, s.edges, {}));
                fixed_built = true;
                fixed_tested = 2 * n;
                for (std::size_t k = 0; k < q; ++k) fixed_holds[k] = fixed_edges->holds(wrenches[k]).member;
            }
            return;
        }
        Part& part = parts[task - 1];
        std::vector<Decider> deciders;
        deciders.reserve(q);
        for (const Vec3& e : wrenches) deciders.emplace_back(walk.feasible_twists(), m, s.edges, e);
        part.members.resize(q);
        TwistFilters filters;
        GroupedEdges groups(s.edges);
        const std::size_t begin = walk.faces() * (task - 1) / parts.size(), end = walk.faces() * task / parts.size();
        // Progress from the calling thread only (the callback need not be thread-safe), by parts
        // when there are several, else face by face.
        const bool reports = s.progress && std::this_thread::get_id() == caller;
        walk.run_faces(begin, end, reports && parts.size() == 1 ? s.progress : Progress(), counts, [&](const detail::WalkCell& cell) {
            groups.next_cell(cell);
            if (cell.index == 0) {  // (its letters are counted once, as the all-f mode's)
                if (!closure_known) part.fixed_closure.insert(part.fixed_closure.end(), cell.closure->begin(), cell.closure->end());
                return;
            }
            part.closed_letters += cell.closed.size();
            filters.next_cell();
            std::shared_ptr<Kept> kept;  // made for the first wrench the mode holds
            for (std::size_t k = 0; k < q; ++k) {
                if (!deciders[k].member(cell, filters, &groups)) continue;
                if (!kept && cell.closed.size() * (sizeof(int) + 1) >= n) {  // (a face that closes most contacts)
                    kept = std::make_shared<Kept>(Kept{true, {}, cell.all_letters(n), *cell.closure});
                } else if (!kept) {
                    kept = std::make_shared<Kept>(Kept{false,
                                                       {cell.closed.begin(), cell.closed.end()},
                                                       {cell.letters.begin(), cell.letters.end()},
                                                       cell.closed.empty() ? std::vector<Exact3>() : *cell.closure});
                }
                part.members[k].push_back({cell.face, cell.index, kept});
            }
        });
        for (const Decider& decider : deciders) {
            part.built.push_back(decider.built());
            part.tested.push_back(decider.tested());
            part.mended.push_back(decider.mended());
            part.scanned.push_back(decider.scanned());
            part.grouped.push_back(decider.grouped());
        }
        faces_done += end - begin;
        if (reports && parts.size() > 1) s.progress("faces of the cone of motions", faces_done, walk.faces());
    });
    // Face i's modes come after those of the faces before it.
    std::vector<std::size_t> first_index(counts.size());
    std::size_t total = 1;
    for (std::size_t i = 0; i < counts.size(); ++i) {
        first_index[i] = total;
        total += counts[i];
    }
    if (!closure_known) {
        std::vector<Exact3> fixed_closure;
        for (const Part& part : parts) fixed_closure.insert(fixed_closure.end(), part.fixed_closure.begin(), part.fixed_closure.end());
        if (fixed_edges && (!m || fixed_closure.empty())) {
            s.fixed_cone = std::move(fixed_edges);  // the whole E: no twist joins it
        } else if (fixed_edges) {
            const bool undecided = std::find(fixed_holds.begin(), fixed_holds.end(), 0) != fixed_holds.end();
            if (undecided) {
                s.fixed_cone = fixed_applied(m, s.edges, fixed_closure);
                fixed_tested += fixed_closure.size() + 2 * n;
                for (std::size_t k = 0; k < q; ++k) fixed_holds[k] = fixed_holds[k] || s.fixed_cone->holds(wrenches[k]).member;
            }
        } else {
            for (std::size_t k = 0; k < q; ++k) {
                if (!fixed_holds[k] && m && !fixed_closure.empty()) fixed_holds[k] = fixed_member(k, fixed_closure);
            }
        }
        s.fixed_closure = std::make_shared<const std::vector<Exact3>>(std::move(fixed_closure));
    }
    // The modes' indices in enumerate_modes' order, and how many answers of the batch hold each:
    // a mode's cone of twists is built once and kept only while a later answer still needs it
    // (the copies share its exact coordinates).
    std::map<std::size_t, std::size_t> uses;
    for (std::size_t k = 0; k < q; ++k) {
        if (fixed_holds[k]) ++uses[0];
    }
    for (Part& part : parts) {
        for (std::vector<Member>& list : part.members) {
            for (Member& member : list) {
                member.index = first_index[member.face] + member.index - 1;
                ++uses[member.index];
            }
        }
    }
    std::map<std::size_t, Cone> twist_cones;
    const auto twists_of = [&](std::size_t index, const std::vector<Exact3>& closure) {
        const std::size_t left = --uses[index];
        if (closure.empty() && index != 0) return walk.feasible_twists();  // the interior of A
        const auto kept = twist_cones.find(index);
        if (kept != twist_cones.end()) {
            if (left > 0) return kept->second;
            Cone cone = std::move(kept->second);
            twist_cones.erase(kept);
            return cone;
        }
        std::vector<ExactVector> gens;
        gens.reserve(closure.size());
        for (const Exact3& g : closure) gens.push_back(ExactVector::from_exact(g));
        Cone cone = Cone::from_generators(gens);
        if (left > 0) twist_cones.emplace(index, cone);
        return cone;
    };
    for (std::size_t k = 0; k < q; ++k) {
        SceneAnswer out;
        out.mode_count = total;
        std::vector<Member> members;
        if (fixed_holds[k]) members.push_back({0, 0, nullptr});
        for (Part& part : parts) {
            members.insert(members.end(), part.members[k].begin(), part.members[k].end());
            part.members[k] = {};
        }
        std::sort(members.begin(), members.end(), [](const Member& a, const Member& b) { return a.index < b.index; });
        for (Member& member : members) {
            // (a mode's letters moved out of it by the last answer that holds it: this one when no
            // other answer's list still shares it)
            const bool last = member.mode && member.mode.use_count() == 1;
            std::string letters = !member.mode        ? std::string(n, letter(ContactMode::Fixed))
                                  : member.mode->whole ? (last ? std::move(member.mode->letters) : member.mode->letters)
                                                       : detail::all_letters(member.mode->closed, member.mode->letters, n);
            out.result.modes.push_back(member.index);
            out.modes.push_back(Mode{std::move(letters), twists_of(member.index, member.mode ? member.mode->closure : *s.fixed_closure)});
        }
        // The all-f mode's E counts once however many times its decider built it (and, built for
        // the batch, with the batch's first answer).
        const bool built_here = fixed_deciders[k].built() > 0 || (fixed_built && k == 0);
        out.built = (built_here ? 1 : 0);
        out.tested_generators = fixed_deciders[k].tested() + (k == 0 ? fixed_tested : 0);
        out.mended = fixed_deciders[k].mended();
        out.scanned_generators = fixed_deciders[k].scanned();
        out.closed_letters = n;
        for (const Part& part : parts) {
            out.built += part.built[k];
            out.tested_generators += part.tested[k];
            out.mended += part.mended[k];
            out.scanned_generators += part.scanned[k];
            out.grouped += part.grouped[k];
            out.closed_letters += part.closed_letters;
        }
        out.result.verdict = verdict_of(out.result.modes.size());
        take(std::move(out));
    }
}

SceneAnswer query_scene(const Scene& scene, const Vec3& e, const AnalysisOptions& options) {
    if (!e.allFinite()) throw std::invalid_argument("query_scene: the wrench must be finite");
    return SceneQuestions(scene, options).answer(e);
}

const char* to_string(Verdict v) {
    switch (v) {
        case Verdict::Unique: return "unique";
        case Verdict::Ambiguous: return "ambiguous";
        default: return "inconsistent";
    }
}

QueryResult query(const std::vector<ModeForces>& analysis, const Vec3& e) {
    if (!e.allFinite()) throw std::invalid_argument("query: the wrench must be finite");
    QueryResult r;
    for (std::size_t i = 0; i < analysis.size(); ++i) {
        if (analysis[i].applied.has(e)) r.modes.push_back(i);
    }
    r.verdict = verdict_of(r.modes.size());
    return r;
}

}  // namespace momentlab
