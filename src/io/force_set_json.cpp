#include "momentlab/io/force_set_json.hpp"

#include <cmath>
#include <vector>

#include "momentlab/geometry/force_sets.hpp"

namespace momentlab {
namespace {

using nlohmann::json;

const json& field(const json& obj, const std::string& path, const char* name) {
    if (!obj.contains(name)) throw InputError(path, std::string("missing field \"") + name + "\"");
    return obj.at(name);
}

double number(const json& v, const std::string& path) {
    if (!v.is_number()) throw InputError(path, "expected a number, got " + std::string(v.type_name()));
    const double x = v.get<double>();
    if (!std::isfinite(x)) throw InputError(path, "expected a finite number");
    return x;
}

Vec2 vec2(const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 2) throw InputError(path, "expected [x, y]");
    return Vec2(number(v[0], path + "[0]"), number(v[1], path + "[1]"));
}

Vec3 vec3(const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 3) throw InputError(path, "expected [a, b, c]");
    return Vec3(number(v[0], path + "[0]"), number(v[1], path + "[1]"), number(v[2], path + "[2]"));
}

std::vector<Vec3> vec3_list(const json& v, const std::string& path) {
    if (!v.is_array()) throw InputError(path, "expected a list of [a, b, c]");
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(vec3(v[i], path + "[" + std::to_string(i) + "]"));
    return out;
}

Vec2 nonzero2(const json& obj, const std::string& path, const char* name) {
    const std::string p = path + "." + name;
    const Vec2 v = vec2(field(obj, path, name), p);
    if (v.x() == 0.0 && v.y() == 0.0) throw InputError(p, "expected a non-zero vector");
    return v;
}

Cone read_set(const json& s, const std::string& path);

Cone combine(const json& sets, const std::string& path, bool intersect) {
    if (!sets.is_array()) throw InputError(path, "expected a list of force sets");
    std::vector<Cone> cones;
    for (std::size_t i = 0; i < sets.size(); ++i) cones.push_back(read_set(sets[i], path + "[" + std::to_string(i) + "]"));
    if (!intersect) return sum(cones);
    Cone result = Cone::whole_space();
    for (const Cone& c : cones) result = intersection(result, c);
    return result;
}

Cone read_set(const json& s, const std::string& path) {
    if (!s.is_object()) throw InputError(path, "expected an object with a \"type\"");
    const json& type_field = field(s, path, "type");
    if (!type_field.is_string()) throw InputError(path + ".type", "expected a string");
    const std::string type = type_field.get<std::string>();
    if (type == "force") {
        return force_ray(vec2(field(s, path, "point"), path + ".point"), nonzero2(s, path, "direction"));
    }
    if (type == "line") {
        return line_of_force(vec2(field(s, path, "point"), path + ".point"), nonzero2(s, path, "direction"));
    }
    if (type == "point") return forces_through_point(vec2(field(s, path, "point"), path + ".point"));
    if (type == "friction_cone") {
        const double mu = number(field(s, path, "mu"), path + ".mu");
        if (mu < 0.0) throw InputError(path + ".mu", "expected mu >= 0");
        return friction_cone(vec2(field(s, path, "point"), path + ".point"), nonzero2(s, path, "normal"), mu);
    }
    if (type == "moment") {
        const double sign = number(field(s, path, "sign"), path + ".sign");
        if (sign != 1.0 && sign != -1.0 && sign != 0.0) throw InputError(path + ".sign", "expected 1, -1 or 0");
        return pure_moments(static_cast<int>(sign));
    }
    if (type == "wrenches") {
        return Cone::from_generators(vec3_list(field(s, path, "generators"), path + ".generators"));
    }
    if (type == "halfspaces") {
        return Cone::from_halfspaces(vec3_list(field(s, path, "normals"), path + ".normals"));
    }
    if (type == "sum" || type == "intersection") {
        return combine(field(s, path, "sets"), path + ".sets", type == "intersection");
    }
    throw InputError(path + ".type", "unknown type \"" + type +
                                         "\" (expected force, line, point, friction_cone, moment, "
                                         "wrenches, halfspaces, sum or intersection)");
}

}  // namespace

Cone read_force_set(const json& doc) {
    if (doc.is_array()) return combine(doc, "$", false);
    if (!doc.is_object()) throw InputError("$", "expected a list of force sets or an object with \"sets\"");
    std::string how = "sum";
    if (doc.contains("combine")) {
        const json& c = doc.at("combine");
        if (!c.is_string() || (c != "sum" && c != "intersection")) {
            throw InputError("$.combine", "expected \"sum\" or \"intersection\"");
        }
        how = c.get<std::string>();
    }
    return combine(field(doc, "$", "sets"), "$.sets", how == "intersection");
}

Cone read_force_set_text(const std::string& text) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        throw InputError("$", std::string("malformed JSON: ") + e.what());
    }
    return read_force_set(doc);
}

}  // namespace momentlab
