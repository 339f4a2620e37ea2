#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab::cli {

/// Adds the `label` subcommand; the returned function runs it after parsing.
std::function<int()> add_label_command(CLI::App& app);

/// Adds the `modes` subcommand.
std::function<int()> add_modes_command(CLI::App& app);

/// Adds the `query` and `analyze` subcommands.
std::function<int()> add_query_command(CLI::App& app);
std::function<int()> add_analyze_command(CLI::App& app);

/// Reads a whole file; throws InputError at "$" if it cannot be read.
std::string read_file(const std::string& path);

/// The scene / force set in a file; warnings (unknown fields) go to stderr, one line each.
Scene read_scene_file(const std::string& path);
Cone read_force_set_file(const std::string& path);

}  // namespace momentlab::cli
