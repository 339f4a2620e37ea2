// momentlab: planar contact mechanics by moment labels. Each command parses its arguments,
// calls the library and prints; bad input gives one line on stderr and exit status 2, and so
// does output that cannot be written (a full disk, a closed pipe).
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <system_error>

#if defined(__linux__) && defined(__GLIBC__)
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

#include "common.hpp"

namespace {

constexpr const char* kCommands[] = {"label", "modes", "query", "analyze", "draw", "plan", "closure", "stand"};

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
        int error = errno;
        // A stream that failed while the command wrote (analyze --json writes as it goes) writes
        // nothing more, so no errno is left to tell why: one byte more, to a stream already
        // incomplete, asks the system again.
        if (error == 0 && ::write(STDOUT_FILENO, "\n", 1) < 0) error = errno;
        return fail(std::string("cannot write the answer to standard output (") +
                    (error != 0 ? std::strerror(error) : "write error") + ")");
    }
    return status;
}

// For a big input (an argument naming a file of 1 MB or more: a scene of about 10^4 contacts),
// glibc's malloc is asked to back its memory with transparent huge pages and to keep what it
// frees (docs/benchmarks.md, "Reading scene files"): on the bowl of 10^5 contacts `analyze --json` touches
// about 340 MB, and a page touched the first time costs a page fault. glibc reads these settings
// (GLIBC_TUNABLES) only when a program starts, so the command starts itself again once with
// them added to any the caller set; a caller who set glibc.malloc.hugetlb is left alone, and
// so is a run under another loader (valgrind) or a limited address space (ulimit -v: there a
// top pad of 256 MB made the libraries' own start-up allocations fail, a crash before main
// under a limit of 200 MB). If that fails, it runs on as it is.
void tune_malloc_for_big_inputs(int argc, char** argv) {
#if defined(__linux__) && defined(__GLIBC__)
    constexpr off_t kBig = off_t{1} << 20;
    bool big = false;
    for (int i = 1; i < argc && !big; ++i) {
        struct stat st {};
        big = ::stat(argv[i], &st) == 0 && S_ISREG(st.st_mode) && st.st_size >= kBig;
    }
    if (!big) return;
    struct rlimit space {};
    if (::getrlimit(RLIMIT_AS, &space) != 0 || space.rlim_cur != RLIM_INFINITY) return;
    const char* caller = std::getenv("GLIBC_TUNABLES");
    std::string tunables = caller ? caller : "";
    if (tunables.find("glibc.malloc.hugetlb") != std::string::npos) return;
    char self[4096];
    const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
    if (length <= 0) return;
    self[length] = '\0';
    const char* name = std::strrchr(self, '/');
    if (std::strncmp(name ? name + 1 : self, "momentlab", 9) != 0) return;
    tunables += std::string(tunables.empty() ? "" : ":") +
                "glibc.malloc.hugetlb=1:glibc.malloc.top_pad=268435456:glibc.malloc.trim_threshold=1073741824";
    if (::setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
    ::execv(self, argv);
    if (caller) {  // the exec failed: as the caller had it
        ::setenv("GLIBC_TUNABLES", caller, 1);
    } else {
        ::unsetenv("GLIBC_TUNABLES");
    }
#else
    (void)argc;
    (void)argv;
#endif
}

}  // namespace

int main(int argc, char** argv) {
    tune_malloc_for_big_inputs(argc, argv);
    CLI::App app{"momentlab: moment labels and planar contact mechanics (Mason 1991)"};
    app.require_subcommand(1);
    const auto run_label = momentlab::cli::add_label_command(app);
    const auto run_modes = momentlab::cli::add_modes_command(app);
    const auto run_query = momentlab::cli::add_query_command(app);
    const auto run_analyze = momentlab::cli::add_analyze_command(app);
    const auto run_draw = momentlab::cli::add_draw_command(app);
    const auto run_plan = momentlab::cli::add_plan_command(app);
    const auto run_closure = momentlab::cli::add_closure_command(app);
    const auto run_stand = momentlab::cli::add_stand_command(app);
    if (argc >= 2 && argv[1][0] != '-') {
        bool known = false;
        for (const char* c : kCommands) known = known || std::strcmp(argv[1], c) == 0;
        if (!known) {
            return fail(std::string("unknown command \"") + argv[1] +
                        "\" (expected label, modes, query, analyze, draw, plan, closure or stand; see momentlab --help)");
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
        if (app.got_subcommand("stand")) status = run_stand();
        return finish(status);
    } catch (const std::invalid_argument& e) {
        return fail(e.what());
    } catch (const momentlab::UnrepresentableError& e) {
        return fail(e.what());
    } catch (const std::bad_alloc&) {
        return fail("out of memory (the input is too large for this machine)");
    } catch (const std::system_error& e) {
        // A thread that cannot start (no memory for its stack under ulimit -v) is out of memory too.
        if (e.code() == std::errc::resource_unavailable_try_again || e.code() == std::errc::not_enough_memory) {
            return fail("out of memory (the input is too large for this machine)");
        }
        std::cerr << "momentlab: internal error: " << momentlab::cli::printable(e.what()) << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "momentlab: internal error: " << momentlab::cli::printable(e.what()) << "\n";
        return 1;
    }
}
