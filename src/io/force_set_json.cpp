#include "momentlab/io/force_set_json.hpp"

#include <cmath>
#include <vector>

#include "json_read.hpp"
#include "momentlab/geometry/force_sets.hpp"

namespace momentlab {
namespace {

using nlohmann::json;
using namespace json_read;

// Sets nest through "sum" / "intersection"; deeper nesting than this is rejected rather than
// recursed into (a stack overflow is a crash, not an error message).
constexpr int kMaxDepth = 64;

Cone read_set(const json& s, const std::string& path, InputWarnings* w, int depth);

std::vector<Cone> read_sets(const json& sets, const std::string& path, InputWarnings* w, int depth) {
    if (depth > kMaxDepth) throw InputError(path, "sets nested more than 64 deep");
    if (!sets.is_array()) throw InputError(path, "expected a list of force sets");
    std::vector<Cone> cones;
    for (std::size_t i = 0; i < sets.size(); ++i) cones.push_back(read_set(sets[i], at(path, i), w, depth));
    return cones;
}

Cone combine(const std::vector<Cone>& cones, bool intersect) {
    if (!intersect) return sum(cones);
    Cone result = Cone::whole_space();
    for (const Cone& c : cones) result = intersection(result, c);
    return result;
}

Cone read_set(const json& s, const std::string& path, InputWarnings* w, int depth) {
    if (!s.is_object()) throw InputError(path, "expected an object with a \"type\"");
    const json& type_field = field(s, path, "type");
    if (!type_field.is_string()) throw InputError(path + ".type", "expected a string");
    const std::string type = type_field.get<std::string>();
    if (type == "force" || type == "line") known_fields(s, path, {"type", "point", "direction"}, w);
    if (type == "point") known_fields(s, path, {"type", "point"}, w);
    if (type == "friction_cone") known_fields(s, path, {"type", "point", "normal", "mu"}, w);
    if (type == "moment") known_fields(s, path, {"type", "sign"}, w);
    if (type == "wrenches") known_fields(s, path, {"type", "generators"}, w);
    if (type == "halfspaces") known_fields(s, path, {"type", "normals"}, w);
    if (type == "sum" || type == "intersection") known_fields(s, path, {"type", "sets"}, w);
    if (type == "force") {
        return force_ray(vec2(field(s, path, "point"), path + ".point"), nonzero2(s, path, "direction"));
    }
    if (type == "line") {
        return line_of_force(vec2(field(s, path, "point"), path + ".point"), nonzero2(s, path, "direction"));
    }
    if (type == "point") return forces_through_point(vec2(field(s, path, "point"), path + ".point"));
    if (type == "friction_cone") {
        const double mu = nonnegative(field(s, path, "mu"), path + ".mu", "mu");
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
        return combine(read_sets(field(s, path, "sets"), path + ".sets", w, depth + 1), type == "intersection");
    }
    throw InputError(path + ".type", "unknown type \"" + type +
                                         "\" (expected force, line, point, friction_cone, moment, "
                                         "wrenches, halfspaces, sum or intersection)");
}

}  // namespace

ForceSetFile read_force_set_parts(const json& doc, InputWarnings* w) {
    ForceSetFile file;
    if (doc.is_array()) {
        file.parts = read_sets(doc, "$", w, 0);
    } else {
        if (!doc.is_object()) throw InputError("$", "expected a list of force sets or an object with \"sets\"");
        known_fields(doc, "$", {"combine", "sets"}, w);
        if (doc.contains("combine")) {
            const json& c = doc.at("combine");
            if (!c.is_string() || (c != "sum" && c != "intersection")) {
                throw InputError("$.combine", "expected \"sum\" or \"intersection\"");
            }
            file.intersect = c == "intersection";
        }
        file.parts = read_sets(field(doc, "$", "sets"), "$.sets", w, 0);
    }
    file.result = combine(file.parts, file.intersect);
    return file;
}

Cone read_force_set(const json& doc, InputWarnings* w) { return read_force_set_parts(doc, w).result; }

ForceSetFile read_force_set_parts_text(const std::string& text, InputWarnings* warnings) {
    return read_force_set_parts(parse(text), warnings);
}

Cone read_force_set_text(const std::string& text, InputWarnings* warnings) { return read_force_set(parse(text), warnings); }

}  // namespace momentlab
