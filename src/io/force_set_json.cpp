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

// The exact [x, y] of field `name` (after the double reader has checked it).
Rational2 exact2(const Value& s, const Path& path, std::string_view name) { return exact_vec2(field(s, path, name)); }

// The exact triples of a list (after vec3_list has checked it), each times a positive number.
std::vector<ExactVector> cleared_triples(const Value& list) {
    std::vector<ExactVector> out;
    list.for_each_element([&](std::size_t, const Value& e) {
        const std::vector<Dyadic> c = clear_denominators(exact_vec3(e));
        out.push_back(ExactVector::from_exact({c[0], c[1], c[2]}));
    });
    return out;
}

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
    // Each number as the decimal it spells (the builders take the doubles' path when every value
    // is a double); the doubles read first for the checks and their messages.
    if (type == "force" || type == "line") {
        (void)vec2(field(s, path, "point"), Path(path, "point"));
        (void)nonzero2(s, path, "direction");
        const Rational2 p = exact2(s, path, "point"), d = exact2(s, path, "direction");
        return type == "force" ? force_ray(p, d) : line_of_force(p, d);
    }
    if (type == "point") {
        (void)vec2(field(s, path, "point"), Path(path, "point"));
        return forces_through_point(exact2(s, path, "point"));
    }
    if (type == "friction_cone") {
        (void)nonnegative(field(s, path, "mu"), Path(path, "mu"), "mu");
        (void)vec2(field(s, path, "point"), Path(path, "point"));
        (void)nonzero2(s, path, "normal");
        return friction_cone(exact2(s, path, "point"), exact2(s, path, "normal"), exact_number(field(s, path, "mu")));
    }
    if (type == "moment") {
        const double sign = number(field(s, path, "sign"), Path(path, "sign"));
        if (sign != 1.0 && sign != -1.0 && sign != 0.0) throw InputError(Path(path, "sign").str(), "expected 1, -1 or 0");
        return pure_moments(static_cast<int>(sign));
    }
    if (type == "wrenches" || type == "halfspaces") {
        const char* name = type == "wrenches" ? "generators" : "normals";
        const Value list = field(s, path, name);
        const std::vector<Vec3> v = vec3_list(list, Path(path, name));
        bool doubles = true;
        list.for_each_element([&](std::size_t, const Value& e) { doubles = doubles && is_double(exact_vec3(e)); });
        if (doubles) return type == "wrenches" ? Cone::from_generators(v) : Cone::from_halfspaces(v);
        const std::vector<ExactVector> g = cleared_triples(list);
        return type == "wrenches" ? Cone::from_generators(g) : Cone::from_halfspaces(g);
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
