// momentlab: planar contact mechanics by moment labels. Each command parses its arguments,
// calls the library and prints; bad input gives one line on stderr and exit status 2, and so
// does output that cannot be written (a full disk, a closed pipe).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>

#include "common.hpp"

namespace {

constexpr const char* kCommands[] = {"label", "modes", "query", "analyze", "draw", "plan", "closure"};

int fail(const std::string& message) {
    std::cerr << "momentlab: " << momentlab::cli::printable(message) << "\n";
    return 2;
}

// Everything written to stdout reached it; otherwise one line and exit status 2.
int finish(int status) {
    errno = 0;
    std::cout.flush();
    const bool failed = std::fflush(stdout) != 0 || std::ferror(stdout) != 0 || !std::cout;
    if (failed) {
        const int error = errno;
        return fail(std::string("cannot write the answer to standard output (") +
                    (error != 0 ? std::strerror(error) : "write error") + ")");
    }
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"momentlab: moment labels and planar contact mechanics (Mason 1991)"};
    app.require_subcommand(1);
    const auto run_label = momentlab::cli::add_label_command(app);
    const auto run_modes = momentlab::cli::add_modes_command(app);
    const auto run_query = momentlab::cli::add_query_command(app);
    const auto run_analyze = momentlab::cli::add_analyze_command(app);
    const auto run_draw = momentlab::cli::add_draw_command(app);
    const auto run_plan = momentlab::cli::add_plan_command(app);
    const auto run_closure = momentlab::cli::add_closure_command(app);
    if (argc >= 2 && argv[1][0] != '-') {
        bool known = false;
        for (const char* c : kCommands) known = known || std::strcmp(argv[1], c) == 0;
        if (!known) {
            return fail(std::string("unknown command \"") + argv[1] +
                        "\" (expected label, modes, query, analyze, draw, plan or closure; see momentlab --help)");
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return finish(app.exit(e));
    } catch (const CLI::CallForAllHelp& e) {
        return finish(app.exit(e));
    } catch (const CLI::ParseError& e) {  // one line, like every other input error
        return fail(std::string(e.what()) + " (see momentlab --help)");
    }
    try {
        int status = 0;
        if (app.got_subcommand("label")) status = run_label();
        if (app.got_subcommand("modes")) status = run_modes();
        if (app.got_subcommand("query")) status = run_query();
        if (app.got_subcommand("analyze")) status = run_analyze();
        if (app.got_subcommand("draw")) status = run_draw();
        if (app.got_subcommand("plan")) status = run_plan();
        if (app.got_subcommand("closure")) status = run_closure();
        return finish(status);
    } catch (const std::invalid_argument& e) {
        return fail(e.what());
    } catch (const momentlab::UnrepresentableError& e) {
        return fail(e.what());
    } catch (const std::bad_alloc&) {
        return fail("out of memory (the input is too large for this machine)");
    } catch (const std::exception& e) {
        std::cerr << "momentlab: internal error: " << momentlab::cli::printable(e.what()) << "\n";
        return 1;
    }
}
