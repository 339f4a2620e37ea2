#include "momentlab/io/scene_json.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <span>

#include "json_read.hpp"
#include "momentlab/geometry/polygon.hpp"
#include "momentlab/mechanics/find_contacts.hpp"

namespace momentlab {
namespace {

using nlohmann::json;
using namespace json_read;

double positive(const json& obj, const std::string& path, const char* name) {
    const double x = number(field(obj, path, name), path + "." + name);
    if (!(x > 0.0)) throw InputError(path + "." + name, "expected a number > 0");
    return x;
}

Polygon checked_polygon(Polygon p, const std::string& path) {
    const std::string problem = polygon_problem(p);
    if (!problem.empty()) throw InputError(path, problem);
    return p;
}

Polygon polygon(const json& v, const std::string& path) { return checked_polygon(vec2_list(v, path), path); }

// A "polygon" field's value, or the plain reader's list of it when it took the list apart.
Polygon polygon(const json& v, const std::optional<std::vector<PlainPoint>>* plain, const std::string& path) {
    return plain && *plain ? checked_polygon(vec2_list(**plain, path), path) : polygon(v, path);
}

Body read_body(const json& b, const std::optional<std::vector<PlainPoint>>* plain_polygon, const std::string& path,
               InputWarnings* w) {
    if (!b.is_object()) throw InputError(path, "expected an object with \"mass\", \"com\" and \"inertia\"");
    known_fields(b, path, {"mass", "com", "inertia", "radius_of_gyration", "polygon"}, w);
    Body body;
    body.mass = positive(b, path, "mass");
    body.com = vec2(field(b, path, "com"), path + ".com");
    if (b.contains("inertia")) {
        body.inertia = positive(b, path, "inertia");
        if (b.contains("radius_of_gyration")) {
            throw InputError(path + ".radius_of_gyration", "give either \"inertia\" or \"radius_of_gyration\", not both");
        }
    } else if (b.contains("radius_of_gyration")) {
        const double rho = positive(b, path, "radius_of_gyration");
        body.radius_of_gyration = rho;
        body.inertia = body.mass * rho * rho;
    } else {
        throw InputError(path, "missing field \"inertia\" (or \"radius_of_gyration\")");
    }
    if (b.contains("polygon")) body.polygon = polygon(b.at("polygon"), plain_polygon, path + ".polygon");
    return body;
}

// A contact from its checked point and normal and its other fields as written (nullptr: absent).
Contact read_contact(const Vec2& point, const Vec2& normal, const json* mu, const json* mu_kinetic, const json* name,
                     const std::string& path) {
    const double friction = mu ? nonnegative(*mu, path + ".mu", "mu") : 0.0;
    std::optional<double> kinetic;
    if (mu_kinetic) kinetic = nonnegative(*mu_kinetic, path + ".mu_kinetic", "mu_kinetic");
    if (name && !name->is_string()) throw InputError(path + ".name", "expected a string");
    return Contact::make(point, normal, friction, kinetic, name ? name->get_ref<const std::string&>() : std::string());
}

Contact read_contact(const json& c, const std::string& path, InputWarnings* w) {
    if (!c.is_object()) throw InputError(path, "expected an object with \"point\" and \"normal\"");
    known_fields(c, path, {"point", "normal", "mu", "mu_kinetic", "name"}, w);
    const Vec2 point = vec2(field(c, path, "point"), path + ".point");
    const Vec2 normal = nonzero2(c, path, "normal");
    const auto given = [&](const char* name) { return c.contains(name) ? &c.at(name) : nullptr; };
    return read_contact(point, normal, given("mu"), given("mu_kinetic"), given("name"), path);
}

// The same from a contact the plain reader took apart (it has exactly the known fields).
Contact read_contact(const PlainContact& c, const std::string& path) {
    const Vec2 point = vec2(c.point[0], c.point[1], path + ".point");
    const Vec2 normal = nonzero(vec2(c.normal[0], c.normal[1], path + ".normal"), path + ".normal");
    const auto given = [](const std::optional<json>& v) { return v ? &*v : nullptr; };
    return read_contact(point, normal, given(c.mu), given(c.mu_kinetic), given(c.name), path);
}

// read_scene, with the lists the plain reader took apart from `plain` (nullptr: none).
Scene read_scene(const json& doc, const PlainScene* plain_scene, InputWarnings* w) {
    const std::span<const PlainContact> plain = plain_scene ? std::span<const PlainContact>(plain_scene->contacts)
                                                            : std::span<const PlainContact>();
    if (!doc.is_object()) throw InputError("$", "expected a scene object with \"body\" and \"contacts\"");
    known_fields(doc, "$", {"body", "contacts", "obstacles", "contact_distance", "mu"}, w);
    Scene scene;
    if (doc.contains("body")) {
        scene.body = read_body(doc.at("body"), plain_scene ? &plain_scene->body_polygon : nullptr, "$.body", w);
    }
    if (doc.contains("obstacles")) {
        const json& obstacles = doc.at("obstacles");
        if (!obstacles.is_array()) throw InputError("$.obstacles", "expected a list of obstacles");
        for (std::size_t i = 0; i < obstacles.size(); ++i) {
            const std::string p = at("$.obstacles", i);
            if (!obstacles[i].is_object()) throw InputError(p, "expected an object with \"polygon\"");
            known_fields(obstacles[i], p, {"polygon"}, w);
            const bool plain_polygon = plain_scene && i < plain_scene->obstacle_polygons.size();
            scene.obstacles.push_back(polygon(field(obstacles[i], p, "polygon"),
                                              plain_polygon ? &plain_scene->obstacle_polygons[i] : nullptr, p + ".polygon"));
        }
    }
    ContactFinding options;
    if (doc.contains("contact_distance")) {
        options.distance = nonnegative(doc.at("contact_distance"), "$.contact_distance", "a distance");
        scene.contact_distance = options.distance;
    }
    if (doc.contains("contacts")) {
        const json& contacts = doc.at("contacts");
        if (plain.empty() && !contacts.is_array()) throw InputError("$.contacts", "expected a list of contacts");
        const std::size_t count = plain.empty() ? contacts.size() : plain.size();
        if (count == 0) {
            throw InputError("$.contacts", "expected at least one contact (omit the field to find them from the polygons)");
        }
        // A contact must be on the body's outline when the outline is given: its edges indexed
        // once for all the contacts.
        const Polygon* outline = scene.body && !scene.body->polygon.empty() ? &scene.body->polygon : nullptr;
        const std::optional<EdgeGrid> edges = outline ? std::optional<EdgeGrid>(std::in_place, *outline, options.distance)
                                                      : std::nullopt;
        scene.contacts.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
            const std::string p = at("$.contacts", i);
            scene.contacts.push_back(plain.empty() ? read_contact(contacts[i], p, w) : read_contact(plain[i], p));
            if (outline) {
                const Vec2& point = scene.contacts.back().point;
                const auto near = edges->near(point);
                const bool on_outline = std::any_of(near.begin(), near.end(), [&](std::size_t k) {
                    return within_distance_of_segment(point, (*outline)[k], (*outline)[(k + 1) % outline->size()], options.distance);
                });
                if (!on_outline) {
                    const double d = distance_to_boundary(scene.body->polygon, point);
                    char text[200];
                    std::snprintf(text, sizeof text,
                                  "is %.3g from the body polygon (expected on its boundary, within contact_distance = %g)",
                                  d, options.distance);
                    throw InputError(p + ".point", text);
                }
            }
        }
        if (doc.contains("mu") && w != nullptr) w->push_back("$.mu: ignored: it applies to contacts found from the polygons");
    } else {
        if (!scene.body || scene.body->polygon.empty() || scene.obstacles.empty()) {
            throw InputError("$", "missing field \"contacts\" (or a body polygon and obstacles to find them from)");
        }
        if (doc.contains("mu")) {
            options.mu = nonnegative(doc.at("mu"), "$.mu", "mu");
            options.mu_kinetic = options.mu;
        }
        try {
            // The outlines were found simple as they were read (checked_polygon).
            scene.contacts = detail::find_contacts_of_simple(scene.body->polygon, scene.obstacles, options);
        } catch (const std::invalid_argument& e) {
            throw InputError("$", e.what());
        }
        if (scene.contacts.empty()) {
            for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
                if (polygons_overlap(scene.body->polygon, scene.obstacles[i])) {
                    throw InputError("$.obstacles[" + std::to_string(i) + "]",
                                     "the body polygon overlaps this obstacle (expected them to touch, not overlap)");
                }
            }
            throw InputError("$", "the body polygon touches no obstacle (no contacts found)");
        }
    }
    return scene;
}

}  // namespace

Scene read_scene(const json& doc, InputWarnings* w) { return read_scene(doc, nullptr, w); }

Scene read_scene_text(const std::string& text, InputWarnings* warnings) {
    if (const std::optional<PlainScene> plain = parse_plain_scene(text)) return read_scene(plain->doc, &*plain, warnings);
    return read_scene(parse_by_library(text), nullptr, warnings);
}

json to_json(const Scene& scene) {
    auto xy = [](const Vec2& v) { return json::array({v.x(), v.y()}); };
    auto polygon = [&](const Polygon& p) {
        json out = json::array();
        for (const Vec2& v : p) out.push_back(xy(v));
        return out;
    };
    json doc = json::object();
    if (scene.body) {
        doc["body"] = {{"mass", scene.body->mass}, {"com", xy(scene.body->com)}};
        // The radius of gyration when the scene gave one: the inertia is its rounded square.
        if (scene.body->radius_of_gyration) {
            doc["body"]["radius_of_gyration"] = *scene.body->radius_of_gyration;
        } else {
            doc["body"]["inertia"] = scene.body->inertia;
        }
        if (!scene.body->polygon.empty()) doc["body"]["polygon"] = polygon(scene.body->polygon);
    }
    doc["contacts"] = json::array();
    for (const Contact& c : scene.contacts) {
        json j = {{"point", xy(c.point)}, {"normal", xy(c.normal)}, {"mu", c.mu}, {"mu_kinetic", c.mu_kinetic}};
        if (!c.name.empty()) j["name"] = c.name;
        doc["contacts"].push_back(j);
    }
    if (!scene.obstacles.empty()) {
        doc["obstacles"] = json::array();
        for (const Polygon& p : scene.obstacles) doc["obstacles"].push_back({{"polygon", polygon(p)}});
    }
    if (scene.contact_distance) {  // the contacts are on the outline within it
        doc["contact_distance"] = *scene.contact_distance;
    }
    return doc;
}

void require_body(const Scene& scene, const std::string& command, const AnalysisOptions& options) {
    if (!scene.body && !options.quasi_static) {
        throw InputError("$", "missing field \"body\" (" + command + " needs its mass, com and inertia)");
    }
}

std::vector<ModeForces> analyze_input(const Scene& scene, const std::string& command, const AnalysisOptions& options) {
    require_body(scene, command, options);
    return analyze(scene, options);
}

const ModeForces& find_mode(const std::vector<ModeForces>& analysis, const std::string& letters,
                            const std::string& where) {
    for (const ModeForces& m : analysis) {
        if (m.mode.letters == letters) return m;
    }
    std::string modes;
    for (const ModeForces& m : analysis) modes += (modes.empty() ? "" : ", ") + m.mode.letters;
    throw InputError(where, "no mode \"" + letters + "\" in this scene (its modes: " + modes + ")");
}

}  // namespace momentlab
