#pragma once

// Membership in cone(generators) without the cone's double description (held_cone.cpp). Its
// user is mechanics (the E of the all-f mode in SceneQuestions, src/mechanics/analysis.cpp),
// which includes this header of the geometry layer's; it is no part of the public API.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/core/vec.hpp"
#include "momentlab/geometry/cone.hpp"

namespace momentlab {

/// Whether cone(generators) holds w, with a certificate, without the double description when
/// the cone is pointed and full-dimensional: its extreme rays are found in cyclic order (as by
/// Cone::from_generators) but its facets are not built, which saves an exact construction per
/// facet; w is tested against each facet as det(r_i, r_i+1, w). Other cones are built.
struct Held {
    bool member = false;
    /// For non-members: a facet normal or +-an equation h of the cone, with h . w < 0.
    ExactVector separator;
    /// For members of a pointed full-dimensional cone: three generators (indices into the
    /// argument) whose cone holds w.
    std::optional<std::array<std::size_t, 3>> triangle;
};
[[nodiscard]] Held cone_holds(std::span<const ExactVector> generators, const Vec3& w);
[[nodiscard]] Held cone_holds(std::span<const ExactVector> generators, const ExactVector& w);

/// cone(generators) kept for membership tests of many wrenches, found once as cone_holds finds
/// it: a pointed full-dimensional cone as its extreme rays in cyclic order (no facets built),
/// any other as the Cone. holds(w) answers as cone_holds(generators, w) does.
class HeldCone {
public:
    explicit HeldCone(std::vector<ExactVector> generators);
    [[nodiscard]] Held holds(const ExactVector& w) const;
    [[nodiscard]] Held holds(const Vec3& w) const { return holds(ExactVector::input(w)); }

private:
    std::vector<ExactVector> generators_;  // the non-zero generators
    std::vector<std::size_t> from_;        // their indices in the argument (empty: no zero ones)
    std::vector<int> cycle_;               // indices into generators_, or empty
    std::optional<Cone> cone_;             // when not pointed and full-dimensional
};

}  // namespace momentlab
