// analyze and query (mechanics/analysis.hpp): every mode's F, T and E, and the modes whose
// closed E holds an applied wrench.
#include "momentlab/mechanics/analysis.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "momentlab/core/parallel.hpp"
#include "momentlab/geometry/force_sets.hpp"
#include "checks.hpp"

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

// Each contact's friction edges, built once for all the modes (exact constructions; copies
// share them): the static cone's two edges, and the kinetic ones n + mu_k t, n - mu_k t.
struct FrictionEdges {
    std::vector<std::array<ExactVector, 2>> statics, kinetics;

    explicit FrictionEdges(const std::vector<Contact>& contacts) {
        for (const Contact& c : contacts) {
            statics.push_back(friction_cone_edges(c.point, c.normal, c.mu));
            kinetics.push_back(c.mu_kinetic == c.mu ? statics.back() : friction_cone_edges(c.point, c.normal, c.mu_kinetic));
        }
    }

    // Calls f(edge) for each generator of the contact cone T of a mode: both static edges of an
    // f contact, n - mu_k t of an r contact (friction opposes sliding along +t), n + mu_k t of an l.
    template <class F>
    void for_each(const Mode& mode, F f) const {
        for (std::size_t j = 0; j < statics.size(); ++j) {
            switch (mode.letters[j]) {
                case 'f': f(statics[j][0]), f(statics[j][1]); break;
                case 'r': f(kinetics[j][1]); break;
                case 'l': f(kinetics[j][0]); break;
                default: break;
            }
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
// contact j's friction edge `slot` (0, 1 static; 2, 3 kinetic, as FrictionEdges), negated, or
// the image M r of a twist r (contact < 0).
struct Piece {
    int contact = -1;
    int slot = 0;
    ExactVector twist;
};

// The slot of contact j's edge in a mode with letter `letter` ('r' or 'l'); the kinetic edges
// are the static ones when mu_k = mu.
int sliding_slot(const Contact& c, char letter) {
    const int side = letter == 'r' ? 1 : 0;
    return c.mu_kinetic == c.mu ? side : side + 2;
}

bool has_piece(const Scene& scene, const Mode& mode, const Piece& p) {
    if (p.contact < 0) return mode.twists.has(p.twist);
    const auto j = static_cast<std::size_t>(p.contact);
    const char letter = mode.letters[j];
    if (letter == 'f') return p.slot < 2;
    return (letter == 'r' || letter == 'l') && p.slot == sliding_slot(scene.contacts[j], letter);
}

// Three generators of the full-dimensional pointed cone c whose cone holds w (a fan from ray 0;
// w in c), as indices into c.rays().
std::array<std::size_t, 3> fan_triangle(const Cone& c, const ExactVector& w) {
    const auto& r = c.rays();
    for (std::size_t i = 1; i + 1 < r.size(); ++i) {
        if (det_sign(r[0], r[i], w) != Sign::Negative && det_sign(r[0], r[i + 1], w) != Sign::Positive) return {0, i, i + 1};
    }
    return {0, 1, r.size() - 1};
}

}  // namespace

SceneAnswer query_scene(const Scene& scene, const Vec3& e, const AnalysisOptions& options) {
    if (!e.allFinite()) throw std::invalid_argument("query_scene: the wrench must be finite");
    const std::optional<ExactMatrix> m = inertia_of(scene, options, "query_scene");
    SceneAnswer out{enumerate_modes(scene.contacts, options.progress), {}};
    const FrictionEdges edges(scene.contacts);
    const ExactVector wrench = ExactVector::input(e);
    // Two caches of certificates from modes decided before, the latest that worked first
    // (neighbouring modes share most generators):
    //  - planes h with h . e < 0 that held every generator of an earlier E on their side; one
    //    that holds every generator of this E too proves e is not in it (Farkas). Each keeps
    //    the contact that last broke it, tried first.
    //  - three generators of an earlier E whose cone holds e; when this E has all three, e is
    //    in it.
    struct Plane {
        ExactVector h;
        std::size_t hint = 0;
    };
    constexpr std::size_t kCache = 8;
    const std::size_t count = out.modes.modes.size();
    const std::size_t n = scene.contacts.size();
    // The modes in two halves on two threads when there is enough to do (as analyze), each half
    // with its own caches; the answers joined in order.
    struct Part {
        std::vector<std::size_t> members;
        std::size_t built = 0;
    };
    const bool large = count * n >= 2000;
    std::vector<Part> parts(large ? 2 : 1);
    const std::thread::id caller = std::this_thread::get_id();
    detail::for_each_index(parts.size(), large, [&](std::size_t k) {
        Part& part = parts[k];
        std::vector<Plane> planes;
        std::vector<std::array<Piece, 3>> triangles;
        const std::size_t begin = count * k / parts.size(), end = count * (k + 1) / parts.size();
        for (std::size_t i = begin; i < end; ++i) {
            if (options.progress && std::this_thread::get_id() == caller) options.progress("modes tested", i - begin, end - begin);
            const Mode& mode = out.modes.modes[i];
            if (is_zero(e)) {  // in every closed cone
                part.members.push_back(i);
                continue;
            }
            const auto inside = std::find_if(triangles.begin(), triangles.end(), [&](const std::array<Piece, 3>& t) {
                return has_piece(scene, mode, t[0]) && has_piece(scene, mode, t[1]) && has_piece(scene, mode, t[2]);
            });
            if (inside != triangles.end()) {
                std::rotate(triangles.begin(), inside, inside + 1);
                part.members.push_back(i);
                continue;
            }
            // E = M A + (-T): the images of the twists' generators, then minus the contact edges.
            std::vector<ExactVector> generators;
            std::vector<Piece> pieces;
            if (m) {
                const auto image = [&](const ExactVector& r) {
                    generators.push_back(r.transformed(*m));
                    pieces.push_back(Piece{-1, 0, r});
                };
                for (const ExactVector& r : mode.twists.rays()) image(r);
                for (const ExactVector& l : mode.twists.lineality()) image(l), image(l.negated());
            }
            const std::size_t images = generators.size();
            // Does h hold contact j's generators in this mode on its side (h . -edge >= 0)?
            const auto holds_contact = [&](const ExactVector& h, std::size_t j) {
                switch (mode.letters[j]) {
                    case 'f':
                        return dot_sign(h, edges.statics[j][0]) != Sign::Positive && dot_sign(h, edges.statics[j][1]) != Sign::Positive;
                    case 'r': return dot_sign(h, edges.kinetics[j][1]) != Sign::Positive;
                    case 'l': return dot_sign(h, edges.kinetics[j][0]) != Sign::Positive;
                    default: return true;
                }
            };
            const auto separates = [&](Plane& p) {
                for (std::size_t g = 0; g < images; ++g) {
                    if (dot_sign(p.h, generators[g]) == Sign::Negative) return false;
                }
                if (p.hint < n && !holds_contact(p.h, p.hint)) return false;
                for (std::size_t j = 0; j < n; ++j) {
                    if (!holds_contact(p.h, j)) {
                        p.hint = j;
                        return false;
                    }
                }
                return true;
            };
            const auto found = std::find_if(planes.begin(), planes.end(), separates);
            if (found != planes.end()) {
                std::rotate(planes.begin(), found, found + 1);
                continue;
            }
            for (std::size_t j = 0; j < n; ++j) {
                const char letter = mode.letters[j];
                if (letter == 'f') {
                    for (int slot = 0; slot < 2; ++slot) {
                        generators.push_back(edges.statics[j][static_cast<std::size_t>(slot)].negated());
                        pieces.push_back(Piece{static_cast<int>(j), slot, {}});
                    }
                } else if (letter == 'r' || letter == 'l') {
                    generators.push_back(edges.kinetics[j][letter == 'r' ? 1 : 0].negated());
                    pieces.push_back(Piece{static_cast<int>(j), sliding_slot(scene.contacts[j], letter), {}});
                }
            }
            const Cone applied = Cone::from_generators(generators);
            ++part.built;
            if (applied.has(e)) {
                part.members.push_back(i);
                if (applied.dimension() == 3 && applied.is_pointed()) {
                    // Name the three rays by generators pointing the same way (each ray is one).
                    std::array<Piece, 3> t;
                    bool named = true;
                    const auto corners = fan_triangle(applied, wrench);
                    for (std::size_t corner = 0; corner < 3 && named; ++corner) {
                        const ExactVector& ray = applied.rays()[corners[corner]];
                        const auto g = std::find_if(generators.begin(), generators.end(), [&](const ExactVector& v) {
                            return parallel(v, ray) && dot_sign(v, ray) == Sign::Positive;
                        });
                        named = g != generators.end();
                        if (named) t[corner] = pieces[static_cast<std::size_t>(g - generators.begin())];
                    }
                    // Kept only when exactly checked: det(a, b, c) > 0 and w on the inner side of each face.
                    const auto in_triangle = [&] {
                        const ExactVector &a = applied.rays()[corners[0]], &b = applied.rays()[corners[1]], &c = applied.rays()[corners[2]];
                        return det_sign(a, b, c) == Sign::Positive && det_sign(wrench, b, c) != Sign::Negative &&
                               det_sign(a, wrench, c) != Sign::Negative && det_sign(a, b, wrench) != Sign::Negative;
                    };
                    if (named && in_triangle()) {
                        triangles.insert(triangles.begin(), t);
                        if (triangles.size() > kCache) triangles.pop_back();
                    }
                }
                continue;
            }
            // A facet or equation of E with h . e < 0 (one exists: e is outside E).
            const Membership why = applied.contains(e);
            assert(!why.member);
            planes.insert(planes.begin(), Plane{why.separator, 0});
            if (planes.size() > kCache) planes.pop_back();
        }
    });
    for (const Part& part : parts) {
        out.result.modes.insert(out.result.modes.end(), part.members.begin(), part.members.end());
        out.built += part.built;
    }
    out.result.verdict = verdict_of(out.result.modes.size());
    return out;
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
