#include "momentlab/planning/push.hpp"

#include <cmath>
#include <stdexcept>

#include "momentlab/geometry/force_sets.hpp"

namespace momentlab {

Cone push_actions(const Vec2& a, const Vec2& b, const Vec2& normal, char slip, double mu) {
    if (slip != 'l' && slip != 'f' && slip != 'r') throw std::invalid_argument("push_actions: slip must be l, f or r");
    if (!(mu >= 0.0) || !std::isfinite(mu)) throw std::invalid_argument("push_actions: mu must be finite and >= 0");
    if (!normal.allFinite() || normal.isZero()) throw std::invalid_argument("push_actions: the normal must be non-zero");
    // Edges of the Coulomb cone: [0] = n + mu t opposes sliding along -t (l), [1] = n - mu t
    // opposes sliding along +t (r).
    std::vector<Vec3> generators;
    for (const Vec2& p : {a, b}) {
        const auto edges = friction_cone_edges(p, normal, mu);
        if (slip != 'r') generators.push_back(edges[0]);
        if (slip != 'l') generators.push_back(edges[1]);
    }
    return Cone::from_generators(generators);
}

std::vector<PushCase> plan_push_edges(const Scene& scene, const ModeForces& goal, double mu) {
    if (!scene.body || scene.body->polygon.size() < 3) throw std::invalid_argument("plan_push_edges: the body needs a polygon");
    const Polygon& poly = scene.body->polygon;
    double area2 = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) area2 += cross2(poly[i], poly[(i + 1) % poly.size()]);
    std::vector<PushCase> cases;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        const Vec2 d = b - a;
        // Inward: to the left of the edge for a counter-clockwise outline, else to the right.
        const Vec2 n = (area2 > 0.0 ? Vec2(-d.y(), d.x()) : Vec2(d.y(), -d.x())).normalized();
        for (char slip : {'l', 'f', 'r'}) {
            PushCase c;
            c.edge = i;
            c.from = a;
            c.to = b;
            c.normal = n;
            c.slip = slip;
            c.actions = push_actions(a, b, n, slip, mu);
            c.solutions = intersection(c.actions, goal.applied);
            cases.push_back(std::move(c));
        }
    }
    return cases;
}

}  // namespace momentlab
