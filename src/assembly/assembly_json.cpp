#include "momentlab/assembly/assembly_json.hpp"

#include <cmath>

#include "momentlab/geometry/polygon.hpp"
#include "momentlab/io/scene_json.hpp"

namespace momentlab {
namespace {

using nlohmann::json;

std::string at(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

void known(const json& obj, const std::string& path, std::initializer_list<const char*> names, InputWarnings* w) {
    if (!w) return;
    for (const auto& [key, value] : obj.items()) {
        bool found = false;
        for (const char* n : names) found = found || key == n;
        if (!found) w->push_back(path + "." + key + ": unknown field, ignored");
    }
}

const json& field(const json& obj, const std::string& path, const char* name) {
    if (!obj.contains(name)) throw InputError(path, std::string("missing field \"") + name + "\"");
    return obj.at(name);
}

double number(const json& v, const std::string& path) {
    if (!v.is_number()) throw InputError(path, "expected a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || !magnitude_in_range(std::abs(x))) {
        throw InputError(path, "expected a finite number, " + std::string(kMagnitudeRange));
    }
    return x;
}

double positive(const json& v, const std::string& path) {
    const double x = number(v, path);
    if (!(x > 0.0)) throw InputError(path, "expected a number > 0");
    return x;
}

double nonnegative(const json& v, const std::string& path) {
    const double x = number(v, path);
    if (x < 0.0) throw InputError(path, "expected a number >= 0");
    return x;
}

Vec2 vec2(const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 2) throw InputError(path, "expected [x, y]");
    const Vec2 p(number(v[0], path + "[0]"), number(v[1], path + "[1]"));
    return p;
}

Polygon polygon(const json& v, const std::string& path) {
    if (!v.is_array()) throw InputError(path, "expected a list of [x, y]");
    Polygon p;
    for (std::size_t i = 0; i < v.size(); ++i) p.push_back(vec2(v[i], at(path, i)));
    const std::string problem = polygon_problem(p);
    if (!problem.empty()) throw InputError(path, problem);
    return p;
}

std::size_t body_index(const json& v, const std::string& path) {
    if (!v.is_number_integer() && !(v.is_number() && std::floor(v.get<double>()) == v.get<double>())) {
        throw InputError(path, "expected a body index: 0 (the world) or 1..N");
    }
    const double x = v.get<double>();
    if (x < 0.0 || x > 1e9) throw InputError(path, "expected a body index: 0 (the world) or 1..N");
    return static_cast<std::size_t>(x);
}

AssemblyBody read_body(const json& b, const std::string& path, InputWarnings* w) {
    if (!b.is_object()) throw InputError(path, "expected an object with \"mass\" and \"com\"");
    known(b, path, {"name", "mass", "com", "inertia", "radius_of_gyration", "polygon"}, w);
    AssemblyBody body;
    if (b.contains("name")) {
        if (!b.at("name").is_string()) throw InputError(path + ".name", "expected a string");
        body.name = b.at("name").get<std::string>();
    }
    if (!b.contains("mass")) throw InputError(path, "missing field \"mass\" (every body needs its mass: gravity acts on it)");
    body.mass = positive(b.at("mass"), path + ".mass");
    body.com = vec2(field(b, path, "com"), path + ".com");
    if (b.contains("inertia")) body.inertia = positive(b.at("inertia"), path + ".inertia");
    if (b.contains("radius_of_gyration")) {
        if (body.inertia) {
            throw InputError(path + ".radius_of_gyration", "give either \"inertia\" or \"radius_of_gyration\", not both");
        }
        body.radius_of_gyration = positive(b.at("radius_of_gyration"), path + ".radius_of_gyration");
    }
    if (b.contains("polygon")) body.polygon = polygon(b.at("polygon"), path + ".polygon");
    return body;
}

AssemblyContact read_contact(const json& c, const std::string& path, InputWarnings* w) {
    if (!c.is_object()) throw InputError(path, "expected an object with \"bodies\", \"point\" and \"normal\"");
    known(c, path, {"bodies", "point", "normal", "mu", "mu_kinetic", "name"}, w);
    const json& pair = field(c, path, "bodies");
    if (!pair.is_array() || pair.size() != 2) throw InputError(path + ".bodies", "expected [a, b]: body a (1..N), body b (0 the world, or 1..N)");
    AssemblyContact out;
    out.a = body_index(pair[0], path + ".bodies[0]");
    out.b = body_index(pair[1], path + ".bodies[1]");
    const Vec2 point = vec2(field(c, path, "point"), path + ".point");
    const Vec2 normal = vec2(field(c, path, "normal"), path + ".normal");
    if (normal.x() == 0.0 && normal.y() == 0.0) throw InputError(path + ".normal", "expected a non-zero normal");
    const double mu = c.contains("mu") ? nonnegative(c.at("mu"), path + ".mu") : 0.0;
    std::optional<double> kinetic;
    if (c.contains("mu_kinetic")) kinetic = nonnegative(c.at("mu_kinetic"), path + ".mu_kinetic");
    std::string name;
    if (c.contains("name")) {
        if (!c.at("name").is_string()) throw InputError(path + ".name", "expected a string");
        name = c.at("name").get<std::string>();
    }
    out.contact = Contact::make(point, normal, mu, kinetic, name);
    return out;
}

Assembly read_bodies(const json& doc, InputWarnings* w) {
    known(doc, "$", {"bodies", "contacts", "obstacles", "contact_distance", "mu"}, w);
    Assembly a;
    const json& bodies = doc.at("bodies");
    if (!bodies.is_array() || bodies.empty()) throw InputError("$.bodies", "expected a non-empty list of bodies");
    for (std::size_t i = 0; i < bodies.size(); ++i) a.bodies.push_back(read_body(bodies[i], at("$.bodies", i), w));
    if (doc.contains("obstacles")) {
        const json& obstacles = doc.at("obstacles");
        if (!obstacles.is_array()) throw InputError("$.obstacles", "expected a list of obstacles");
        for (std::size_t i = 0; i < obstacles.size(); ++i) {
            const std::string p = at("$.obstacles", i);
            if (!obstacles[i].is_object()) throw InputError(p, "expected an object with \"polygon\"");
            known(obstacles[i], p, {"polygon"}, w);
            a.obstacles.push_back(polygon(field(obstacles[i], p, "polygon"), p + ".polygon"));
        }
    }
    ContactFinding finding;
    if (doc.contains("contact_distance")) {
        finding.distance = nonnegative(doc.at("contact_distance"), "$.contact_distance");
        a.contact_distance = finding.distance;
    }
    if (doc.contains("contacts")) {
        const json& contacts = doc.at("contacts");
        if (!contacts.is_array()) throw InputError("$.contacts", "expected a list of contacts");
        for (std::size_t i = 0; i < contacts.size(); ++i) a.contacts.push_back(read_contact(contacts[i], at("$.contacts", i), w));
        if (doc.contains("mu") && w) w->push_back("$.mu: ignored: it applies to contacts found from the polygons");
    } else {
        if (doc.contains("mu")) {
            finding.mu = nonnegative(doc.at("mu"), "$.mu");
            finding.mu_kinetic = finding.mu;
        }
        check_assembly(a);  // the polygons must not overlap before contacts are looked for
        try {
            a.contacts = find_assembly_contacts(a.bodies, a.obstacles, finding);
        } catch (const std::invalid_argument& e) {
            throw InputError("$", e.what());
        }
    }
    check_assembly(a);
    return a;
}

json xy(const Vec2& v) { return json::array({output_value(v.x()), output_value(v.y())}); }

}  // namespace

Assembly read_assembly(const json& doc, InputWarnings* warnings) {
    if (!doc.is_object()) throw InputError("$", "expected a scene object with \"bodies\" (or \"body\")");
    if (doc.contains("bodies") && doc.contains("body")) throw InputError("$", "give either \"body\" or \"bodies\", not both");
    if (doc.contains("bodies")) return read_bodies(doc, warnings);
    Assembly a = assembly_of([&] {
        Scene s = read_scene(doc, warnings);
        if (!s.body) throw InputError("$", "missing field \"bodies\" (or \"body\"): stand needs the bodies' masses");
        return s;
    }());
    check_assembly(a);
    return a;
}

Assembly read_assembly_text(const std::string& text, InputWarnings* warnings) {
    if (const std::optional<std::string> bad = underflowing_number(text)) {
        throw InputError("$", "the number " + *bad + " is too small for a double (it would be taken as 0)");
    }
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        throw InputError("$", std::string("not valid JSON: ") + e.what());
    }
    return read_assembly(doc, warnings);
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
