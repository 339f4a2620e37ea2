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
using json_read::Schema;
using json_read::Value;
using namespace json_read;

// What the reader keeps of a scene's document: the fields below (any other is a warning).
constexpr Schema::Member kContactFields[] = {
    {"point", &kPair}, {"normal", &kPair}, {"mu", &kScalar}, {"mu_kinetic", &kScalar}, {"name", &kScalar}};
constexpr Schema kContact{kContactFields};
constexpr Schema kContacts{{}, &kContact};
constexpr Schema::Member kBodyFields[] = {{"mass", &kScalar},
                                          {"com", &kPair},
                                          {"inertia", &kScalar},
                                          {"radius_of_gyration", &kScalar},
                                          {"polygon", &kPairs}};
constexpr Schema kBody{kBodyFields};
constexpr Schema::Member kObstacleFields[] = {{"polygon", &kPairs}};
constexpr Schema kObstacle{kObstacleFields};
constexpr Schema kObstacles{{}, &kObstacle};
constexpr Schema::Member kSceneFields[] = {{"body", &kBody},
                                           {"contacts", &kContacts},
                                           {"obstacles", &kObstacles},
                                           {"contact_distance", &kScalar},
                                           {"mu", &kScalar}};
constexpr Schema kScene{kSceneFields};

double positive(const Value& obj, const Path& path, std::string_view name) {
    const Path p(path, name);
    const double x = number(field(obj, path, name), p);
    if (!(x > 0.0)) throw InputError(p.str(), "expected a number > 0");
    return x;
}

// The contacts found from the polygons (`exact`: their vertices as typed, the body's first), as
// typed (contact_as_typed): `scaled` when they were found on the scaled polygons.
void exact_found_contacts(Scene& scene, const std::vector<std::vector<Rational2>>& exact, const Rational& mu, bool scaled) {
    for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
        const ContactOrigin& o = scene.origins[i];
        const std::vector<Rational2>& touching = exact[o.body_vertex ? 0 : o.obstacle + 1];
        const std::vector<Rational2>& touched = exact[o.body_vertex ? o.obstacle + 1 : 0];
        scene.contacts[i] = contact_as_typed(scene.contacts[i], touching[o.vertex], touched[o.edge],
                                             touched[(o.edge + 1) % touched.size()], mu, scaled);
    }
}

Body read_body(const Value& b, const Path& path, InputWarnings* w) {
    if (!b.is_object()) throw InputError(path.str(), "expected an object with \"mass\", \"com\" and \"inertia\"");
    known_fields(b, path, {"mass", "com", "inertia", "radius_of_gyration", "polygon"}, w);
    Body body;
    body.mass = positive(b, path, "mass");
    body.com = vec2(field(b, path, "com"), Path(path, "com"));
    if (b.contains("inertia")) {
        body.inertia = positive(b, path, "inertia");
        if (b.contains("radius_of_gyration")) {
            throw InputError(Path(path, "radius_of_gyration").str(), "give either \"inertia\" or \"radius_of_gyration\", not both");
        }
    } else if (b.contains("radius_of_gyration")) {
        const double rho = positive(b, path, "radius_of_gyration");
        body.radius_of_gyration = rho;
        body.inertia = body.mass * rho * rho;
    } else {
        throw InputError(path.str(), "missing field \"inertia\" (or \"radius_of_gyration\")");
    }
    if (const std::optional<Value> p = b.find("polygon")) body.polygon = polygon(*p, Path(path, "polygon"));
    BodyValues doubles;
    doubles.mass_double = body.mass;
    doubles.com_double = body.com;
    doubles.inertia_double = body.inertia;
    doubles.radius_double = body.radius_of_gyration;
    body.exact = json_read::exact_body_values(b, std::move(doubles));
    return body;
}

Contact read_contact(const Value& c, const Path& path, InputWarnings* w) {
    if (!c.is_object()) throw InputError(path.str(), "expected an object with \"point\" and \"normal\"");
    known_fields(c, path, {"point", "normal", "mu", "mu_kinetic", "name"}, w);
    return json_read::contact_of(c, path);
}

}  // namespace

namespace json_read {

Polygon polygon(const Value& v, const Path& path) {
    Polygon p = vec2_list(v, path);
    const std::string problem = polygon_problem(p);
    if (!problem.empty()) throw InputError(path.str(), problem);
    return p;
}

std::vector<Rational2> exact_polygon(const Value& v) {
    std::vector<Rational2> out;
    out.reserve(v.size());
    v.for_each_element([&](std::size_t, const Value& e) { out.push_back(exact_vec2(e)); });
    return out;
}

std::vector<Polygon> obstacles(const Value& list, const Path& path, InputWarnings* w) {
    if (!list.is_array()) throw InputError(path.str(), "expected a list of obstacles");
    std::vector<Polygon> out;
    out.reserve(list.size());
    list.for_each_element([&](std::size_t i, const Value& o) {
        const Path p(path, i);
        if (!o.is_object()) throw InputError(p.str(), "expected an object with \"polygon\"");
        known_fields(o, p, {"polygon"}, w);
        out.push_back(polygon(field(o, p, "polygon"), Path(p, "polygon")));
    });
    return out;
}

std::shared_ptr<const BodyValues> exact_body_values(const Value& b, BodyValues v) {
    v.mass = exact_number(*b.find("mass"));
    v.com = exact_vec2(*b.find("com"));
    if (const std::optional<Value> i = b.find("inertia")) v.inertia = exact_number(*i);
    if (const std::optional<Value> r = b.find("radius_of_gyration")) v.radius_of_gyration = exact_number(*r);
    if (const std::optional<Value> p = b.find("polygon")) {
        std::vector<Rational2> typed = exact_polygon(*p);
        if (!std::all_of(typed.begin(), typed.end(), [](const Rational2& x) { return is_double(x); })) v.polygon = std::move(typed);
    }
    if (v.mass.is_double() && is_double(v.com) && v.inertia.is_double() && (!v.radius_of_gyration || v.radius_of_gyration->is_double()) &&
        v.polygon.empty()) {
        return nullptr;
    }
    return std::make_shared<const BodyValues>(std::move(v));
}

Contact contact_of(const Value& c, const Path& path) {
    static constexpr std::array<std::string_view, 5> kFields = {"point", "normal", "mu", "mu_kinetic", "name"};
    const auto [given_point, given_normal, mu, mu_kinetic, name] = c.find(kFields);
    if (!given_point) throw InputError(path.str(), "missing field \"point\"");
    const Vec2 point = vec2(*given_point, Path(path, "point"));
    if (!given_normal) throw InputError(path.str(), "missing field \"normal\"");
    const Path normal_path(path, "normal");
    const Vec2 normal = nonzero(vec2(*given_normal, normal_path), normal_path);
    const double friction = mu ? nonnegative(*mu, Path(path, "mu"), "mu") : 0.0;
    std::optional<double> kinetic;
    if (mu_kinetic) kinetic = nonnegative(*mu_kinetic, Path(path, "mu_kinetic"), "mu_kinetic");
    if (name && !name->is_string()) throw InputError(Path(path, "name").str(), "expected a string");
    std::string text = name ? std::string(name->string()) : std::string();
    // The exact values (0.1 is 1/10), kept beside the doubles when some are not doubles.
    if (given_point->spells_doubles() && given_normal->spells_doubles() && (!mu || mu->spells_doubles()) &&
        (!mu_kinetic || mu_kinetic->spells_doubles())) {
        return Contact::make(point, normal, friction, kinetic, std::move(text));
    }
    ContactValues v;
    v.point = exact_vec2(*given_point);
    v.normal = exact_vec2(*given_normal);
    v.mu = mu ? exact_number(*mu) : Rational();
    v.mu_kinetic = mu_kinetic ? exact_number(*mu_kinetic) : v.mu;
    if (is_double(v.point) && is_double(v.normal) && v.mu.is_double() && v.mu_kinetic.is_double()) {
        return Contact::make(point, normal, friction, kinetic, std::move(text));
    }
    v.point_double = point;
    v.normal_double = normal;
    v.mu_double = friction;
    v.mu_kinetic_double = kinetic.value_or(friction);
    return Contact::make(std::move(v), std::move(text));
}

}  // namespace json_read

namespace {

Scene read_scene(const Value& doc, InputWarnings* w) {
    const Path root("$");
    if (!doc.is_object()) throw InputError("$", "expected a scene object with \"body\" and \"contacts\"");
    known_fields(doc, root, {"body", "contacts", "obstacles", "contact_distance", "mu"}, w);
    Scene scene;
    if (const std::optional<Value> body = doc.find("body")) scene.body = read_body(*body, Path(root, "body"), w);
    if (const std::optional<Value> list = doc.find("obstacles")) scene.obstacles = obstacles(*list, Path(root, "obstacles"), w);
    ContactFinding options;
    if (const std::optional<Value> distance = doc.find("contact_distance")) {
        options.distance = nonnegative(*distance, Path(root, "contact_distance"), "a distance");
        scene.contact_distance = options.distance;
    }
    const std::optional<Value> mu = doc.find("mu");
    if (const std::optional<Value> contacts = doc.find("contacts")) {
        const Path list(root, "contacts");
        if (!contacts->is_array()) throw InputError(list.str(), "expected a list of contacts");
        if (contacts->size() == 0) {
            throw InputError(list.str(), "expected at least one contact (omit the field to find them from the polygons)");
        }
        // A contact must be on the body's outline when the outline is given: its edges indexed
        // once for all the contacts.
        const Polygon* outline = scene.body && !scene.body->polygon.empty() ? &scene.body->polygon : nullptr;
        const std::optional<EdgeGrid> edges = outline ? std::optional<EdgeGrid>(std::in_place, *outline, options.distance)
                                                      : std::nullopt;
        scene.contacts.reserve(contacts->size());
        contacts->for_each_element([&](std::size_t i, const Value& c) {
            const Path p(list, i);
            scene.contacts.push_back(read_contact(c, p, w));
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
                    throw InputError(Path(p, "point").str(), text);
                }
            }
        });
        if (mu && w != nullptr) w->push_back("$.mu: ignored: it applies to contacts found from the polygons");
    } else {
        if (!scene.body || scene.body->polygon.empty() || scene.obstacles.empty()) {
            throw InputError("$", "missing field \"contacts\" (or a body polygon and obstacles to find them from)");
        }
        if (mu) {
            options.mu = nonnegative(*mu, Path(root, "mu"), "mu");
            options.mu_kinetic = options.mu;
        }
        // The vertices as typed: with decimals (0.1 is 1/10), the polygons scaled to exact doubles
        // when they can be, so that touching and overlap are decided on the decimals.
        std::vector<std::vector<Rational2>> exact;
        exact.push_back(exact_polygon(*doc.find("body")->find("polygon")));
        doc.find("obstacles")->for_each_element([&](std::size_t, const Value& o) { exact.push_back(exact_polygon(*o.find("polygon"))); });
        const std::optional<ScaledPolygons> scaled = scaled_polygons(exact);
        const bool exactly = scaled && !scaled->exact.empty();  // decimals beyond the doubles when scaled
        const double scale = scaled ? scaled->scale.to_double() : 1.0;
        const std::vector<Polygon>* scaled_doubles = scaled && !exactly ? &scaled->doubles : nullptr;
        std::vector<Polygon> scaled_obstacles;
        if (scaled_doubles) scaled_obstacles.assign(scaled_doubles->begin() + 1, scaled_doubles->end());
        const Polygon& body = scaled_doubles ? scaled_doubles->front() : scene.body->polygon;
        const std::vector<Polygon>& obstacles = scaled_doubles ? scaled_obstacles : scene.obstacles;
        const auto polygon_path = [](std::size_t k) {  // k = 0 the body's, else obstacle k - 1's
            return k == 0 ? std::string("$.body.polygon") : "$.obstacles[" + std::to_string(k - 1) + "].polygon";
        };
        if (exactly) {  // each outline simple as typed too (read as its doubles above)
            for (std::size_t k = 0; k < scaled->exact.size(); ++k) {
                const std::string problem = polygon_problem(scaled->exact[k]);
                if (!problem.empty()) throw InputError(polygon_path(k), problem);
            }
        }
        // Drawn touching, not overlapping: decided exactly (polygons_overlap), before the contacts.
        for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
            const std::optional<Vec2> x = exactly ? polygons_overlap(scaled->exact[0], scaled->exact[i + 1])
                                                  : polygons_overlap(body, obstacles[i]);
            if (x) {
                throw InputError(polygon_path(i + 1),
                                 "overlaps the body polygon ($.body.polygon), for instance at (" + json(x->x() / scale).dump() +
                                     ", " + json(x->y() / scale).dump() + ") (expected them to touch, not overlap)");
            }
        }
        try {
            // The outlines were found simple as they were read (polygon()), and as typed above.
            if (exactly) {
                const std::vector<ExactPolygon> exact_obstacles(scaled->exact.begin() + 1, scaled->exact.end());
                scene.contacts = detail::find_contacts_of_simple(scaled->exact[0], exact_obstacles, options, *scaled, &scene.origins);
            } else if (scaled) {
                scene.contacts = detail::find_contacts_of_simple(body, obstacles, options, *scaled, &scene.origins);
            } else {
                scene.contacts = detail::find_contacts_of_simple(body, obstacles, options, &scene.origins);
            }
        } catch (const std::invalid_argument& e) {
            throw InputError("$", e.what());
        }
        // Decimal vertices and a decimal mu (0.3 is 3/10), exactly.
        exact_found_contacts(scene, exact, mu ? exact_number(*mu) : Rational(), scaled.has_value());
        if (scene.contacts.empty()) {
            throw InputError("$", "the body polygon touches no obstacle (no contacts found)");
        }
    }
    return scene;
}

}  // namespace

namespace json_read {

const Schema& scene_schema() { return kScene; }

Scene scene_of(const Document& doc, InputWarnings* warnings) { return read_scene(doc.root(), warnings); }

}  // namespace json_read

Scene read_scene(const json& doc, InputWarnings* w) { return read_scene(document_of(doc, kScene).root(), w); }

Scene read_scene_text(const std::string& text, InputWarnings* warnings) {
    return read_scene(json_read::read(text, kScene).root(), warnings);
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
