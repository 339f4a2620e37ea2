#include "momentlab/geometry/force_sets.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace momentlab {
namespace {

void require_finite(const Vec2& v, const char* what) {
    if (!v.allFinite()) throw std::invalid_argument(std::string(what) + " must be finite");
}

void require_nonzero(const Vec2& v, const char* what) {
    require_finite(v, what);
    if (v.x() == 0.0 && v.y() == 0.0) throw std::invalid_argument(std::string(what) + " must be non-zero");
}

}  // namespace

Cone force_ray(const Vec2& point, const Vec2& direction) {
    require_finite(point, "point");
    require_nonzero(direction, "direction");
    const Vec3 g[] = {wrench_at(point, direction)};
    return Cone::from_generators(g);
}

Cone line_of_force(const Vec2& point, const Vec2& direction) {
    require_finite(point, "point");
    require_nonzero(direction, "direction");
    const Vec3 w = wrench_at(point, direction);
    const Vec3 g[] = {w, -w};
    return Cone::from_generators(g);
}

Cone forces_through_point(const Vec2& point) {
    require_finite(point, "point");
    // Unit forces along x and y through the point; the torque p x f is exact here.
    const Vec3 ex(1.0, 0.0, -point.y()), ey(0.0, 1.0, point.x());
    const Vec3 g[] = {ex, -ex, ey, -ey};
    return Cone::from_generators(g);
}

Cone friction_cone(const Vec2& point, const Vec2& normal, double mu) {
    require_finite(point, "point");
    require_nonzero(normal, "normal");
    if (!(mu >= 0.0) || !std::isfinite(mu)) throw std::invalid_argument("mu must be finite and >= 0");
    const auto edges = friction_cone_edges(point, normal, mu);
    return Cone::from_generators(edges);
}

Cone pure_moments(int sign) {
    const Vec3 up(0.0, 0.0, 1.0);
    if (sign > 0) {
        const Vec3 g[] = {up};
        return Cone::from_generators(g);
    }
    if (sign < 0) {
        const Vec3 g[] = {-up};
        return Cone::from_generators(g);
    }
    const Vec3 g[] = {up, -up};
    return Cone::from_generators(g);
}

}  // namespace momentlab
