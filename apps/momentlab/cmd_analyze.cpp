// `momentlab analyze SCENE [--json]`: every mode with its sets of twists, total, contact and
// applied wrenches, and their labels.
#include <array>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "common.hpp"

namespace momentlab::cli {
namespace {

struct AnalyzeOptions {
    std::string file;
    bool json = false;
    bool quasi_static = false;
};

// Passes text on to `out`, with `prefix` after each newline (buffered; flush before writing
// to `out` directly).
class IndentingBuffer : public std::streambuf {
public:
    IndentingBuffer(std::streambuf& out, std::string prefix) : out_(out), prefix_(std::move(prefix)) {
        setp(buffer_.data(), buffer_.data() + buffer_.size());
    }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain() {
        const char* s = pbase();
        const char* end = pptr();
        while (s < end) {  // runs without a newline in one piece
            const char* newline = static_cast<const char*>(std::memchr(s, '\n', static_cast<std::size_t>(end - s)));
            const char* stop = newline ? newline + 1 : end;
            if (out_.sputn(s, stop - s) != stop - s) return false;
            if (newline && out_.sputn(prefix_.data(), static_cast<std::streamsize>(prefix_.size())) !=
                               static_cast<std::streamsize>(prefix_.size())) {
                return false;
            }
            s = stop;
        }
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        return true;
    }

    std::streambuf& out_;
    std::string prefix_;
    std::array<char, 1 << 16> buffer_{};
};

int run(const AnalyzeOptions& o) {
    const Problem p = load_problem(o.file, "analyze", o.quasi_static);
    if (o.json) {
        // One mode's document at a time, written as dump(2) of {"modes": [...]} writes it: on
        // 10^5 contacts the whole document is hundreds of megabytes. JSON strings hold no raw
        // newline, so indenting after each one is indenting each line.
        IndentingBuffer indent(*std::cout.rdbuf(), "    ");
        std::cout << "{\n  \"modes\": [";
        for (std::size_t i = 0; i < p.analysis.size(); ++i) {
            const ModeForces& m = p.analysis[i];
            const nlohmann::json mode = {{"mode", m.mode.letters},
                                         {"A", to_json(m.mode.twists)},
                                         {"rotation_centres", to_json(rotation_centres(m.mode))},
                                         {"F", {{"cone", to_json(m.total)}, {"labels", to_json(Labels(m.total))}}},
                                         {"T", {{"cone", to_json(m.contact)}, {"labels", to_json(Labels(m.contact))}}},
                                         {"E", {{"cone", to_json(m.applied)}, {"labels", to_json(Labels(m.applied))}}}};
            std::cout << (i == 0 ? "\n    " : ",\n    ");
            std::ostream indented(&indent);
            indented << std::setw(2) << mode << std::flush;
        }
        std::cout << (p.analysis.empty() ? "]\n}\n" : "\n  ]\n}\n");
        return 0;
    }
    // The whole answer first: a value that cannot be printed stops it before any of it is.
    std::ostringstream out;
    out << p.analysis.size() << " contact modes" << (o.quasi_static ? " (quasi-static: E = -T, inertia neglected)" : "") << "\n";
    for (const ModeForces& m : p.analysis) {
        const Labels centres = rotation_centres(m.mode);
        const Labels applied(m.applied);
        out << "  " << std::left << std::setw(static_cast<int>(p.scene.contacts.size()) + 2) << m.mode.letters
                  << describe_mode(p.scene, m.mode.letters) << "\n"
                  << "      rotation centres  + " << region_text(centres.plus()) << ";  - "
                  << region_text(centres.minus()) << "\n"
                  << "      applied wrenches E: " << m.applied.kind() << "; labels + "
                  << region_text(applied.plus()) << ";  - " << region_text(applied.minus()) << "\n";
    }
    std::cout << out.str();
    return 0;
}

}  // namespace

std::function<int()> add_analyze_command(CLI::App& app) {
    auto opts = std::make_shared<AnalyzeOptions>();
    CLI::App* cmd = add_scene_command(app, opts, "analyze", "Every mode with its twists, total, contact and applied wrenches",
                                      "machine-readable output");
    cmd->add_flag("--quasi-static", opts->quasi_static, "neglect inertia: the applied wrench balances the contact wrench, E = -T (docs/design.md)");
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
