#include "json_read.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <set>

namespace momentlab::json_read {

const json& field(const json& obj, const std::string& path, const char* name) {
    if (!obj.contains(name)) throw InputError(path, std::string("missing field \"") + name + "\"");
    return obj.at(name);
}

namespace {

// A finite number of magnitude at most kLargestMagnitude.
double coordinate(const json& v, const std::string& path) {
    if (!v.is_number()) throw InputError(path, "expected a number, got " + std::string(v.type_name()));
    const double x = v.get<double>();
    if (!std::isfinite(x)) throw InputError(path, "expected a finite number");
    if (!(std::abs(x) <= kLargestMagnitude)) {
        throw InputError(path, "the magnitude of " + v.dump() + " is out of range (expected 0 or 1e-60 .. 1e60)");
    }
    return x;
}

// A vector is 0 or has its largest coordinate in range; single coordinates may be tiny.
template <class V>
V checked(const V& v, const std::string& path) {
    if (!magnitude_in_range(v.cwiseAbs().maxCoeff())) {
        throw InputError(path, "the vector's magnitude is out of range (expected 0 or 1e-60 .. 1e60)");
    }
    return v;
}

// What coordinate() accepts, decided without the path that only names an error.
bool plain_coordinate(const json& v) {
    if (!v.is_number()) return false;
    const double x = v.get<double>();
    return std::isfinite(x) && std::abs(x) <= kLargestMagnitude;
}

// The vector vec2(x, y, path) returns when it returns one without an error; nullopt where it
// would throw (no path is needed to decide).
std::optional<Vec2> accepted_vec2(const json& x, const json& y) {
    if (!plain_coordinate(x) || !plain_coordinate(y)) return std::nullopt;
    const Vec2 v(x.get<double>(), y.get<double>());
    if (!magnitude_in_range(v.cwiseAbs().maxCoeff())) return std::nullopt;
    return v;
}

}  // namespace

double number(const json& v, const std::string& path) {
    const double x = coordinate(v, path);
    if (!magnitude_in_range(std::abs(x))) {
        throw InputError(path, "the magnitude of " + v.dump() + " is out of range (expected 0 or 1e-60 .. 1e60)");
    }
    return x;
}

double nonnegative(const json& v, const std::string& path, const char* what) {
    const double x = number(v, path);
    if (x < 0.0) throw InputError(path, std::string("expected ") + what + " >= 0");
    return x;
}

Vec2 vec2(const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 2) throw InputError(path, "expected [x, y]");
    return vec2(v[0], v[1], path);
}

Vec2 vec2(const json& x, const json& y, const std::string& path) {
    if (const std::optional<Vec2> v = accepted_vec2(x, y)) return *v;
    const double a = coordinate(x, path + "[0]");  // in order: an error names the first bad coordinate
    const double b = coordinate(y, path + "[1]");
    return checked(Vec2(a, b), path);
}

Vec3 vec3(const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 3) throw InputError(path, "expected [a, b, c]");
    const double a = coordinate(v[0], path + "[0]");  // in order, as in vec2
    const double b = coordinate(v[1], path + "[1]");
    const double c = coordinate(v[2], path + "[2]");
    return checked(Vec3(a, b, c), path);
}

std::vector<Vec3> vec3_list(const json& v, const std::string& path) {
    if (!v.is_array()) throw InputError(path, "expected a list of [a, b, c]");
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(vec3(v[i], at(path, i)));
    return out;
}

Vec2 nonzero2(const json& obj, const std::string& path, const char* name) {
    const std::string p = path + "." + name;
    return nonzero(vec2(field(obj, path, name), p), p);
}

Vec2 nonzero(const Vec2& v, const std::string& path) {
    if (v.x() == 0.0 && v.y() == 0.0) throw InputError(path, "expected a non-zero vector");
    return v;
}

namespace {

// vec2(x, y, at(path, i)), with the element's path made only for an error (10^6 vertices
// would make 10^6 path strings).
Vec2 element_vec2(const json& x, const json& y, const std::string& path, std::size_t i) {
    const std::optional<Vec2> v = accepted_vec2(x, y);
    return v ? *v : vec2(x, y, at(path, i));
}

}  // namespace

std::vector<Vec2> vec2_list(const json& v, const std::string& path) {
    if (!v.is_array()) throw InputError(path, "expected a list of [x, y]");
    std::vector<Vec2> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        const json& e = v[i];
        out.push_back(e.is_array() && e.size() == 2 ? element_vec2(e[0], e[1], path, i) : vec2(e, at(path, i)));
    }
    return out;
}

std::vector<Vec2> vec2_list(const std::vector<PlainPoint>& points, const std::string& path) {
    std::vector<Vec2> out;
    out.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) out.push_back(element_vec2(points[i][0], points[i][1], path, i));
    return out;
}

void known_fields(const json& obj, const std::string& path, std::initializer_list<const char*> known,
                  InputWarnings* warnings) {
    if (warnings == nullptr || !obj.is_object()) return;
    for (const auto& [key, value] : obj.items()) {
        bool found = false;
        for (const char* k : known) found = found || key == k;
        if (found) continue;
        std::string expected;
        for (const char* k : known) expected += std::string(expected.empty() ? "" : ", ") + k;
        warnings->push_back(path + "." + key + ": unknown field, ignored (expected " + expected + ")");
    }
}

std::string at(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

namespace {

// The containers open while parsing, to name the path of a repeated key. Each holds the keys
// seen so far and how the container sits in its parent.
struct Frame {
    static constexpr std::size_t kFewKeys = 16;

    bool is_array = false;
    std::size_t count = 0;                   // elements seen (arrays)
    std::string key;                         // the last key read (objects)
    std::vector<std::string> keys;           // the first kFewKeys keys seen (a linear search)
    std::set<std::string, std::less<>> many;  // all the keys seen, once there are more

    // Records key; false when it was seen before.
    bool add(const std::string& k) {
        if (keys.size() < kFewKeys) {
            if (std::find(keys.begin(), keys.end(), k) != keys.end()) return false;
            keys.push_back(k);
            return true;
        }
        if (many.empty()) many.insert(keys.begin(), keys.end());
        return many.insert(k).second;
    }
};

// The path of the element being read: each open container's place in its parent, then the
// innermost one's current key or index.
std::string path_of(const std::vector<Frame>& stack) {
    std::string path = "$";
    for (std::size_t i = 0; i < stack.size(); ++i) {
        if (stack[i].is_array) {
            path.append(1, '[').append(std::to_string(stack[i].count - 1)).append(1, ']');
        } else {
            path.append(1, '.').append(stack[i].key);
        }
    }
    return path;
}

// Calls f(token) for each number of a JSON text, in order: the tokens outside strings that
// start with '-' or a digit.
template <class F>
void for_each_number(std::string_view text, F f) {
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
            continue;
        }
        if (c == '"') {
            in_string = true;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            std::size_t end = i + 1;
            const auto in_number = [](char d) {
                return (d >= '0' && d <= '9') || d == '+' || d == '-' || d == '.' || d == 'e' || d == 'E';
            };
            while (end < text.size() && in_number(text[end])) ++end;
            f(text.substr(i, end - i));
            i = end - 1;
        }
    }
}

bool underflows(std::string_view token) {
    if (!nonzero_digits(token)) return false;
    // Without an exponent, a number below the smallest double (about 4.9e-324) needs over 300
    // digits: the usual coordinate is decided without converting it.
    if (token.find_first_of("eEpP") == std::string_view::npos && token.size() < 300) return false;
    return std::strtod(std::string(token).c_str(), nullptr) == 0.0;
}

// For each number of the text, in order: whether it underflows. Empty when none does, the
// usual case.
std::vector<bool> underflowing_numbers(std::string_view text) {
    std::vector<bool> flags;
    bool any = false;
    for_each_number(text, [&](std::string_view token) {
        flags.push_back(underflows(token));
        any = any || flags.back();
    });
    if (!any) flags.clear();
    return flags;
}

// The document builder of the JSON library, with the checks of `parse` on each event. (The
// library's callback parser rescans a parent array for discarded elements after every object:
// quadratic time on a list of 10^5 contacts.)
class CheckedBuilder {
public:
    explicit CheckedBuilder(json& result, const std::vector<bool>& underflow) : dom_(result), underflow_(underflow) {}

    bool null() { return element() && dom_.null(); }
    bool boolean(bool v) { return element() && dom_.boolean(v); }
    bool number_integer(json::number_integer_t v) { return number() && dom_.number_integer(v); }
    bool number_unsigned(json::number_unsigned_t v) { return number() && dom_.number_unsigned(v); }
    bool number_float(json::number_float_t v, const json::string_t& s) { return number() && dom_.number_float(v, s); }
    bool string(json::string_t& v) { return element() && dom_.string(v); }
    bool binary(json::binary_t& v) { return element() && dom_.binary(v); }
    bool start_object(std::size_t n) { return open(false) && dom_.start_object(n); }
    bool start_array(std::size_t n) { return open(true) && dom_.start_array(n); }
    bool end_object() { return close() && dom_.end_object(); }
    bool end_array() { return close() && dom_.end_array(); }
    bool key(json::string_t& k) {
        Frame& f = stack_.back();
        f.key = k;
        if (!f.add(k)) throw InputError(path_of(stack_), "duplicate key (each key may appear once in an object)");
        return dom_.key(k);
    }
    template <class Exception>
    bool parse_error(std::size_t position, const std::string& token, const Exception& e) {
        return dom_.parse_error(position, token, e);
    }

private:
    bool element() {
        if (!stack_.empty() && stack_.back().is_array) ++stack_.back().count;
        return true;
    }
    bool number() {
        element();
        if (!underflow_.empty() && underflow_[numbers_++]) {
            throw InputError(path_of(stack_), "a number too small for a double: it would be taken as 0 "
                                              "(expected 0 or a magnitude 1e-60 .. 1e60)");
        }
        return true;
    }
    bool open(bool is_array) {
        element();
        stack_.push_back(Frame{is_array, 0, {}, {}, {}});
        if (!spare_keys_.empty()) {  // a closed object's list, kept for its capacity
            stack_.back().keys = std::move(spare_keys_.back());
            spare_keys_.pop_back();
        }
        return true;
    }
    bool close() {
        if (stack_.empty()) return true;
        if (stack_.back().keys.capacity() != 0) {
            stack_.back().keys.clear();
            spare_keys_.push_back(std::move(stack_.back().keys));
        }
        stack_.pop_back();
        return true;
    }

    nlohmann::detail::json_sax_dom_parser<json> dom_;
    const std::vector<bool>& underflow_;
    std::vector<Frame> stack_;
    std::vector<std::vector<std::string>> spare_keys_;
    std::size_t numbers_ = 0;
};

// A reader of the plain JSON that programs write: ASCII strings without escapes, numbers
// that convert without underflow or overflow, no repeated key, at most kMaxDepth levels. It
// reads such a text in one pass over its characters, about three times faster than the
// library's reader on a scene of 10^5 contacts (0.10 s against 0.34 s for the 9 MB bowl of
// docs/benchmarks.md: the library reads a character at a time through its input adapter and
// copies each token), and gives up on anything else, which the library then reads and reports.
class PlainReader {
public:
    // scene: where a scene's contacts and polygons go when they are plain (PlainScene), or
    // nullptr to read any document.
    PlainReader(std::string_view text, PlainScene* scene) : p_(text.data()), end_(text.data() + text.size()), scene_(scene) {}

    std::optional<json> document() {
        json out;
        if (!value(out, 0, scene_ ? Place::Scene : Place::Other)) return std::nullopt;
        skip_space();
        if (p_ != end_) return std::nullopt;
        return out;
    }

private:
    static constexpr int kMaxDepth = 64;

    // Where a value sits in a scene: the places whose lists the scene reader takes apart.
    enum class Place { Other, Scene, Body, Obstacles, Obstacle };

    static bool digit(char c) { return c >= '0' && c <= '9'; }

    void skip_space() {
        while (p_ != end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t')) ++p_;
    }

    // Whether the text continues with c (after white space); consumes it if so.
    bool next_is(char c) {
        skip_space();
        if (p_ == end_ || *p_ != c) return false;
        ++p_;
        return true;
    }

    bool value(json& out, int depth, Place place = Place::Other) {
        skip_space();
        if (p_ == end_) return false;
        switch (*p_) {
            case '{': return object(out, depth, place);
            case '[': return array(out, depth, place);
            case '"': {
                std::string s;
                if (!string(s)) return false;
                out = std::move(s);
                return true;
            }
            case 't': return literal("true", out, json(true));
            case 'f': return literal("false", out, json(false));
            case 'n': return literal("null", out, json(nullptr));
            default: return number(out);
        }
    }

    bool object(json& out, int depth, Place place) {
        if (depth == kMaxDepth) return false;
        ++p_;
        out = json::object();
        auto& members = out.get_ref<json::object_t&>();
        if (next_is('}')) return true;
        do {
            std::string key;
            if (!member_key(key)) return false;
            // The member's place, and where its list goes if it is taken apart.
            Place inner = Place::Other;
            std::optional<std::vector<PlainPoint>>* polygon = nullptr;
            bool contacts = false;
            if (place == Place::Scene) {
                contacts = key == "contacts";
                inner = key == "body" ? Place::Body : key == "obstacles" ? Place::Obstacles : Place::Other;
            } else if (key == "polygon" && place == Place::Body) {
                polygon = &scene_->body_polygon;
            } else if (key == "polygon" && place == Place::Obstacle) {
                if (scene_->obstacle_polygons.size() <= obstacle_) scene_->obstacle_polygons.resize(obstacle_ + 1);
                polygon = &scene_->obstacle_polygons[obstacle_];
            }
            const auto [member, inserted] = members.emplace(std::move(key), json());
            if (!inserted) return false;  // a repeated key: the library names its path
            // A list taken apart leaves the member null.
            if ((contacts && contact_list()) || (polygon && point_list(*polygon))) continue;
            if (!value(member->second, depth + 1, inner)) return false;
        } while (next_is(','));
        return next_is('}');
    }

    // A non-empty list of [x, y] (numbers), into points. On anything else, false with the
    // position and points as they were.
    bool point_list(std::optional<std::vector<PlainPoint>>& points) {
        std::vector<PlainPoint> list;
        if (!list_of([&] { return pair(list.emplace_back()); })) return false;
        points = std::move(list);
        return true;
    }

    // A non-empty list of contacts, each an object of "point" and "normal" (two numbers each)
    // and optionally "mu", "mu_kinetic" (numbers) and "name" (a string), into the scene. On
    // anything else, false with the position and the list as they were.
    bool contact_list() {
        if (list_of([&] { return next_is('{') && contact(scene_->contacts.emplace_back()); })) return true;
        scene_->contacts.clear();
        return false;
    }

    // A non-empty list whose every element item() reads; false, with the position as it was,
    // at the first element it cannot read or anything else.
    template <class Item>
    bool list_of(Item item) {
        const char* const start = p_;
        if (next_is('[')) {
            do {
                if (!item()) break;
                if (next_is(']')) return true;
            } while (next_is(','));
        }
        p_ = start;
        return false;
    }

    // [x, y] of two numbers.
    bool pair(PlainPoint& xy) {
        return next_is('[') && scalar_number(xy[0]) && next_is(',') && scalar_number(xy[1]) && next_is(']');
    }

    bool contact(PlainContact& c) {
        static constexpr std::string_view kFields[] = {"point", "normal", "mu", "mu_kinetic", "name"};
        unsigned seen = 0;
        do {
            std::string key;
            if (!member_key(key)) return false;
            const auto field = static_cast<unsigned>(std::find(std::begin(kFields), std::end(kFields), key) - std::begin(kFields));
            if (field == std::size(kFields) || (seen & (1u << field)) != 0) return false;
            seen |= 1u << field;
            bool read = false;
            if (field <= 1) {
                read = pair(field == 0 ? c.point : c.normal);
            } else if (field <= 3) {
                read = scalar_number((field == 2 ? c.mu : c.mu_kinetic).emplace());
            } else {
                skip_space();
                std::string name;
                read = p_ != end_ && *p_ == '"' && string(name);
                c.name = std::move(name);
            }
            if (!read) return false;
        } while (next_is(','));
        return (seen & 3u) == 3u && next_is('}');
    }

    bool scalar_number(json& out) {
        skip_space();
        return p_ != end_ && (*p_ == '-' || digit(*p_)) && number(out);
    }

    bool array(json& out, int depth, Place place) {
        if (depth == kMaxDepth) return false;
        ++p_;
        out = json::array();
        auto& elements = out.get_ref<json::array_t&>();
        if (next_is(']')) return true;
        do {
            if (place == Place::Obstacles) obstacle_ = elements.size();
            elements.emplace_back();
            if (!value(elements.back(), depth + 1, place == Place::Obstacles ? Place::Obstacle : Place::Other)) return false;
        } while (next_is(','));
        return next_is(']');
    }

    // A member's key and the colon after it.
    bool member_key(std::string& key) {
        skip_space();
        return p_ != end_ && *p_ == '"' && string(key) && next_is(':');
    }

    // ASCII from the space to DEL between quotes, with no escape.
    bool string(std::string& out) {
        const char* start = ++p_;
        for (; p_ != end_; ++p_) {
            const auto c = static_cast<unsigned char>(*p_);
            if (c == '"') {
                out.assign(start, p_++);
                return true;
            }
            if (c < 0x20 || c == '\\' || c >= 0x80) return false;
        }
        return false;
    }

    bool literal(std::string_view word, json& out, json v) {
        if (static_cast<std::size_t>(end_ - p_) < word.size() || std::string_view(p_, word.size()) != word) return false;
        p_ += word.size();
        out = std::move(v);
        return true;
    }

    // JSON's number grammar; the value as the library stores it: an integer without fraction
    // or exponent (unsigned unless negative), else a double.
    bool number(json& out) {
        const char* const start = p_;
        const char* q = p_;
        const bool negative = *q == '-';
        if (negative) ++q;
        if (q == end_ || !digit(*q)) return false;
        if (*q == '0') {
            ++q;
        } else {
            while (q != end_ && digit(*q)) ++q;
        }
        const char* const integer_end = q;
        bool fraction_or_exponent = false;
        if (q != end_ && *q == '.') {
            const char* const digits = ++q;
            while (q != end_ && digit(*q)) ++q;
            if (q == digits) return false;
            fraction_or_exponent = true;
        }
        if (q != end_ && (*q == 'e' || *q == 'E')) {
            ++q;
            if (q != end_ && (*q == '+' || *q == '-')) ++q;
            const char* const digits = q;
            while (q != end_ && digit(*q)) ++q;
            if (q == digits) return false;
            fraction_or_exponent = true;
        }
        p_ = q;
        if (!fraction_or_exponent) {
            const char* d = start + (negative ? 1 : 0);
            if (integer_end - d > 18) return false;  // may not fit 64 bits: the library decides
            std::uint64_t v = 0;
            for (; d != integer_end; ++d) v = v * 10 + static_cast<std::uint64_t>(*d - '0');
            if (negative) {
                out = -static_cast<std::int64_t>(v);
            } else {
                out = v;
            }
            return true;
        }
#if defined(__cpp_lib_to_chars)
        double x = 0.0;
        const auto [end, error] = std::from_chars(start, q, x);
        if (error != std::errc() || end != q || !std::isfinite(x)) return false;
        if (x == 0.0 && nonzero_digits(std::string_view(start, static_cast<std::size_t>(q - start)))) return false;
        out = x;
        return true;
#else
        return false;  // no exact conversion without a locale: the library reads the text
#endif
    }

    const char* p_;
    const char* end_;
    PlainScene* scene_;
    std::size_t obstacle_ = 0;  // the index of the obstacle being read
};

}  // namespace

std::optional<json> parse_plain(std::string_view text) { return PlainReader(text, nullptr).document(); }

std::optional<PlainScene> parse_plain_scene(std::string_view text) {
    PlainScene out;
    std::optional<json> doc = PlainReader(text, &out).document();
    if (!doc) return std::nullopt;
    out.doc = std::move(*doc);
    return out;
}

json parse(const std::string& text) {
    if (std::optional<json> doc = parse_plain(text)) return std::move(*doc);
    return parse_by_library(text);
}

json parse_by_library(const std::string& text) {
    // Duplicate keys are an error: JSON parsers differ on which one wins, so a file with two
    // "mu" fields means different scenes to different programs.
    const std::vector<bool> underflow = underflowing_numbers(text);
    json result;
    CheckedBuilder builder(result, underflow);
    try {
        json::sax_parse(text, &builder);
    } catch (const json::parse_error& e) {
        throw InputError("$", std::string("malformed JSON: ") + e.what());
    } catch (const json::out_of_range& e) {  // e.g. 1e999: too large for a double
        throw InputError("$", std::string("a number is out of range (expected 0 or 1e-60 .. 1e60): ") + e.what());
    }
    return result;
}

}  // namespace momentlab::json_read

namespace momentlab {

std::optional<std::string> underflowing_number(std::string_view json_text) {
    std::optional<std::string> first;
    json_read::for_each_number(json_text, [&](std::string_view token) {
        if (!first && json_read::underflows(token)) first = std::string(token);
    });
    return first;
}

bool nonzero_digits(std::string_view number) {
    std::size_t i = 0;
    if (i < number.size() && (number[i] == '-' || number[i] == '+')) ++i;
    const bool hex = number.size() >= i + 2 && number[i] == '0' && (number[i + 1] == 'x' || number[i + 1] == 'X');
    if (hex) i += 2;
    for (; i < number.size(); ++i) {
        const char c = number[i];
        if (hex ? (c == 'p' || c == 'P') : (c == 'e' || c == 'E')) break;
        if (c >= '1' && c <= '9') return true;
        if (hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'))) return true;
    }
    return false;
}

}  // namespace momentlab
