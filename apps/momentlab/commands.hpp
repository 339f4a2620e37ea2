#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/dynamics.hpp"
#include "momentlab/mechanics/scene.hpp"
#include "momentlab/render/figure.hpp"

namespace momentlab::cli {

/// Adds the `label` subcommand; the returned function runs it after parsing.
std::function<int()> add_label_command(CLI::App& app);

/// Adds the `modes` subcommand.
std::function<int()> add_modes_command(CLI::App& app);

/// Adds the `query` and `analyze` subcommands.
std::function<int()> add_query_command(CLI::App& app);
std::function<int()> add_analyze_command(CLI::App& app);

/// Adds the `plan` subcommand (plan tilt).
std::function<int()> add_plan_command(CLI::App& app);

/// Adds the `draw` subcommand.
std::function<int()> add_draw_command(CLI::App& app);

/// Where a command writes its picture: `-o FILE` (repeatable; .svg, .pdf or .png), `--view`.
struct PictureOptions {
    std::vector<std::string> files;
    std::vector<double> view;
    std::string title;
};

/// Adds -o, --view and --title to a command; `required` makes -o required.
void add_picture_options(CLI::App* cmd, PictureOptions& options, bool required);

/// The --view box, if given; throws InputError at "--view" unless XMIN < XMAX and YMIN < YMAX,
/// finite. Also checks every -o name's extension (at "-o"), before anything is computed.
std::optional<Box> checked_picture_options(const PictureOptions& options);

/// Writes the figure to every -o file and says so on stdout; a file that cannot be written is an
/// InputError at "-o" (and is left untouched).
void write_picture(const render::Figure& figure, const PictureOptions& options);

/// The index of the mode with these letters in the analysis; an unknown mode is an InputError
/// at `option` that lists the scene's modes.
std::size_t mode_index(const std::vector<ModeForces>& analysis, const std::string& letters, const std::string& option);

/// Reads a whole file; throws InputError at "$" if it cannot be read.
std::string read_file(const std::string& path);

/// The scene / force set in a file; warnings (unknown fields) go to stderr, one line each.
Scene read_scene_file(const std::string& path);
Cone read_force_set_file(const std::string& path);

}  // namespace momentlab::cli
