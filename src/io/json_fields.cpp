// Typed access to a read document: numbers, vectors and lists with their JSON paths in
// messages, each number's exact decimal, and the warnings for unknown fields.
#include "json_read.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>

namespace momentlab::json_read {

using nlohmann::json;

std::optional<Decimal> exact_decimal(std::string_view text) {
    std::size_t i = 0;
    Decimal d;
    d.negative = i < text.size() && text[i] == '-';
    if (d.negative) ++i;
    const auto digits_from = [&](std::size_t from) {
        while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
        return text.substr(from, i - from);
    };
    const std::string_view whole = digits_from(i);
    if (whole.empty() || (whole.size() > 1 && whole[0] == '0')) return std::nullopt;
    std::string_view fraction;
    if (i < text.size() && text[i] == '.') {
        fraction = digits_from(++i);
        if (fraction.empty()) return std::nullopt;
    }
    std::int64_t exponent = 0;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        const bool down = i < text.size() && text[i] == '-';
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        std::string_view e = digits_from(i);
        if (e.empty()) return std::nullopt;
        e.remove_prefix(std::min(e.find_first_not_of('0'), e.size()));
        if (e.size() > 18) return std::nullopt;
        for (const char c : e) exponent = exponent * 10 + (c - '0');
        if (down) exponent = -exponent;
    }
    if (i != text.size()) return std::nullopt;
    // digits x 10^(exponent - |fraction|), then without leading and trailing zeros.
    d.digits.reserve(whole.size() + fraction.size());
    d.digits.append(whole).append(fraction);
    d.exponent = exponent - static_cast<std::int64_t>(fraction.size());
    d.digits.erase(0, std::min(d.digits.find_first_not_of('0'), d.digits.size()));
    const std::size_t last = d.digits.find_last_not_of('0');
    if (last == std::string::npos) return Decimal{};
    d.exponent += static_cast<std::int64_t>(d.digits.size() - 1 - last);
    d.digits.resize(last + 1);
    return d;
}

// Typed access.

std::string Path::str() const {
    std::string out = parent_ ? parent_->str() : std::string();
    if (parent_ == nullptr) return out.append(name_);
    if (index_ != std::numeric_limits<std::size_t>::max()) return out.append(1, '[').append(std::to_string(index_)).append(1, ']');
    return out.append(1, '.').append(name_);
}

Value field(const Value& obj, const Path& path, std::string_view name) {
    const std::optional<Value> v = obj.find(name);
    if (!v) throw InputError(path.str(), "missing field \"" + std::string(name) + "\"");
    return *v;
}

namespace {

// A number's value as the JSON library writes it (in messages).
std::string dumped(double x) { return json(x).dump(); }

// A finite number of magnitude at most kLargestMagnitude.
double coordinate(const Value& v, const Path& path) {
    if (!v.is_number()) throw InputError(path.str(), "expected a number, got " + std::string(v.type_name()));
    const double x = v.number().value;
    if (!std::isfinite(x)) throw InputError(path.str(), "expected a finite number");
    if (!(std::abs(x) <= kLargestMagnitude)) {
        throw InputError(path.str(), "the magnitude of " + dumped(x) + " is out of range (expected " + std::string(kMagnitudeRange) + ")");
    }
    return x;
}

// A vector is 0 or has its largest coordinate in range; single coordinates may be tiny.
template <class V>
V checked(const V& v, const Path& path) {
    if (!magnitude_in_range(v.cwiseAbs().maxCoeff())) {
        throw InputError(path.str(), "the vector's magnitude is out of range (expected " + std::string(kMagnitudeRange) + ")");
    }
    return v;
}

// The coordinates of an array of N numbers, the first bad one an error (in order).
template <int N>
std::array<double, N> coordinates(const Value& v, const Path& path) {
    std::array<double, N> out{};
    v.for_each_element([&](std::size_t k, const Value& c) { out[k] = coordinate(c, Path(path, k)); });
    return out;
}

}  // namespace

double number(const Value& v, const Path& path) {
    const double x = coordinate(v, path);
    if (!magnitude_in_range(std::abs(x))) {
        throw InputError(path.str(), "the magnitude of " + dumped(x) + " is out of range (expected " + std::string(kMagnitudeRange) + ")");
    }
    return x;
}

double nonnegative(const Value& v, const Path& path, const char* what) {
    const double x = number(v, path);
    if (x < 0.0) throw InputError(path.str(), std::string("expected ") + what + " >= 0");
    return x;
}

Vec2 vec2(const Value& v, const Path& path) {
    if (!v.is_array() || v.size() != 2) throw InputError(path.str(), "expected [x, y]");
    const auto xy = coordinates<2>(v, path);
    return checked(Vec2(xy[0], xy[1]), path);
}

Vec3 vec3(const Value& v, const Path& path) {
    if (!v.is_array() || v.size() != 3) throw InputError(path.str(), "expected [a, b, c]");
    const auto abc = coordinates<3>(v, path);
    return checked(Vec3(abc[0], abc[1], abc[2]), path);
}

std::vector<Vec3> vec3_list(const Value& v, const Path& path) {
    if (!v.is_array()) throw InputError(path.str(), "expected a list of [a, b, c]");
    std::vector<Vec3> out;
    out.reserve(v.size());
    v.for_each_element([&](std::size_t i, const Value& e) { out.push_back(vec3(e, Path(path, i))); });
    return out;
}

std::vector<Vec2> vec2_list(const Value& v, const Path& path) {
    if (!v.is_array()) throw InputError(path.str(), "expected a list of [x, y]");
    std::vector<Vec2> out;
    out.reserve(v.size());
    v.for_each_element([&](std::size_t i, const Value& e) { out.push_back(vec2(e, Path(path, i))); });
    return out;
}

Rational exact_number(const Value& v) {
    const JsonNumber n = v.number();
    if (n.spelling == JsonNumber::Spelling::Exact) return Rational(n.value);
    if (n.spelling == JsonNumber::Spelling::Unknown) {
        // An integer of at most 15 digits is its double (no need to parse it again).
        const std::string_view t = n.text.substr(!n.text.empty() && n.text[0] == '-' ? 1 : 0);
        if (t.size() <= 15 && t.find_first_not_of("0123456789") == std::string_view::npos) return Rational(n.value);
        if (Rational::spells(n.text, n.value)) return Rational(n.value);  // a double written exactly (dyadic)
    }
    const std::optional<Rational> r = Rational::parse(n.text);
    return r ? *r : Rational(n.value);
}

Rational2 exact_vec2(const Value& v) {
    Rational2 out;
    v.for_each_element([&](std::size_t k, const Value& c) { out[k] = exact_number(c); });
    return out;
}

Rational3 exact_vec3(const Value& v) {
    Rational3 out;
    v.for_each_element([&](std::size_t k, const Value& c) { out[k] = exact_number(c); });
    return out;
}

Vec2 nonzero2(const Value& obj, const Path& path, std::string_view name) {
    const Path p(path, name);
    return nonzero(vec2(field(obj, path, name), p), p);
}

Vec2 nonzero(const Vec2& v, const Path& path) {
    if (v.x() == 0.0 && v.y() == 0.0) throw InputError(path.str(), "expected a non-zero vector");
    return v;
}

namespace {
constexpr std::size_t kListedUnknown = 20;
constexpr const char* kMoreUnknown = "$: ";
}  // namespace

void known_fields(const Value& obj, const Path& path, std::initializer_list<std::string_view> known,
                  InputWarnings* warnings) {
    if (warnings == nullptr || !obj.is_object()) return;
    const auto is_known = [&](std::string_view key) { return std::find(known.begin(), known.end(), key) != known.end(); };
    // The first kListedUnknown unknown fields of a document are listed, one a line, in the order
    // of their names; the rest are counted in one last line (a file of millions of unknown
    // fields gives a few lines, and only the names listed are held).
    const std::size_t room = kListedUnknown - std::min(warnings->size(), kListedUnknown);
    std::vector<std::string_view> first;  // the smallest `room` unknown names, among others
    std::size_t unknown = 0;
    obj.for_each_member([&](std::string_view key, const Value&) {
        if (is_known(key)) return;
        ++unknown;
        first.push_back(key);
        if (first.size() > 2 * room + 64) {
            std::nth_element(first.begin(), first.begin() + static_cast<std::ptrdiff_t>(room), first.end());
            first.resize(room);
        }
    });
    if (unknown == 0) return;
    std::sort(first.begin(), first.end());
    first.resize(std::min(first.size(), room));
    std::string expected;
    for (const std::string_view k : known) expected.append(expected.empty() ? "" : ", ").append(k);
    const std::string at = path.str();
    for (const std::string_view key : first) {
        warnings->push_back(at + "." + std::string(key) + ": unknown field, ignored (expected " + expected + ")");
    }
    std::size_t more = unknown - first.size();
    if (more == 0) return;
    if (warnings->size() > kListedUnknown) {
        more += std::stoull(warnings->back().substr(std::strlen(kMoreUnknown)));
        warnings->pop_back();
    }
    warnings->push_back(kMoreUnknown + std::to_string(more) + " more unknown fields, ignored (the first " +
                        std::to_string(kListedUnknown) + " are listed)");
}

}  // namespace momentlab::json_read

namespace momentlab {

namespace {

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

}  // namespace

std::optional<std::string> underflowing_number(std::string_view json_text) {
    std::optional<std::string> first;
    for_each_number(json_text, [&](std::string_view token) {
        if (first || !nonzero_digits(token)) return;
        if (std::strtod(std::string(token).c_str(), nullptr) == 0.0) first = std::string(token);
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
