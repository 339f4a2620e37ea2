#include "momentlab/io/force_set_json.hpp"

#include <cmath>
#include <vector>

#include "json_read.hpp"
#include "momentlab/geometry/force_sets.hpp"

namespace momentlab {
namespace {

using nlohmann::json;
using json_read::Path;
using json_read::Schema;
using json_read::Value;
using namespace json_read;

// What the reader keeps of a force-set file: the fields of every type of set (a field of
// another type is kept, and warned about).
extern const Schema kSets;
constexpr Schema::Member kSetFields[] = {{"type", &kScalar},  {"point", &kPair},      {"direction", &kPair},
                                         {"normal", &kPair},  {"mu", &kScalar},       {"sign", &kScalar},
                                         {"generators", &kTriples}, {"normals", &kTriples}, {"sets", &kSets}};
constexpr Schema kSet{kSetFields};
constexpr Schema kSets{{}, &kSet};
constexpr Schema::Member kFileFields[] = {{"combine", &kScalar}, {"sets", &kSets}};
constexpr Schema kFile{kFileFields, &kSet};

// Sets nest through "sum" / "intersection"; deeper nesting than this is rejected rather than
// recursed into (a stack overflow is a crash, not an error message).
constexpr int kMaxDepth = 64;

Cone read_set(const Value& s, const Path& path, InputWarnings* w, int depth);

std::vector<Cone> read_sets(const Value& sets, const Path& path, InputWarnings* w, int depth) {
    if (depth > kMaxDepth) throw InputError(path.str(), "sets nested more than 64 deep");
    if (!sets.is_array()) throw InputError(path.str(), "expected a list of force sets");
    std::vector<Cone> cones;
    sets.for_each_element([&](std::size_t i, const Value& s) { cones.push_back(read_set(s, Path(path, i), w, depth)); });
    return cones;
}

Cone combine(const std::vector<Cone>& cones, bool intersect) {
    if (!intersect) return sum(cones);
    Cone result = Cone::whole_space();
    for (const Cone& c : cones) result = intersection(result, c);
    return result;
}

Cone read_set(const Value& s, const Path& path, InputWarnings* w, int depth) {
    if (!s.is_object()) throw InputError(path.str(), "expected an object with a \"type\"");
    const Value type_field = field(s, path, "type");
    if (!type_field.is_string()) throw InputError(Path(path, "type").str(), "expected a string");
    const std::string type(type_field.string());
    if (type == "force" || type == "line") known_fields(s, path, {"type", "point", "direction"}, w);
    if (type == "point") known_fields(s, path, {"type", "point"}, w);
    if (type == "friction_cone") known_fields(s, path, {"type", "point", "normal", "mu"}, w);
    if (type == "moment") known_fields(s, path, {"type", "sign"}, w);
    if (type == "wrenches") known_fields(s, path, {"type", "generators"}, w);
    if (type == "halfspaces") known_fields(s, path, {"type", "normals"}, w);
    if (type == "sum" || type == "intersection") known_fields(s, path, {"type", "sets"}, w);
    if (type == "force") {
        return force_ray(vec2(field(s, path, "point"), Path(path, "point")), nonzero2(s, path, "direction"));
    }
    if (type == "line") {
        return line_of_force(vec2(field(s, path, "point"), Path(path, "point")), nonzero2(s, path, "direction"));
    }
    if (type == "point") return forces_through_point(vec2(field(s, path, "point"), Path(path, "point")));
    if (type == "friction_cone") {
        const double mu = nonnegative(field(s, path, "mu"), Path(path, "mu"), "mu");
        return friction_cone(vec2(field(s, path, "point"), Path(path, "point")), nonzero2(s, path, "normal"), mu);
    }
    if (type == "moment") {
        const double sign = number(field(s, path, "sign"), Path(path, "sign"));
        if (sign != 1.0 && sign != -1.0 && sign != 0.0) throw InputError(Path(path, "sign").str(), "expected 1, -1 or 0");
        return pure_moments(static_cast<int>(sign));
    }
    if (type == "wrenches") {
        return Cone::from_generators(vec3_list(field(s, path, "generators"), Path(path, "generators")));
    }
    if (type == "halfspaces") {
        return Cone::from_halfspaces(vec3_list(field(s, path, "normals"), Path(path, "normals")));
    }
    if (type == "sum" || type == "intersection") {
        return combine(read_sets(field(s, path, "sets"), Path(path, "sets"), w, depth + 1), type == "intersection");
    }
    throw InputError(Path(path, "type").str(), "unknown type \"" + type +
                                         "\" (expected force, line, point, friction_cone, moment, "
                                         "wrenches, halfspaces, sum or intersection)");
}

ForceSetFile read_parts(const Value& doc, InputWarnings* w) {
    const Path root("$");
    ForceSetFile file;
    if (doc.is_array()) {
        file.parts = read_sets(doc, root, w, 0);
    } else {
        if (!doc.is_object()) throw InputError("$", "expected a list of force sets or an object with \"sets\"");
        known_fields(doc, root, {"combine", "sets"}, w);
        if (const std::optional<Value> c = doc.find("combine")) {
            if (!c->is_string() || (c->string() != "sum" && c->string() != "intersection")) {
                throw InputError("$.combine", "expected \"sum\" or \"intersection\"");
            }
            file.intersect = c->string() == "intersection";
        }
        file.parts = read_sets(field(doc, root, "sets"), Path(root, "sets"), w, 0);
    }
    file.result = combine(file.parts, file.intersect);
    return file;
}

}  // namespace

ForceSetFile read_force_set_parts(const json& doc, InputWarnings* w) { return read_parts(document_of(doc, kFile).root(), w); }

Cone read_force_set(const json& doc, InputWarnings* w) { return read_force_set_parts(doc, w).result; }

ForceSetFile read_force_set_parts_text(const std::string& text, InputWarnings* warnings) {
    return read_parts(json_read::read(text, kFile).root(), warnings);
}

Cone read_force_set_text(const std::string& text, InputWarnings* warnings) {
    return read_force_set_parts_text(text, warnings).result;
}

}  // namespace momentlab
