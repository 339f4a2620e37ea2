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

// The edges of a polygon that may lie within `distance` of a point: a uniform grid over the
// polygon's box, each edge entered in the cells near it (the boxes, grown by the distance and a
// rounding margin, of pieces of the edge no longer than a cell). A superset: the exact test
// decides. Cells are about as long as the mean edge, so a polygon of n edges of total length L
// costs O(n + L / h) to index and a query O(1 + the edges near the point) for outlines whose
// edges do not crowd into a few cells.
class EdgeGrid {
public:
    EdgeGrid(const Polygon& p, double distance) {
        const std::size_t m = p.size();
        lo_ = hi_ = p[0];
        double length = 0.0;
        for (std::size_t k = 0; k < m; ++k) {
            lo_ = lo_.cwiseMin(p[k]);
            hi_ = hi_.cwiseMax(p[k]);
            length += (p[(k + 1) % m] - p[k]).norm();
        }
        const Vec2 extent = hi_ - lo_;
        margin_ = distance + 1e-9 * (lo_.cwiseAbs().maxCoeff() + hi_.cwiseAbs().maxCoeff() + extent.maxCoeff());
        cell_ = std::max({length / static_cast<double>(m), 2.0 * margin_, extent.maxCoeff() / static_cast<double>(4 * m)});
        // At most about 4 m cells: coarser for outlines whose edges are short beside their box.
        while ((extent.x() / cell_ + 1.0) * (extent.y() / cell_ + 1.0) > 4.0 * static_cast<double>(m) + 16.0) cell_ *= 1.5;
        nx_ = static_cast<std::size_t>(extent.x() / cell_) + 1;
        ny_ = static_cast<std::size_t>(extent.y() / cell_) + 1;
        std::vector<std::pair<std::size_t, std::size_t>> entries;  // (cell, edge)
        for (std::size_t k = 0; k < m; ++k) {
            const Vec2 &a = p[k], &b = p[(k + 1) % m];
            const std::size_t pieces = static_cast<std::size_t>((b - a).norm() / cell_) + 1;
            const std::size_t first = entries.size();
            for (std::size_t i = 0; i < pieces; ++i) {
                const Vec2 u = a + (b - a) * (static_cast<double>(i) / pieces);
                const Vec2 v = i + 1 == pieces ? b : Vec2(a + (b - a) * (static_cast<double>(i + 1) / pieces));
                const Vec2 box_lo = u.cwiseMin(v).array() - margin_, box_hi = u.cwiseMax(v).array() + margin_;
                const auto [x0, y0] = index(box_lo);
                const auto [x1, y1] = index(box_hi);
                for (std::size_t x = x0; x <= x1; ++x) {
                    for (std::size_t y = y0; y <= y1; ++y) entries.emplace_back(x * ny_ + y, k);
                }
            }
            std::sort(entries.begin() + static_cast<std::ptrdiff_t>(first), entries.end());
            entries.erase(std::unique(entries.begin() + static_cast<std::ptrdiff_t>(first), entries.end()), entries.end());
        }
        std::stable_sort(entries.begin(), entries.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        start_.assign(nx_ * ny_ + 1, 0);
        for (const auto& e : entries) ++start_[e.first + 1];
        for (std::size_t c = 0; c < nx_ * ny_; ++c) start_[c + 1] += start_[c];
        edges_.reserve(entries.size());
        for (const auto& e : entries) edges_.push_back(e.second);  // per cell, increasing edge number
    }

    // The edges entered in the cell of q (none when q is beyond the grown box), increasing.
    [[nodiscard]] std::span<const std::size_t> near(const Vec2& q) const {
        if ((q.array() < lo_.array() - margin_).any() || (q.array() > hi_.array() + margin_).any()) return {};
        const auto [x, y] = index(q);
        const std::size_t c = x * ny_ + y;
        return {edges_.data() + start_[c], start_[c + 1] - start_[c]};
    }

private:
    [[nodiscard]] std::pair<std::size_t, std::size_t> index(const Vec2& q) const {
        const auto clamp = [](double t, std::size_t n) {
            return t <= 0.0 ? std::size_t{0} : std::min(static_cast<std::size_t>(t), n - 1);
        };
        return {clamp((q.x() - lo_.x()) / cell_, nx_), clamp((q.y() - lo_.y()) / cell_, ny_)};
    }

    Vec2 lo_ = Vec2::Zero(), hi_ = Vec2::Zero();
    double margin_ = 0.0, cell_ = 1.0;
    std::size_t nx_ = 1, ny_ = 1;
    std::vector<std::size_t> start_;
    std::vector<std::size_t> edges_;
};

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
