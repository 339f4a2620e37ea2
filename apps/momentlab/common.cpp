// What the commands share (common.hpp).
#include "common.hpp"


#include "momentlab/core/rounding.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace momentlab::cli {
namespace {

std::string reason(int error) { return std::strerror(error); }

void print_warnings(const InputWarnings& warnings) {
    for (const std::string& w : warnings) std::cerr << "momentlab: warning: " << printable(w) << "\n";
}

bool same_file(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Input files.

Scene read_scene_file(const std::string& path) {
    InputWarnings warnings;
    Scene scene = read_scene_text(read_json_file(path), &warnings);
    print_warnings(warnings);
    return scene;
}

// How long work goes before its progress is drawn: 1 s, or MOMENTLAB_PROGRESS_DELAY_MS (tests
// set 0 to see the line on short work).
std::chrono::milliseconds progress_delay() {
    const char* env = std::getenv("MOMENTLAB_PROGRESS_DELAY_MS");
    if (!env || !*env) return std::chrono::milliseconds(1000);
    char* end = nullptr;
    const long ms = std::strtol(env, &end, 10);
    return std::chrono::milliseconds(*end == '\0' && ms >= 0 ? ms : 1000);
}

struct TerminalProgress::State {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::chrono::milliseconds delay = progress_delay();
    std::chrono::steady_clock::time_point last{};
    bool shown = false;
};

TerminalProgress::TerminalProgress() : state_(isatty(STDERR_FILENO) ? std::make_shared<State>() : nullptr) {}

TerminalProgress::~TerminalProgress() { finish(); }

Progress TerminalProgress::callback() {
    if (!state_) return nullptr;
    return [state = state_](std::string_view what, std::size_t done, std::size_t total) {
        using namespace std::chrono_literals;
        const auto now = std::chrono::steady_clock::now();
        if (now - state->start < state->delay || now - state->last < 100ms) return;
        state->last = now;
        state->shown = true;
        std::fprintf(stderr, "\r\033[Kmomentlab: %.*s: %zu of %zu", static_cast<int>(what.size()), what.data(), done, total);
        std::fflush(stderr);
    };
}

void TerminalProgress::finish() {
    if (state_ && state_->shown) {
        std::fputs("\r\033[K", stderr);
        std::fflush(stderr);
        state_->shown = false;
    }
}

Problem open_problem(const std::string& path, bool quasi_static, TerminalProgress& progress) {
    return Problem(read_scene_file(path), quasi_static, InputNames::command_line(), progress.callback());
}

// ---------------------------------------------------------------------------------------------
// Options.

// The longest --title drawn: a line of about 1,000 characters is already wider than any panel.
constexpr std::size_t kMaxTitleBytes = 1000;

const CLI::Validator& number_check() {
    static const CLI::Validator check(
        [](std::string& s) -> std::string {
            const std::size_t first = s.find_first_not_of(" \t\r\n");
            if (first == std::string::npos) return "expected a number, got an empty string";
            s.erase(s.find_last_not_of(" \t\r\n") + 1);  // blanks around a number are not part of it
            s.erase(0, first);
            char* end = nullptr;
            const double x = std::strtod(s.c_str(), &end);
            // One grammar in every front end: a decimal as Rational::parse reads it (no hex
            // floats); "nan", "inf" and overflow pass here to be refused as not finite.
            if (end != s.c_str() + s.size() || (std::isfinite(x) && !Rational::is_decimal(s))) {
                return "expected a number, got \"" + printable(s) + "\"";
            }
            if (x == 0.0 && nonzero_digits(s)) {
                return "\"" + printable(s) + "\" is " + std::string(kTooSmallForADouble);
            }
            return {};
        },
        "NUMBER");
    return check;
}

const CLI::Validator& index_check() {
    static const CLI::Validator check(
        [](std::string& s) -> std::string {
            if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) {
                return "expected an index 0, 1, 2 ..., got \"" + printable(s) + "\"";
            }
            return {};
        },
        "INDEX");
    return check;
}

std::istream& operator>>(std::istream& in, TypedNumber& n) {
    std::string text;
    in >> text;
    char* end = nullptr;
    n.value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) in.setstate(std::ios::failbit);
    n.exact = std::isfinite(n.value) ? Rational::parse(text) : std::nullopt;
    return in;
}

namespace {

std::vector<double> values_of(const std::vector<TypedNumber>& typed) {
    std::vector<double> out;
    for (const TypedNumber& t : typed) out.push_back(t.value);
    return out;
}

}  // namespace

std::vector<Rational2> checked_points(const std::vector<TypedNumber>& values, const std::string& option,
                                      std::optional<std::size_t> count) {
    (void)checked_points(values_of(values), option, count);  // the checks, on the doubles
    std::vector<Rational2> out;
    for (std::size_t i = 0; i < values.size(); i += 2) out.push_back({values[i].rational(), values[i + 1].rational()});
    return out;
}

Load load_of(const std::vector<TypedNumber>& gravity, const std::vector<TypedNumber>& wrench,
             const std::vector<TypedNumber>& forces) {
    Load load;
    if (!gravity.empty()) load.gravity = checked_points(gravity, "--gravity", 1).front();
    if (!wrench.empty()) {
        if (wrench.size() != 3) throw InputError("--wrench", "expected three numbers FX FY TAU");
        (void)checked_vector(Vec3(wrench[0].value, wrench[1].value, wrench[2].value), "--wrench");
        load.wrench = Rational3{wrench[0].rational(), wrench[1].rational(), wrench[2].rational()};
    }
    if (forces.size() % 4 != 0) throw InputError("--force", "expected four numbers X Y FX FY for each --force");
    for (std::size_t i = 0; i < forces.size(); i += 4) {
        (void)checked_vector(Vec2(forces[i].value, forces[i + 1].value), "--force");
        (void)checked_vector(Vec2(forces[i + 2].value, forces[i + 3].value), "--force");
        load.forces.emplace_back(Rational2{forces[i].rational(), forces[i + 1].rational()},
                                 Rational2{forces[i + 2].rational(), forces[i + 3].rational()});
    }
    return load;
}

void add_force_option(CLI::App* cmd, std::vector<TypedNumber>& forces, const char* what) {
    cmd->add_option("--force", forces, std::string("X Y FX FY: a force (FX, FY) acting through (X, Y), ") + what + " (repeatable)")
        ->expected(4)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->transform(number_check());
}

std::string magnitude_text(const MagnitudeRange& range) {
    if (!range.hi) return "from " + fmt(range.lo.value()) + " up";
    if (compare(range.lo, *range.hi) == 0) return fmt(range.lo.value()) + " only";
    return "from " + fmt(range.lo.value()) + " to " + fmt(range.hi->value());
}

void print_bands(const std::vector<MagnitudeBand>& bands, const std::vector<ModeForces>& analysis) {
    for (const MagnitudeBand& b : bands) {
        std::string range;
        if (b.to && compare(b.from, *b.to) == 0) {
            range = fmt(b.from) + " only";
        } else {
            range = std::string(b.from_closed ? "[" : "(") + fmt(b.from) + ", " +
                    (b.to ? fmt(*b.to) + (b.to_closed ? "]" : ")") : std::string("unbounded)"));
        }
        std::string modes;
        for (std::size_t j : b.modes) modes += (modes.empty() ? "" : " ") + analysis[j].mode.letters;
        if (modes.empty()) modes = "(no mode)";
        std::string line = "  " + range;
        line.resize(std::max<std::size_t>(line.size() + 2, 30), ' ');
        std::cout << line << modes << "   " << to_string(verdict_of(b.modes.size())) << "\n";
    }
}

std::vector<Vec2> checked_points(const std::vector<double>& values, const std::string& option,
                                 std::optional<std::size_t> count) {
    if (values.size() % 2 != 0 || (count && values.size() != 2 * *count)) {
        throw InputError(option, "expected " + std::string(count && *count == 1 ? "two numbers X Y" : "pairs of numbers X Y") +
                                     ", got " + std::to_string(values.size()) + " number" + (values.size() == 1 ? "" : "s"));
    }
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < values.size(); i += 2) out.push_back(checked_vector(Vec2(values[i], values[i + 1]), option));
    return out;
}

void add_picture_options(CLI::App* cmd, PictureOptions& options, bool required) {
    auto* out = cmd->add_option("-o,--output", options.files, "write a picture: FILE.svg, FILE.pdf or FILE.png (repeatable)")
                    ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    if (required) out->required();
    cmd->add_option("--view", options.view, "XMIN YMIN XMAX YMAX: the part of the plane drawn (default: fitted)")
        ->expected(4)
        ->transform(number_check());
    cmd->add_option("--title", options.title, "the picture's title");
}

std::optional<Box> checked_picture_options(const PictureOptions& options, const std::vector<std::string>& inputs) {
    if (options.title.size() > kMaxTitleBytes) {
        throw InputError("--title", "a title of " + std::to_string(options.title.size()) + " bytes is too long to draw (at most " +
                                        std::to_string(kMaxTitleBytes) + ")");
    }
    for (const std::string& f : options.files) {
        for (const std::string& in : inputs) {
            if (same_file(f, in)) throw InputError("-o", "\"" + f + "\" is the input file: refusing to write a picture over it");
        }
        try {
            (void)render::format_for(f);
        } catch (const std::invalid_argument& e) {
            throw InputError("-o", e.what());
        }
        const std::filesystem::path target(f);
        const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
        struct stat st {};
        if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
            throw InputError("-o", "cannot write \"" + f + "\" (no directory \"" + dir.string() + "\")");
        }
        if (::access(dir.c_str(), W_OK) != 0) throw InputError("-o", "cannot write \"" + f + "\" (" + reason(errno) + ")");
        if (::stat(f.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
            throw InputError("-o", "cannot write \"" + f + "\" (a directory)");
        }
    }
    if (options.view.empty()) return std::nullopt;
    const auto& v = options.view;
    if (v.size() != 4) return checked_view(NAN, NAN, NAN, NAN, "--view");
    return checked_view(v[0], v[1], v[2], v[3], "--view");
}

void write_picture(const render::Figure& figure, const PictureOptions& options) {
    for (const std::string& f : options.files) {
        try {
            render::write(figure, f);
        } catch (const std::runtime_error& e) {
            throw InputError("-o", e.what());
        }
        std::cout << "wrote " << printable(f) << "\n";
    }
}

// ---------------------------------------------------------------------------------------------
// Printing.

std::string fmt(double x, int digits) {
    std::ostringstream s;
    s << std::setprecision(digits) << output_value(x);
    return s.str();
}

std::string fmt(const Vec2& v, int digits) { return "(" + fmt(v.x(), digits) + ", " + fmt(v.y(), digits) + ")"; }

std::string fmt(const Vec3& v, int digits) {
    return "(" + fmt(v.x(), digits) + ", " + fmt(v.y(), digits) + ", " + fmt(v.z(), digits) + ")";
}

std::string fmt(const Dyadic& num, const Dyadic& den, int digits) {
    (void)output_value(nearest_double(num, den));  // (throws beyond the doubles)
    return significant_digits(num, den, digits);
}

std::string fmt(const Magnitude& m, int digits) { return fmt(m.num, m.den, digits); }

std::string fmt_point(const ExactVector& homogeneous, int digits) {
    const Exact3 v = homogeneous.exact();
    return "(" + fmt(v[0], v[2], digits) + ", " + fmt(v[1], v[2], digits) + ")";
}

std::string degrees(double radians) {
    std::ostringstream s;
    const double d = radians * 180.0 / M_PI;
    s << std::fixed << std::setprecision(2) << (std::fabs(d) < 0.005 ? 0.0 : d) << "\u00B0";
    return s.str();
}

std::string describe_mode(const Scene& scene, const std::string& letters) {
    std::string out;  // appended in place: Theta(contacts) per mode, Theta(modes x contacts) in all
    for (std::size_t j = 0; j < letters.size(); ++j) {
        const std::string& name = scene.contacts[j].name;
        if (j) out += ", ";
        if (name.empty()) {
            out += "contact ";
            out += std::to_string(j + 1);
        } else {
            out += printable(name);
        }
        out += ' ';
        out += describe(contact_mode(letters[j]));
    }
    return out;
}

std::string region_text(const Region& r) {
    std::string s = r.kind();
    const char* separator = ": ";
    for (const auto& [name, list] : {std::pair{"vertices", &r.vertices}, std::pair{"rays", &r.rays}, std::pair{"lines", &r.lines}}) {
        if (list->empty()) continue;
        s += separator;
        s += name;
        for (const Vec2& v : *list) s += " " + fmt(v, kRegionDigits);
        separator = "; ";
    }
    return s;
}

namespace {

std::string polygon_path(bool body, std::size_t obstacle) {
    return body ? "$.body.polygon" : "$.obstacles[" + std::to_string(obstacle) + "].polygon";
}

std::string polygon_name(bool body, std::size_t obstacle) {
    return body ? "the body" : "obstacle " + std::to_string(obstacle);
}

}  // namespace

std::string found_contacts_text(const Scene& scene) {
    if (scene.origins.empty()) return {};
    std::string out = "contacts found from the polygons (vertex and edge indices from 0, as in the file):\n";
    for (std::size_t j = 0; j < scene.origins.size(); ++j) {
        const ContactOrigin& o = scene.origins[j];
        out += "  contact " + std::to_string(j + 1) + " at " + fmt(scene.contacts[j].point) + ", normal " +
               fmt(scene.contacts[j].normal) + ": vertex " + std::to_string(o.vertex) + " of " +
               polygon_name(o.body_vertex, o.obstacle) + " on edge " + std::to_string(o.edge) + " of " +
               polygon_name(!o.body_vertex, o.obstacle) + "\n";
    }
    return out;
}

nlohmann::json found_contacts_json(const Scene& scene) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t j = 0; j < scene.origins.size(); ++j) {
        const ContactOrigin& o = scene.origins[j];
        out.push_back({{"point", vector_json(scene.contacts[j].point)},
                       {"normal", vector_json(scene.contacts[j].normal)},
                       {"vertex", {{"polygon", polygon_path(o.body_vertex, o.obstacle)}, {"index", o.vertex}}},
                       {"edge", {{"polygon", polygon_path(!o.body_vertex, o.obstacle)}, {"index", o.edge}}}});
    }
    return out;
}

void write_json_value(JsonWriter& w, const nlohmann::json& j) {
    switch (j.type()) {
        case nlohmann::json::value_t::object:
            w.begin_object();
            for (const auto& [key, item] : j.items()) {
                w.key(key);
                write_json_value(w, item);
            }
            w.end_object();
            return;
        case nlohmann::json::value_t::array:
            w.begin_array();
            for (const auto& item : j) write_json_value(w, item);
            w.end_array();
            return;
        case nlohmann::json::value_t::string: w.value(j.get<std::string>()); return;
        case nlohmann::json::value_t::boolean: w.value(j.get<bool>()); return;
        case nlohmann::json::value_t::number_integer:
        case nlohmann::json::value_t::number_unsigned: w.value(j.get<long long>()); return;
        case nlohmann::json::value_t::number_float: w.value(j.get<double>()); return;
        default: throw std::logic_error("write_json_value: null is not written");
    }
}

std::string stem(const std::string& path) { return printable(std::filesystem::path(path).stem().string()); }

}  // namespace momentlab::cli
