#pragma once

/// \file
/// Moment labels (Mason 1991, section 2): the F+ and F- regions of a force set F, which are the
/// two sheets of the dual cone F* seen through X = (x, y, s) -> (y, -x, s) (docs/design.md).

#include <string>
#include <vector>

#include "momentlab/core/rational.hpp"
#include "momentlab/core/vec.hpp"
#include "momentlab/geometry/cone.hpp"

namespace momentlab {

/// The label of a point of the plane (as taught in Modern Robotics, ch. 12).
enum class Label { None, Plus, Minus, Both };

/// "+", "-", "+-" or "none".
[[nodiscard]] const char* to_string(Label label);

/// An axis-aligned rectangle of the plane.
struct Box {
    Vec2 min = Vec2(-1.0, -1.0);
    Vec2 max = Vec2(1.0, 1.0);
};

/// One sheet of the labels: the convex region conv(vertices) + cone(rays) + span(lines).
struct Region {
    /// Vertices as homogeneous points (x, y, s) with s > 0: exact constructions of the cone.
    std::vector<ExactVector> vertices_h;
    /// Directions in which the region is unbounded, as exact points at infinity (x, y, 0).
    std::vector<ExactVector> rays_h;
    /// Directions of lines contained in the region, as exact points at infinity (x, y, 0).
    std::vector<ExactVector> lines_dir_h;
    /// Vertices (x/s, y/s), each coordinate the exact quotient correctly rounded (nearest_double,
    /// core/rounding.hpp; infinite beyond the double range).
    std::vector<Vec2> vertices;
    /// rays_h and lines_dir_h rounded (directions only).
    std::vector<Vec2> rays;
    std::vector<Vec2> lines;
    /// Boundary order: the homogeneous points of the region's cone, counter-clockwise, with
    /// s = 0 for directions at infinity (filled for pointed region cones; rounded).
    std::vector<Vec3> boundary;
    /// Half-planes a x + b y + c >= 0 (as (a, b, c)) and lines (= 0) whose intersection it is
    /// (rounded: for drawing).
    std::vector<Vec3> halfplanes;
    std::vector<Vec3> lines_h;
    bool is_empty = true;

    /// "empty", "point", "segment", "ray", "line", "polygon", "unbounded", "strip",
    /// "half-plane" or "plane".
    [[nodiscard]] std::string kind() const;
    /// The region intersected with a box, as a convex polygon (counter-clockwise; two points
    /// for a segment, one for a point, none when empty). Rounded: for drawing only.
    [[nodiscard]] std::vector<Vec2> clipped(const Box& box) const;
};

/// The moment labels of a force set.
class Labels {
public:
    /// The labels of the force set `forces` (a cone of wrenches).
    explicit Labels(Cone forces);

    /// The force set (the truth; the labels are a view of it).
    [[nodiscard]] const Cone& forces() const { return forces_; }
    /// K = {X = (x, y, s) : the moment functional of X is in F*}, a cone of homogeneous points.
    [[nodiscard]] const Cone& point_cone() const { return points_; }
    /// The + region (s > 0 sheet) and the - region (s < 0 sheet, drawn at (x/s, y/s)).
    [[nodiscard]] const Region& plus() const { return plus_; }
    [[nodiscard]] const Region& minus() const { return minus_; }

    /// The exact label of a point: + if every force of F has moment >= 0 about it, - if <= 0.
    [[nodiscard]] Label at(const Vec2& point) const;
    /// The same for a point given exactly (a decimal as typed: 0.1 is 1/10).
    [[nodiscard]] Label at(const Rational2& point) const;

    /// The force set represented by two regions (the inverse view). Exact on the homogeneous
    /// vertices. When both regions are empty the labels do not determine F (a line of pure
    /// moments and R^3 both have empty labels): R^3 is returned.
    [[nodiscard]] static Cone forces_from_regions(const Region& plus, const Region& minus);

private:
    Cone forces_;
    Cone dual_;
    Cone points_;
    Region plus_;
    Region minus_;
};

/// The exact label of a point for the force set `forces`, without building its regions: + if
/// every force has moment >= 0 about it, - if <= 0 (the test Labels::at makes). Throws
/// std::invalid_argument for a non-finite point.
[[nodiscard]] Label moment_label(const Cone& forces, const Vec2& point);
[[nodiscard]] Label moment_label(const Cone& forces, const Rational2& point);

/// The +- set of a force set: the points about which every force of F has zero moment, i.e. the
/// common part of F+ and F- (a line, a point, the whole plane for F = {0}, else empty). Exact:
/// it is the + region of the labels of span(F), built from F's exact rays and lines.
[[nodiscard]] Region both_region(const Cone& forces);

/// The moment functional of the point (x, y): lambda(w) = y fx - x fy + tau, as a covector.
[[nodiscard]] inline Vec3 moment_functional(const Vec2& point) {
    return Vec3(point.y(), -point.x(), 1.0);
}
/// The same for an exact point P / d (a decimal as typed): (P.y, -P.x, d), d > 0 times it.
[[nodiscard]] ExactVector moment_functional(const Rational2& point);

}  // namespace momentlab
