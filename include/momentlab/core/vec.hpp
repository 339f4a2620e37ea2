#pragma once

/// \file
/// Small fixed-size vectors (Eigen) and the planar conventions of docs/design.md.

#include <Eigen/Dense>

namespace momentlab {

/// A point or direction of the plane.
using Vec2 = Eigen::Vector2d;
/// A wrench (fx, fy, tau), a twist (vx, vy, omega), a covector, or a homogeneous point (x, y, s).
using Vec3 = Eigen::Vector3d;
/// A 3x3 matrix acting on Vec3.
using Mat3 = Eigen::Matrix3d;

/// The planar cross product a.x*b.y - a.y*b.x (rounded; see cross2_sign for the exact sign).
inline double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// The wrench of a force `f` acting through the point `p`: (f, p x f), torque about the origin.
/// Rounds the torque (one cross product); exact when the products are representable.
inline Vec3 wrench_at(const Vec2& p, const Vec2& f) { return Vec3(f.x(), f.y(), cross2(p, f)); }

/// True when every coordinate is finite (neither NaN nor infinite).
inline bool all_finite(const Vec3& v) { return v.allFinite(); }

}  // namespace momentlab
