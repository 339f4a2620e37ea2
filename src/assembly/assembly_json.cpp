#include "momentlab/assembly/assembly_json.hpp"

#include <cmath>
#include <memory>
#include <optional>

#include "momentlab/geometry/polygon.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/find_contacts.hpp"
#include "../io/json_read.hpp"

namespace momentlab {
namespace {

using nlohmann::json;
using json_read::Path;
using json_read::Schema;
using json_read::Value;
using namespace json_read;

// What the reader keeps of an assembly's document (any other field is a warning).
constexpr Schema::Member kBodyFields[] = {{"name", &kScalar},   {"mass", &kScalar},
                                          {"com", &kPair},      {"inertia", &kScalar},
                                          {"radius_of_gyration", &kScalar}, {"polygon", &kPairs}};
constexpr Schema kBody{kBodyFields};
constexpr Schema kBodies{{}, &kBody};
constexpr Schema::Member kContactFields[] = {{"bodies", &kPair}, {"point", &kPair},      {"normal", &kPair},
                                             {"mu", &kScalar},   {"mu_kinetic", &kScalar}, {"name", &kScalar}};
constexpr Schema kContact{kContactFields};
constexpr Schema kContacts{{}, &kContact};
constexpr Schema::Member kObstacleFields[] = {{"polygon", &kPairs}};
constexpr Schema kObstacle{kObstacleFields};
constexpr Schema kObstacles{{}, &kObstacle};
constexpr Schema::Member kAssemblyFields[] = {{"bodies", &kBodies},           {"body", &kBody},   {"contacts", &kContacts},
                                              {"obstacles", &kObstacles},      {"contact_distance", &kScalar},
                                              {"mu", &kScalar}};
constexpr Schema kAssembly{kAssemblyFields};

double positive(const Value& v, const Path& path) {
    const double x = number(v, path);
    if (!(x > 0.0)) throw InputError(path.str(), "expected a number > 0");
    return x;
}

std::size_t body_index(const Value& v, const Path& path) {
    const char* expected = "expected a body index: 0 (the world) or 1..N";
    if (!v.is_number()) throw InputError(path.str(), expected);
    const double x = v.number().value;
    // an integer as typed: 1.0000000000000000001 rounds to 1 but is not one
    if (std::floor(x) != x || x < 0.0 || x > 1e9 || !exact_number(v).is_double()) throw InputError(path.str(), expected);
    return static_cast<std::size_t>(x);
}

AssemblyBody read_body(const Value& b, const Path& path, InputWarnings* w) {
    if (!b.is_object()) throw InputError(path.str(), "expected an object with \"mass\" and \"com\"");
    known_fields(b, path, {"name", "mass", "com", "inertia", "radius_of_gyration", "polygon"}, w);
    AssemblyBody body;
    if (const std::optional<Value> name = b.find("name")) {
        if (!name->is_string()) throw InputError(Path(path, "name").str(), "expected a string");
        body.name = std::string(name->string());
    }
    const std::optional<Value> mass = b.find("mass");
    if (!mass) throw InputError(path.str(), "missing field \"mass\" (every body needs its mass: gravity acts on it)");
    body.mass = positive(*mass, Path(path, "mass"));
    const Value com = field(b, path, "com");
    body.com = vec2(com, Path(path, "com"));
    const std::optional<Value> inertia = b.find("inertia"), radius = b.find("radius_of_gyration");
    if (inertia) body.inertia = positive(*inertia, Path(path, "inertia"));
    if (radius) {
        if (inertia) throw InputError(Path(path, "radius_of_gyration").str(), "give either \"inertia\" or \"radius_of_gyration\", not both");
        body.radius_of_gyration = positive(*radius, Path(path, "radius_of_gyration"));
    }
    if (const std::optional<Value> p = b.find("polygon")) body.polygon = polygon(*p, Path(path, "polygon"));
    BodyValues doubles;
    doubles.mass_double = body.mass;
    doubles.com_double = body.com;
    doubles.inertia_double = body.inertia.value_or(0.0);
    doubles.radius_double = body.radius_of_gyration;
    body.exact = exact_body_values(b, std::move(doubles));
    return body;
}

AssemblyContact read_contact(const Value& c, const Path& path, InputWarnings* w) {
    if (!c.is_object()) throw InputError(path.str(), "expected an object with \"bodies\", \"point\" and \"normal\"");
    known_fields(c, path, {"bodies", "point", "normal", "mu", "mu_kinetic", "name"}, w);
    const Path pair_path(path, "bodies");
    const Value pair = field(c, path, "bodies");
    if (!pair.is_array() || pair.size() != 2) throw InputError(pair_path.str(), "expected [a, b]: body a (1..N), body b (0 the world, or 1..N)");
    AssemblyContact out;
    pair.for_each_element([&](std::size_t i, const Value& e) { (i == 0 ? out.a : out.b) = body_index(e, Path(pair_path, i)); });
    out.contact = contact_of(c, path);
    return out;
}

// The polygons as typed, bodies' then obstacles', when some vertex is not a double.
std::shared_ptr<const std::vector<std::vector<Rational2>>> exact_polygons(const std::vector<Value>& bodies, const std::optional<Value>& obstacles) {
    auto exact = std::make_shared<std::vector<std::vector<Rational2>>>();
    for (const Value& b : bodies) {
        const std::optional<Value> p = b.find("polygon");
        exact->push_back(p ? exact_polygon(*p) : std::vector<Rational2>{});
    }
    if (obstacles) obstacles->for_each_element([&](std::size_t, const Value& o) { exact->push_back(exact_polygon(*o.find("polygon"))); });
    for (const auto& p : *exact) {
        for (const Rational2& v : p) {
            if (!is_double(v)) return exact;
        }
    }
    return nullptr;
}

// The contacts found from the polygons, as typed (contact_as_typed): on the polygons scaled to
// integers when they are decimals (scaled_polygons: exact doubles, or exact points beyond them),
// else on their doubles.
std::vector<AssemblyContact> found_contacts(const Assembly& a, ContactFinding finding, const Rational& mu) {
    const std::size_t n = a.bodies.size();
    std::optional<ScaledPolygons> scaled;
    if (a.exact_polygons) scaled = scaled_polygons(*a.exact_polygons);
    std::vector<ContactOrigin> origins;
    std::vector<AssemblyContact> found;
    if (scaled) {  // decimals: on the polygons scaled to integers (exact doubles, or exact points)
        found = detail::find_assembly_contacts_of_simple(*scaled, n, finding, &origins);
    } else {
        found = find_assembly_contacts(a.bodies, a.obstacles, finding, &origins);
    }
    // The polygons as typed (bodies' then obstacles'; their doubles when every vertex is one).
    std::vector<std::vector<Rational2>> doubles;
    if (!a.exact_polygons) {
        for (std::size_t k = 0; k < n + a.obstacles.size(); ++k) {
            std::vector<Rational2>& p = doubles.emplace_back();
            for (const Vec2& v : k < n ? a.bodies[k].polygon : a.obstacles[k - n]) p.push_back(rational(v));
        }
    }
    const std::vector<std::vector<Rational2>>& exact = a.exact_polygons ? *a.exact_polygons : doubles;
    for (std::size_t i = 0; i < found.size(); ++i) {
        AssemblyContact& c = found[i];
        const ContactOrigin& o = origins[i];
        // body 1..N, or 0: obstacle o.obstacle
        const auto polygon_of = [&](std::size_t body) -> const std::vector<Rational2>& { return exact[body == 0 ? n + o.obstacle : body - 1]; };
        const std::vector<Rational2>& touching = polygon_of(o.body_vertex ? c.a : c.b);
        const std::vector<Rational2>& touched = polygon_of(o.body_vertex ? c.b : c.a);
        c.contact = contact_as_typed(c.contact, touching[o.vertex], touched[o.edge], touched[(o.edge + 1) % touched.size()], mu,
                                     scaled.has_value());
    }
    return found;
}

Assembly read_bodies(const Value& doc, InputWarnings* w) {
    const Path root("$");
    known_fields(doc, root, {"bodies", "contacts", "obstacles", "contact_distance", "mu"}, w);
    Assembly a;
    const Path bodies_path(root, "bodies");
    const Value list = field(doc, root, "bodies");
    if (!list.is_array() || list.size() == 0) throw InputError(bodies_path.str(), "expected a non-empty list of bodies");
    std::vector<Value> bodies;
    list.for_each_element([&](std::size_t i, const Value& b) {
        a.bodies.push_back(read_body(b, Path(bodies_path, i), w));
        bodies.push_back(b);
    });
    const std::optional<Value> obstacle_list = doc.find("obstacles");
    if (obstacle_list) a.obstacles = obstacles(*obstacle_list, Path(root, "obstacles"), w);
    a.exact_polygons = exact_polygons(bodies, obstacle_list);
    ContactFinding finding;
    if (const std::optional<Value> distance = doc.find("contact_distance")) {
        finding.distance = nonnegative(*distance, Path(root, "contact_distance"), "a distance");
        a.contact_distance = finding.distance;
    }
    const std::optional<Value> mu = doc.find("mu");
    if (const std::optional<Value> contacts = doc.find("contacts")) {
        const Path contacts_path(root, "contacts");
        if (!contacts->is_array()) throw InputError(contacts_path.str(), "expected a list of contacts");
        contacts->for_each_element([&](std::size_t i, const Value& c) { a.contacts.push_back(read_contact(c, Path(contacts_path, i), w)); });
        if (mu && w) w->push_back("$.mu: ignored: it applies to contacts found from the polygons");
    } else {
        if (mu) {
            finding.mu = nonnegative(*mu, Path(root, "mu"), "mu");
            finding.mu_kinetic = finding.mu;
        }
        check_assembly(a);  // the polygons must not overlap before contacts are looked for
        try {
            a.contacts = found_contacts(a, finding, mu ? exact_number(*mu) : Rational());
        } catch (const std::invalid_argument& e) {
            throw InputError("$", e.what());
        }
    }
    check_assembly(a);
    return a;
}

Assembly read_assembly(const Document& doc, const Scene* single, InputWarnings* warnings) {
    const Value root = doc.root();
    if (!root.is_object()) throw InputError("$", "expected a scene object with \"bodies\" (or \"body\")");
    if (root.contains("bodies") && root.contains("body")) throw InputError("$", "give either \"body\" or \"bodies\", not both");
    if (root.contains("bodies")) return read_bodies(root, warnings);
    if (!single || !single->body) throw InputError("$", "missing field \"bodies\" (or \"body\"): stand needs the bodies' masses");
    Assembly a = assembly_of(*single);
    // The polygons as typed: overlap decided on them (the scene reader found its contacts so).
    std::vector<Value> body;
    if (const std::optional<Value> b = root.find("body")) body.push_back(*b);
    a.exact_polygons = exact_polygons(body, root.find("obstacles"));
    check_assembly(a);
    return a;
}

json xy(const Vec2& v) { return json::array({output_value(v.x()), output_value(v.y())}); }

}  // namespace

Assembly read_assembly(const json& doc, InputWarnings* warnings) {
    const Document d = document_of(doc, kAssembly);
    const bool single = d.root().is_object() && !d.root().contains("bodies") && d.root().contains("body");
    const std::optional<Scene> scene = single ? std::optional<Scene>(read_scene(doc, warnings)) : std::nullopt;
    return read_assembly(d, scene ? &*scene : nullptr, warnings);
}

Assembly read_assembly_text(const std::string& text, InputWarnings* warnings) {
    const Document d = json_read::read(text, kAssembly);
    const bool single = d.root().is_object() && !d.root().contains("bodies") && d.root().contains("body");
    const std::optional<Scene> scene = single ? std::optional<Scene>(read_scene_text(text, warnings)) : std::nullopt;
    return read_assembly(d, scene ? &*scene : nullptr, warnings);
}

json to_json(const TiltCone& tilt) {
    json directions = json::array();
    for (const ExactDirection& d : tilt.directions) {
        json v = json::array();
        for (std::size_t i = 0; i < 2; ++i) {
            if (d.is_double[i]) {
                v.push_back(output_value(d.rounded[static_cast<int>(i)]));
            } else {
                v.push_back(d.exact[i]);
            }
        }
        directions.push_back(v);
    }
    return {{"kind", to_string(tilt.kind)}, {"directions", directions}};
}

json to_json(const StandResult& r) {
    json out = {{"can_stand", r.equilibrium.can_stand}};
    if (r.equilibrium.can_stand) {
        json forces = json::array();
        for (const Vec2& f : r.equilibrium.forces) forces.push_back(xy(f));
        out["forces"] = forces;
    } else {
        json mechanism = json::array();
        for (std::size_t k = 0; k < r.equilibrium.mechanism.size(); ++k) {
            const BodyMotion& m = r.equilibrium.mechanism[k];
            mechanism.push_back({{"body", k + 1},
                                 {"twist", json::array({output_value(m.twist.x()), output_value(m.twist.y()),
                                                        output_value(m.twist.z())})},
                                 {"rotation_centre", m.rotation_centre ? xy(*m.rotation_centre) : json(nullptr)}});
        }
        out["mechanism"] = mechanism;
    }
    if (r.modes) {
        out["modes"] = r.modes->modes;
        out["verdict"] = to_string(r.modes->verdict);
        out["motions"] = r.modes->motions;
        out["outcome"] = to_string(*r.outcome);
    } else {
        out["modes"] = nullptr;
        out["modes_reason"] = r.modes_reason;
        out["verdict"] = nullptr;
        out["motions"] = nullptr;
        out["outcome"] = nullptr;
    }
    if (r.tilt) out["tilt"] = to_json(*r.tilt);
    return out;
}

}  // namespace momentlab
