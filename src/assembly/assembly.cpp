#include "momentlab/assembly/assembly.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "momentlab/geometry/polygon.hpp"
#include "momentlab/mechanics/find_contacts.hpp"
#include "momentlab/io/input_error.hpp"

#include <nlohmann/json.hpp>

namespace momentlab {
namespace {

std::string at(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

struct AxisBox {
    Vec2 lo, hi;
};

AxisBox box_of(const Polygon& p, double margin) {
    AxisBox b{p.front(), p.front()};
    for (const Vec2& v : p) {
        b.lo = b.lo.cwiseMin(v);
        b.hi = b.hi.cwiseMax(v);
    }
    b.lo.array() -= margin;
    b.hi.array() += margin;
    return b;
}

bool boxes_meet(const AxisBox& a, const AxisBox& b) {
    return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() && b.lo.y() <= a.hi.y();
}

// A margin beyond the contact distance for the boxes (their coordinates are rounded: the exact
// tests decide).
double box_margin(double distance) { return distance * 2.0 + 1e-9; }

// The box of exact points: of their doubles, grown by their rounding too.
AxisBox box_of(const ExactPolygon& p, double margin) {
    const Polygon r = rounded(p);
    double largest = 0.0;
    for (const Vec2& v : r) largest = std::max(largest, v.cwiseAbs().maxCoeff());
    return box_of(r, margin + 1e-9 * largest);
}

// The contacts of a polygon with others: checked (find_contacts) for the doubles given; on
// scaled polygons (doubles or exact points), checked by the reader (check_assembly).
std::vector<Contact> contacts_between(const Polygon& a, const std::vector<Polygon>& others, const ContactFinding& options,
                                      const ScaledPolygons* scaled, std::vector<ContactOrigin>* where) {
    if (scaled) return detail::find_contacts_of_simple(a, others, options, *scaled, where);
    return find_contacts(a, others, options, where);
}
std::vector<Contact> contacts_between(const ExactPolygon& a, const std::vector<ExactPolygon>& others,
                                      const ContactFinding& options, const ScaledPolygons* scaled, std::vector<ContactOrigin>* where) {
    return detail::find_contacts_of_simple(a, others, options, *scaled, where);
}

// find_assembly_contacts on the outlines (the bodies' n, then the obstacles'; doubles, or exact
// points with an exact distance): every polygon found simple and no two overlapping by the caller.
template <class P>
std::vector<AssemblyContact> assembly_contacts(const std::vector<std::vector<P>>& outlines, std::size_t n,
                                               const ContactFinding& options, const ScaledPolygons* scaled,
                                               std::vector<ContactOrigin>* origins) {
    std::vector<AssemblyContact> found;
    const double margin = box_margin(scaled ? scaled->rounded_distance(options.distance) : options.distance);
    std::vector<AxisBox> boxes;
    for (const auto& p : outlines) boxes.push_back(p.empty() ? AxisBox{} : box_of(p, margin));
    std::vector<ContactOrigin> where;
    // The contacts of body a with `others` (the obstacles at `index`, or body b alone).
    const auto add = [&](std::size_t a, std::size_t b, const std::vector<std::vector<P>>& others, const std::vector<std::size_t>& index) {
        where.clear();
        for (Contact& c : contacts_between(outlines[a], others, options, scaled, &where)) {
            found.push_back({a + 1, b, std::move(c)});
        }
        if (!origins) return;
        for (ContactOrigin o : where) {
            o.obstacle = index[o.obstacle];
            origins->push_back(o);
        }
    };
    for (std::size_t a = 0; a < n; ++a) {
        if (outlines[a].empty()) continue;
        std::vector<std::vector<P>> near;
        std::vector<std::size_t> index;
        for (std::size_t k = 0; n + k < outlines.size(); ++k) {
            if (boxes_meet(boxes[a], boxes[n + k])) {
                near.push_back(outlines[n + k]);
                index.push_back(k);
            }
        }
        if (!near.empty()) add(a, 0, near, index);
        for (std::size_t b = 0; b < a; ++b) {
            if (outlines[b].empty() || !boxes_meet(boxes[a], boxes[b])) continue;
            add(a, b + 1, {outlines[b]}, {0});
        }
    }
    return found;
}

}  // namespace

const BodyValues* AssemblyBody::exact_values() const {
    if (!exact) return nullptr;
    const BodyValues& v = *exact;
    const bool current = v.mass_double == mass && v.com_double == com && v.inertia_double == inertia.value_or(0.0) &&
                         v.radius_double == radius_of_gyration;
    return current ? &v : nullptr;
}

const std::vector<std::vector<Rational2>>* Assembly::exact_polygons_in_force() const {
    if (!exact_polygons) return nullptr;
    const std::vector<std::vector<Rational2>>& exact = *exact_polygons;
    if (exact.size() != bodies.size() + obstacles.size()) return nullptr;
    for (std::size_t k = 0; k < exact.size(); ++k) {
        const Polygon& p = k < bodies.size() ? bodies[k].polygon : obstacles[k - bodies.size()];
        if (p.size() != exact[k].size()) return nullptr;
        for (std::size_t i = 0; i < p.size(); ++i) {
            if (to_double(exact[k][i]) != p[i]) return nullptr;
        }
    }
    return &exact;
}

Assembly assembly_of(const Scene& scene) {
    if (!scene.body) throw std::invalid_argument("the scene has no body (an assembly needs its mass and centre of mass)");
    Assembly a;
    AssemblyBody b;
    b.mass = scene.body->mass;
    b.com = scene.body->com;
    if (scene.body->radius_of_gyration) {
        b.radius_of_gyration = scene.body->radius_of_gyration;
    } else {
        b.inertia = scene.body->inertia;
    }
    b.polygon = scene.body->polygon;
    if (const BodyValues* v = scene.body->exact_values()) {
        BodyValues values = *v;
        values.inertia_double = b.inertia.value_or(0.0);
        b.exact = std::make_shared<const BodyValues>(std::move(values));
    }
    a.bodies.push_back(std::move(b));
    for (const Contact& c : scene.contacts) a.contacts.push_back({1, 0, c});
    a.obstacles = scene.obstacles;
    a.contact_distance = scene.contact_distance;
    return a;
}

std::vector<AssemblyContact> find_assembly_contacts(const std::vector<AssemblyBody>& bodies,
                                                    const std::vector<Polygon>& obstacles, const ContactFinding& options,
                                                    std::vector<ContactOrigin>* origins) {
    std::vector<Polygon> outlines;
    for (const AssemblyBody& b : bodies) outlines.push_back(b.polygon);
    outlines.insert(outlines.end(), obstacles.begin(), obstacles.end());
    return assembly_contacts(outlines, bodies.size(), options, nullptr, origins);
}

std::vector<AssemblyContact> detail::find_assembly_contacts_of_simple(const ScaledPolygons& scaled, std::size_t n,
                                                                      const ContactFinding& options,
                                                                      std::vector<ContactOrigin>* origins) {
    return scaled.exact.empty() ? assembly_contacts(scaled.doubles, n, options, &scaled, origins)
                                : assembly_contacts(scaled.exact, n, options, &scaled, origins);
}

namespace {

// Refuses the first pair of overlapping outlines (the bodies' n, then the obstacles').
template <class P>
void overlaps(const std::vector<std::vector<P>>& outlines, std::size_t n, double margin, double scale) {
    // A point of the overlap, in the coordinates given (the outlines may be scaled by `scale`).
    const auto at_point = [scale](const Vec2& x) {
        return ", for instance at (" + nlohmann::json(x.x() / scale).dump() + ", " + nlohmann::json(x.y() / scale).dump() + ")";
    };
    std::vector<AxisBox> boxes(outlines.size());
    for (std::size_t k = 0; k < outlines.size(); ++k) {
        if (!outlines[k].empty()) boxes[k] = box_of(outlines[k], margin);
    }
    for (std::size_t a = 0; a < n; ++a) {
        const std::vector<P>& pa = outlines[a];
        if (pa.empty()) continue;
        for (std::size_t k = 0; n + k < outlines.size(); ++k) {
            if (!boxes_meet(boxes[a], boxes[n + k])) continue;
            if (const std::optional<Vec2> x = polygons_overlap(pa, outlines[n + k])) {
                throw InputError(at("$.bodies", a) + ".polygon", "overlaps obstacle " + std::to_string(k) + " ($.obstacles[" +
                                                                     std::to_string(k) + "].polygon)" + at_point(*x) +
                                                                     " (bodies may touch the obstacles, not overlap them)");
            }
        }
        for (std::size_t b = 0; b < a; ++b) {
            const std::vector<P>& pb = outlines[b];
            if (pb.empty() || !boxes_meet(boxes[a], boxes[b])) continue;
            if (const std::optional<Vec2> x = polygons_overlap(pa, pb)) {
                throw InputError(at("$.bodies", a) + ".polygon", "overlaps the polygon of body " + std::to_string(b + 1) + " (" +
                                                                     at("$.bodies", b) + ".polygon)" + at_point(*x) +
                                                                     " (bodies may touch, not overlap)");
            }
        }
    }
}

}  // namespace

void check_assembly(const Assembly& assembly) {
    const std::size_t n = assembly.bodies.size();
    if (n == 0) throw InputError("$.bodies", "expected at least one body");
    const auto positive = [](const std::string& path, double x) {
        if (!(std::isfinite(x) && x > 0.0)) throw InputError(path, "expected a finite number > 0");
    };
    for (std::size_t k = 0; k < n; ++k) {
        const AssemblyBody& b = assembly.bodies[k];
        const std::string path = at("$.bodies", k);
        positive(path + ".mass", b.mass);
        if (!finite(b.com)) throw InputError(path + ".com", "expected finite coordinates");
        if (b.inertia && b.radius_of_gyration) {
            throw InputError(path + ".radius_of_gyration", "give either \"inertia\" or \"radius_of_gyration\", not both");
        }
        if (b.inertia) positive(path + ".inertia", *b.inertia);
        if (b.radius_of_gyration) positive(path + ".radius_of_gyration", *b.radius_of_gyration);
        if (!b.polygon.empty()) {
            const std::string problem = polygon_problem(b.polygon);
            if (!problem.empty()) throw InputError(path + ".polygon", problem);
        }
    }
    const double distance = assembly.contact_distance.value_or(1e-9);
    for (std::size_t i = 0; i < assembly.contacts.size(); ++i) {
        const AssemblyContact& c = assembly.contacts[i];
        const std::string path = at("$.contacts", i);
        const std::string range = " (bodies are 1.." + std::to_string(n) + ", the world is 0)";
        if (c.a == 0 || c.a > n) {
            throw InputError(path + ".bodies", "the first body, " + std::to_string(c.a) +
                                                   ", is not a movable body" + range);
        }
        if (c.b > n) throw InputError(path + ".bodies", "body " + std::to_string(c.b) + " is out of range" + range);
        if (c.a == c.b) throw InputError(path + ".bodies", "a contact of body " + std::to_string(c.a) + " with itself");
        try {
            (void)Contact::make(c.contact.point, c.contact.normal, c.contact.mu, c.contact.mu_kinetic);
        } catch (const std::invalid_argument& e) {
            throw InputError(path, e.what());
        }
        for (std::size_t body : {c.a, c.b}) {
            if (body == 0) continue;
            const Polygon& outline = assembly.bodies[body - 1].polygon;
            if (!outline.empty() && !within_distance_of_boundary(outline, c.contact.point, distance)) {
                throw InputError(path + ".point", "is not on the outline of body " + std::to_string(body) +
                                                      " (within contact_distance)");
            }
        }
    }
    // Overlaps: pairs whose boxes meet, decided on the polygons as typed when they are decimals
    // (scaled_polygons: every coordinate times D, exactly), else on their doubles.
    std::vector<Polygon> outlines;
    for (const AssemblyBody& b : assembly.bodies) outlines.push_back(b.polygon);
    outlines.insert(outlines.end(), assembly.obstacles.begin(), assembly.obstacles.end());
    std::optional<ScaledPolygons> scaled;
    if (const auto* exact = assembly.exact_polygons_in_force()) scaled = scaled_polygons(*exact);
    if (scaled && scaled->exact.empty()) outlines = scaled->doubles;
    if (scaled && !scaled->exact.empty()) {
        for (std::size_t k = 0; k < scaled->exact.size(); ++k) {  // simple as typed too (read as doubles)
            if (scaled->exact[k].empty()) continue;
            const std::string problem = polygon_problem(scaled->exact[k]);
            if (!problem.empty()) throw InputError(k < n ? at("$.bodies", k) + ".polygon" : at("$.obstacles", k - n) + ".polygon", problem);
        }
        overlaps(scaled->exact, n, box_margin(scaled->rounded_distance(distance)), scaled->scale.to_double());
    } else {
        const double scale = scaled ? scaled->scale.to_double() : 1.0;
        overlaps(outlines, n, box_margin(scaled ? scaled->rounded_distance(distance) : distance), scale);
    }
}

}  // namespace momentlab
