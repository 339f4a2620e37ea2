#pragma once

// What the validators share: `--name value` options, and the report a run writes (a text
// summary on standard output; with --markdown FILE, the rows of docs/validation.md's table).

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace momentlab::validation {

/// Options given as `--name value`; every name must be known (a typo is an error, exit 2).
class Options {
public:
    Options(int argc, char** argv, std::map<std::string, std::string> defaults)
        : values_(std::move(defaults)) {
        for (int i = 1; i < argc; i += 2) {
            const std::string name = argv[i];
            if (name.rfind("--", 0) != 0 || i + 1 >= argc || !values_.count(name.substr(2))) {
                std::fprintf(stderr, "%s: unknown option or missing value: %s\nknown:", argv[0], name.c_str());
                for (const auto& [k, v] : values_) std::fprintf(stderr, " --%s (%s)", k.c_str(), v.c_str());
                std::fprintf(stderr, "\n");
                std::exit(2);
            }
            values_[name.substr(2)] = argv[i + 1];
        }
    }
    [[nodiscard]] const std::string& text(const std::string& name) const { return values_.at(name); }
    [[nodiscard]] long integer(const std::string& name) const { return std::stol(values_.at(name)); }

private:
    std::map<std::string, std::string> values_;
};

/// One row of the agreement table: what was compared, on how many cases, and how many agreed.
struct Row {
    std::string engine;     ///< the independent implementation
    std::string check;      ///< what must agree
    long cases = 0;
    long agree = 0;
    std::string notes;      ///< what else was counted
};

/// Prints the rows, and writes them as Markdown table rows to `path` (when not empty).
inline void write_rows(const std::vector<Row>& rows, const std::string& path) {
    std::ostringstream md;
    for (const Row& r : rows) {
        std::printf("%-20s %-50s %8ld / %-8ld %s\n", r.engine.c_str(), r.check.c_str(), r.agree, r.cases,
                    r.notes.c_str());
        md << "| " << r.engine << " | " << r.check << " | " << r.cases << " | " << r.agree << " | "
           << (r.cases - r.agree) << " | " << r.notes << " |\n";
    }
    if (!path.empty()) {
        std::ofstream out(path);
        if (!out) throw std::runtime_error("cannot write " + path);
        out << md.str();
    }
}

}  // namespace momentlab::validation
