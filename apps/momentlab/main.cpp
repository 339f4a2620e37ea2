// momentlab: planar contact mechanics by moment labels. Each command parses its arguments,
// calls the library and prints; bad input gives one line on stderr and exit status 2.
#include <iostream>
#include <stdexcept>
#include <string>

#include "commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{"momentlab: moment labels and planar contact mechanics (Mason 1991)"};
    app.require_subcommand(1);
    const auto run_label = momentlab::cli::add_label_command(app);
    const auto run_modes = momentlab::cli::add_modes_command(app);
    const auto run_query = momentlab::cli::add_query_command(app);
    const auto run_analyze = momentlab::cli::add_analyze_command(app);
    const auto run_draw = momentlab::cli::add_draw_command(app);
    const auto run_plan = momentlab::cli::add_plan_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {  // one line, like every other input error
        std::cerr << "momentlab: " << e.what() << " (see momentlab --help)\n";
        return 2;
    }
    try {
        if (app.got_subcommand("label")) return run_label();
        if (app.got_subcommand("modes")) return run_modes();
        if (app.got_subcommand("query")) return run_query();
        if (app.got_subcommand("analyze")) return run_analyze();
        if (app.got_subcommand("draw")) return run_draw();
        if (app.got_subcommand("plan")) return run_plan();
    } catch (const std::invalid_argument& e) {
        std::cerr << "momentlab: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "momentlab: internal error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
