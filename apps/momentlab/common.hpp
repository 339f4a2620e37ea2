#pragma once

// What every command of the `momentlab` tool shares: reading input files safely, the scene and
// its analysis, picture options and safe picture files, checked number options, and one way
// of printing numbers, names and regions.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "momentlab/momentlab.hpp"
#include "momentlab/io/files.hpp"
#include "momentlab/io/json_writer.hpp"
#include "momentlab/io/json_output.hpp"
#include "momentlab/io/printable.hpp"

namespace momentlab::cli {

/// The commands: each adds its subcommand and returns the function that runs it after parsing.
std::function<int()> add_label_command(CLI::App& app);
std::function<int()> add_modes_command(CLI::App& app);
std::function<int()> add_query_command(CLI::App& app);
std::function<int()> add_analyze_command(CLI::App& app);
std::function<int()> add_draw_command(CLI::App& app);
std::function<int()> add_plan_command(CLI::App& app);
std::function<int()> add_closure_command(CLI::App& app);
std::function<int()> add_stand_command(CLI::App& app);

// ---------------------------------------------------------------------------------------------
// Input files.

// read_json_file and LineReader: io/files.hpp.

/// A scene file, read and checked; warnings (unknown fields) go to stderr, one line each.
Scene read_scene_file(const std::string& path);

/// A scene with a body, and every mode with its sets (the start of query, analyze, draw
/// --what forces and the planners). `command` names what needs the body, for the message.
/// Progress of long work on stderr, when stderr is a terminal and the work has taken more than a
/// second (MOMENTLAB_PROGRESS_DELAY_MS): one line, redrawn at most ten times a second, erased when done (or destroyed). Quiet in
/// pipes, files and tests.
class TerminalProgress {
public:
    TerminalProgress();
    ~TerminalProgress();
    TerminalProgress(const TerminalProgress&) = delete;
    TerminalProgress& operator=(const TerminalProgress&) = delete;
    /// The callback to give the library (empty when stderr is not a terminal).
    [[nodiscard]] Progress callback();
    /// Erases the line, if one was drawn.
    void finish();

private:
    struct State;
    std::shared_ptr<State> state_;
};

/// The problem of the scene file `path` (app/problem.hpp), named with the command line's option
/// names; long work reports to `progress`.
Problem open_problem(const std::string& path, bool quasi_static, TerminalProgress& progress);

// find_mode: io/scene_json.hpp.

// ---------------------------------------------------------------------------------------------
// Options.

/// A CLI11 check for numeric options: an empty (or blank) string is not a number, blanks around
/// a number are dropped, anything else strtod does not read whole is refused, and so is a
/// non-zero number that would round to 0 (1e-400).
const CLI::Validator& number_check();
/// A CLI11 check for index options (--edge, --vertex): digits only, not empty.
const CLI::Validator& index_check();

/// A number option as typed (after number_check): the double strtod reads and, for decimal
/// text, the exact value it spells (0.1 is 1/10; docs/design.md, "Numbers as typed").
struct TypedNumber {
    TypedNumber() {}  // (not an aggregate: CLI11 would make it from a double, not from its text)
    double value = 0.0;
    std::optional<Rational> exact;
    /// The exact value (the double's own for text that is not a decimal, such as hexadecimal).
    /// Precondition: value is finite.
    [[nodiscard]] Rational rational() const { return exact ? *exact : Rational(value); }
};
/// How CLI11 reads a TypedNumber option.
std::istream& operator>>(std::istream& in, TypedNumber& n);

/// The load of --gravity GX GY, --wrench FX FY TAU and --force X Y FX FY (repeatable; the
/// numbers of every --force in one list): the wrench acting besides a controlled action, or the
/// applied wrench of a question, exactly as typed. Every vector is checked (app/checks.hpp).
Load load_of(const std::vector<TypedNumber>& gravity, const std::vector<TypedNumber>& wrench,
             const std::vector<TypedNumber>& forces);
/// Adds --force X Y FX FY (repeatable) to a command.
void add_force_option(CLI::App* cmd, std::vector<TypedNumber>& forces, const char* what);
/// checked_points for typed numbers, exactly as typed.
std::vector<Rational2> checked_points(const std::vector<TypedNumber>& values, const std::string& option,
                                      std::optional<std::size_t> count = std::nullopt);
/// "from 4.905 to 9.81", "9.81 only", "from 4.905 up": a range of magnitudes.
std::string magnitude_text(const MagnitudeRange& range);
/// The magnitude bands, one per line: "  [0, 4.905)   ff   unique".
void print_bands(const std::vector<MagnitudeBand>& bands, const std::vector<ModeForces>& analysis);

/// Points given as a flat list X Y X Y ... (--at, --centre): an even count, each point a vector
/// in range (app/checks.hpp); `count` pairs when given.
std::vector<Vec2> checked_points(const std::vector<double>& values, const std::string& option,
                                 std::optional<std::size_t> count = std::nullopt);

/// Where a command writes its picture: `-o FILE` (repeatable; .svg, .pdf or .png), `--view`.
struct PictureOptions {
    std::vector<std::string> files;
    std::vector<double> view;
    std::string title;
};

/// Adds -o, --view and --title to a command; `required` makes -o required.
void add_picture_options(CLI::App* cmd, PictureOptions& options, bool required);

/// A subcommand that reads one scene: its positional `scene` argument (into `opts->file`) and,
/// when `json_help` is given, a --json flag (into `opts->json`). The command adds the rest.
template <class Options>
CLI::App* add_scene_command(CLI::App& app, const std::shared_ptr<Options>& opts, const char* name,
                            const char* description, const char* json_help = nullptr) {
    CLI::App* cmd = app.add_subcommand(name, description);
    cmd->add_option("scene", opts->file, "scene JSON (docs/formats.md)")->required();
    if constexpr (requires { opts->json; }) {
        if (json_help != nullptr) cmd->add_flag("--json", opts->json, json_help);
    }
    return cmd;
}

/// Checks every -o before anything is computed or written: a known extension, a directory that
/// exists, and not one of the `inputs` (writing a picture over the scene being read is
/// refused). Returns the --view box, if given (finite, XMIN < XMAX, YMIN < YMAX).
std::optional<Box> checked_picture_options(const PictureOptions& options, const std::vector<std::string>& inputs);

/// Writes the figure to every -o file (render::write: a new file, then renamed) and says so on
/// stdout; a file that cannot be written, or a picture too large, is an InputError at "-o".
void write_picture(const render::Figure& figure, const PictureOptions& options);

// ---------------------------------------------------------------------------------------------
// Printing.

/// A number with `digits` significant digits, never "-0"; a non-finite number is an
/// UnrepresentableError (a value of the answer beyond the range of a double).
std::string fmt(double x, int digits = 6);
std::string fmt(const Vec2& v, int digits = 6);
std::string fmt(const Vec3& v, int digits = 6);
/// An exact quotient num / den with `digits` significant digits, the exact value correctly
/// rounded (significant_digits, core/rounding.hpp); beyond the doubles an UnrepresentableError.
std::string fmt(const Dyadic& num, const Dyadic& den, int digits = 6);
std::string fmt(const Magnitude& m, int digits = 6);
/// The homogeneous point (x, y, s), s != 0, as (x / s, y / s), each correctly rounded.
std::string fmt_point(const ExactVector& homogeneous, int digits = 6);
/// An angle in radians as degrees with two decimals and the degree sign.
std::string degrees(double radians);
/// Names and messages as one line (io/printable.hpp).
using momentlab::printable;
/// "contact 2 slides along +t, floor separates, ..." for the letters of a mode.
std::string describe_mode(const Scene& scene, const std::string& letters);
/// Significant digits of region_text's numbers.
inline constexpr int kRegionDigits = 10;
/// A region completely, on one line: its kind, then those of its vertices, rays and lines it has,
/// "unbounded: vertices (0, 1) (2, 3); rays (1, 0) (0, 1)", numbers with kRegionDigits digits:
/// the region is conv(vertices) + cone(rays) + span(lines).
std::string region_text(const Region& r);
/// The contacts found from the polygons (none when the scene gave its contacts), one line each:
/// "  contact 1 at (0, 0), normal (0, 1): vertex 0 of the body on edge 2 of obstacle 0", after a
/// heading line.
std::string found_contacts_text(const Scene& scene);
/// The same as the JSON array of "found_contacts": {"point", "normal", "vertex": {"polygon",
/// "index"}, "edge": {"polygon", "index"}}, polygons named by their path in the scene file
/// ("$.body.polygon", "$.obstacles[0].polygon"); empty when the scene gave its contacts.
nlohmann::json found_contacts_json(const Scene& scene);
/// A JSON value (no nulls) through the writer, as dump(2) would write it.
void write_json_value(JsonWriter& w, const nlohmann::json& j);
/// The file name without directory and extension (for titles).
std::string stem(const std::string& path);

}  // namespace momentlab::cli
