#include "momentlab/mechanics/find_contacts.hpp"

#include "momentlab/geometry/polygon.hpp"

#include <algorithm>
#include <map>
#include <span>
#include <utility>
#include <cmath>
#include <stdexcept>
#include <string>

namespace momentlab {
namespace {

// The polygon (simple, checked by the caller) counter-clockwise.
Polygon counter_clockwise(const Polygon& p) {
    Polygon q = p;
    if (!is_counter_clockwise(p)) std::reverse(q.begin(), q.end());
    return q;
}

// Outward unit normal of the counter-clockwise edge a -> b.
Vec2 outward(const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    return Vec2(d.y(), -d.x()) / d.norm();
}

// Vertices of `touching` lying on edges of `touched`; `into_touching` gives the normal's sense.
void vertex_on_edge(const Polygon& touching, const Polygon& touched, bool body_is_touching,
                    const ContactFinding& o, std::vector<Contact>& out) {
    const std::size_t n = touching.size(), m = touched.size();
    const EdgeGrid grid(touched, o.distance);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& v = touching[i];
        for (std::size_t k : grid.near(v)) {
            const Vec2& a = touched[k];
            const Vec2& b = touched[(k + 1) % m];
            if (!within_distance_of_segment(v, a, b, o.distance)) continue;
            // Vertex on vertex: an obstacle vertex at a body vertex is left to that body
            // vertex, whose contact takes the supporting obstacle edge's normal.
            if (!body_is_touching && ((v - a).norm() <= o.distance || (v - b).norm() <= o.distance)) continue;
            const Vec2 out_n = outward(a, b);
            // The neighbours of v must stay outside the touched edge's line.
            const Vec2& prev = touching[(i + n - 1) % n];
            const Vec2& next = touching[(i + 1) % n];
            if ((prev - a).dot(out_n) < -o.distance || (next - a).dot(out_n) < -o.distance) continue;
            // Into the moving body: the obstacle's outward normal, or the body edge's inward one.
            const Vec2 normal = body_is_touching ? out_n : Vec2(-out_n);
            out.push_back(Contact::make(v, normal, o.mu, o.mu_kinetic));
        }
    }
}

}  // namespace

std::vector<Contact> find_contacts(const Polygon& body, const std::vector<Polygon>& obstacles,
                                   const ContactFinding& options) {
    if (!(options.distance >= 0.0)) throw std::invalid_argument("find_contacts: distance must be >= 0");
    for (std::size_t i = 0; i <= obstacles.size(); ++i) {
        const Polygon& p = i == 0 ? body : obstacles[i - 1];
        const std::string problem = polygon_problem(p);
        if (!problem.empty()) {
            throw std::invalid_argument("find_contacts: " + (i == 0 ? std::string("the body polygon: ") : "obstacle " + std::to_string(i - 1) + ": ") + problem);
        }
    }
    const Polygon b = counter_clockwise(body);
    std::vector<Contact> found;
    for (const Polygon& raw : obstacles) {
        const Polygon o = counter_clockwise(raw);
        vertex_on_edge(b, o, true, options, found);
        vertex_on_edge(o, b, false, options, found);
    }
    // One contact for points and normals both within the distance, the first kept: the kept
    // ones by x, so that only those within the distance in x are compared.
    std::vector<Contact> out;
    std::multimap<double, std::size_t> kept;
    for (const Contact& c : found) {
        bool repeated = false;
        for (auto it = kept.lower_bound(c.point.x() - options.distance);
             it != kept.end() && it->first <= c.point.x() + options.distance && !repeated; ++it) {
            const Contact& d = out[it->second];
            repeated = (c.point - d.point).norm() <= options.distance && (c.normal - d.normal).norm() <= options.distance;
        }
        if (!repeated) {
            kept.emplace(c.point.x(), out.size());
            out.push_back(c);
        }
    }
    return out;
}

}  // namespace momentlab
