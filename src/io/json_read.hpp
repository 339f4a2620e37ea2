#pragma once

// Typed access to JSON fields; every failure is an InputError naming the field's path.

#include <nlohmann/json.hpp>
#include <array>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <string>
#include <vector>

#include "momentlab/core/vec.hpp"
#include "momentlab/io/input_error.hpp"

namespace momentlab::json_read {

using nlohmann::json;

const json& field(const json& obj, const std::string& path, const char* name);
/// A finite number of magnitude 0 or in [kSmallestMagnitude, kLargestMagnitude].
double number(const json& v, const std::string& path);
/// A number (as above) that must be >= 0; the error says "expected <what> >= 0".
double nonnegative(const json& v, const std::string& path, const char* what);
/// A vector of finite coordinates of magnitude at most kLargestMagnitude, zero or with its
/// largest coordinate at least kSmallestMagnitude (a direction like [1e-300, 1] is fine).
Vec2 vec2(const json& v, const std::string& path);
/// The vector [x, y] of two values read apart, checked as vec2 checks it.
Vec2 vec2(const json& x, const json& y, const std::string& path);
Vec3 vec3(const json& v, const std::string& path);
std::vector<Vec3> vec3_list(const json& v, const std::string& path);
std::vector<Vec2> vec2_list(const json& v, const std::string& path);
/// A point [x, y] as written, before any check: its coordinates as the JSON library stores them.
using PlainPoint = std::array<json, 2>;
/// vec2_list of a list the plain reader took apart.
std::vector<Vec2> vec2_list(const std::vector<PlainPoint>& points, const std::string& path);
/// A non-zero [x, y] in field `name` of `obj`.
Vec2 nonzero2(const json& obj, const std::string& path, const char* name);
/// v, unless it is zero (an InputError at path).
Vec2 nonzero(const Vec2& v, const std::string& path);
/// Adds a warning for each field of `obj` not in `known` (when `warnings` is given).
void known_fields(const json& obj, const std::string& path, std::initializer_list<const char*> known,
                  InputWarnings* warnings);
/// `path[i]`.
std::string at(const std::string& path, std::size_t i);
/// Parses text; malformed JSON is an InputError at "$".
json parse(const std::string& text);
/// The document of a text in the plain JSON that programs write (ASCII strings without
/// escapes, numbers that convert without underflow or overflow, no repeated key, depth at
/// most 64), exactly as parse_by_library gives it; nullopt for any other text.
std::optional<json> parse_plain(std::string_view text);
/// parse by the JSON library alone, with the checks of parse (repeated keys, underflow).
json parse_by_library(const std::string& text);

/// A contact of a scene as written, before any check: the coordinates of "point" and "normal"
/// and the optional fields, as the JSON library would store them.
struct PlainContact {
    PlainPoint point, normal;
    std::optional<json> mu, mu_kinetic, name;
};
/// A plain text (as parse_plain) read for a scene, with its long lists taken apart instead of
/// made into documents of small arrays and objects (their members in doc are null):
///  * `contacts`: the top-level "contacts" when it is a non-empty list of objects with exactly
///    the fields of a contact, "point" and "normal" among them as two numbers each;
///  * `body_polygon`, `obstacle_polygons[i]`: "polygon" of the top-level "body" and of
///    "obstacles"[i] when it is a non-empty list of [x, y] (numbers).
/// What is not so (empty contacts, absent polygons) is in doc as parse_plain has it.
struct PlainScene {
    json doc;
    std::vector<PlainContact> contacts;
    std::optional<std::vector<PlainPoint>> body_polygon;
    std::vector<std::optional<std::vector<PlainPoint>>> obstacle_polygons;  // may be shorter than "obstacles"
};
std::optional<PlainScene> parse_plain_scene(std::string_view text);

}  // namespace momentlab::json_read
