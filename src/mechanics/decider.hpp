// The walk's decider (query_scene, SceneQuestions): whether an applied wrench lies in each cell's
// E, by certificates kept from the cells before, mended, or found anew. Internal to the
// mechanics layer.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/geometry/cone.hpp"
#include "../geometry/held_cone.hpp"
#include "friction_edges.hpp"
#include "generators.hpp"
#include "grouped_edges.hpp"
#include "mode_walk.hpp"

namespace momentlab::detail {

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
    // e exact (a decimal wrench need not be doubles); e_ its rounding, for the wide plane's
    // guess only (every plane is then checked against e exactly).
    Decider(const Cone& a, const std::optional<ExactMatrix>& m, const FrictionEdges& edges, const ExactVector& e)
        : a_(a), m_(m), edges_(edges), e_(e.value()), wrench_(e) {}

    [[nodiscard]] std::size_t built() const { return built_; }
    [[nodiscard]] std::size_t tested() const { return tested_; }
    [[nodiscard]] std::size_t mended() const { return mended_; }
    [[nodiscard]] std::size_t scanned() const { return scanned_; }
    [[nodiscard]] std::size_t grouped() const { return grouped_; }

    // `filters` holds this cell's twists rounded (shared by the deciders of a batch).
    // `groups`, when given, follows the walk (its reduced generators are this cell's).
    bool member(const WalkCell& cell, TwistFilters& filters, const GroupedEdges* groups = nullptr) {
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

    // h holds every generator of the cell's E.
    bool holds_cell(const Plane& p) const { return holds_images(p) && holds_edges(p); }

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

    Plane plane_of(const ExactVector& h) const;
    bool holds_images(const Plane& p) const;
    bool holds_position(const Plane& p, std::size_t t) const;
    bool holds_edges(const Plane& p) const;
    char letter_of_contact(int j) const;
    bool has_piece(const Piece& p) const;
    bool decide();
    std::optional<bool> mend();
    void collect_generators();
    void collect_images();
    ExactVector vector_of(const Piece& p) const;
    bool mend_triangle();
    void keep_triangle(const std::array<Piece, 3>& t);
    bool bridge(const ExactVector& p, const ExactVector::Approximation& rp, const Piece& name);
    template <class Test> const Generator* changed_generator(Test test) const;
    bool mend_plane();
    bool build();
    std::optional<Plane> wide_plane() const;
    void keep_plane(Plane p);
    void remember_triangle(const std::array<std::size_t, 3>& corners, const std::vector<ExactVector>& generators);

    const Cone& a_;
    const std::optional<ExactMatrix>& m_;
    const FrictionEdges& edges_;
    Vec3 e_;
    ExactVector wrench_;
    const WalkCell* cell_ = nullptr;
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

}  // namespace momentlab::detail
