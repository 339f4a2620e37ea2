// Every row of the table in docs/reliability.md, run as a user would: the input written to a
// file (or, for the input "(a sparse file of 2 GiB)", a sparse file of that size), the command
// run, its exit status and its stderr checked. The table is the test's input, so the
// documentation cannot drift from what the tool does.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Row {
    std::string what, command, input, stderr_contains;
    int exit = -1;
};

std::string trim(std::string s) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// `text` -> text; a lone "-" stays "-".
std::string unquote(const std::string& cell) {
    if (cell.size() >= 2 && cell.front() == '`' && cell.back() == '`') return cell.substr(1, cell.size() - 2);
    return cell;
}

// \\n is a newline and \\xNN the byte NN in an input cell.
std::string unescape_newlines(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == 'n') {
            out += '\n';
            ++i;
        } else if (s[i] == '\\' && i + 3 < s.size() && s[i + 1] == 'x') {  // \xNN: one byte
            out += static_cast<char>(std::stoi(s.substr(i + 2, 2), nullptr, 16));
            i += 3;
        } else {
            out += s[i];
        }
    }
    return out;
}

std::vector<Row> read_table() {
    std::ifstream in(std::string(MOMENTLAB_SOURCE) + "/docs/reliability.md");
    std::vector<Row> rows;
    std::string line;
    bool in_table = false;
    while (std::getline(in, line)) {
        if (line.rfind("| what was tried |", 0) == 0) {
            in_table = true;
            continue;
        }
        if (!in_table) continue;
        if (line.rfind("|---", 0) == 0) continue;
        if (line.rfind("|", 0) != 0) break;
        std::vector<std::string> cells;
        std::stringstream ss(line.substr(1));
        std::string cell;
        while (std::getline(ss, cell, '|')) cells.push_back(trim(cell));
        if (cells.size() < 5) {
            ADD_FAILURE() << "malformed row: " << line;
            continue;
        }
        Row r{cells[0], unquote(cells[1]), unescape_newlines(unquote(cells[2])), unquote(cells[4]), std::stoi(cells[3])};
        rows.push_back(r);
    }
    return rows;
}

struct Outcome {
    int status;
    std::string err;
};

Outcome run(const Row& row, const std::string& input_path) {
    std::string args = row.command;
    for (std::size_t at; (at = args.find("{input}")) != std::string::npos;) args.replace(at, 7, input_path);
    const std::string err_path = input_path + ".stderr";
    // A row that redirects stdout itself (to /dev/full) keeps its redirection.
    const std::string out = args.find(" > ") == std::string::npos ? " >/dev/null" : "";
    const std::string cmd = "cd " + std::string(MOMENTLAB_SOURCE) + " && " + MOMENTLAB_BIN + " " + args + out + " 2>" + err_path;
    const int status = std::system(cmd.c_str());
    std::ifstream e(err_path);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, std::string(std::istreambuf_iterator<char>(e), {})};
}

TEST(Reliability, EveryRowOfTheTableInDocs) {
    const std::vector<Row> rows = read_table();
    ASSERT_GE(rows.size(), 40U) << "the table in docs/reliability.md was not found or is short";
    const std::string dir = ::testing::TempDir() + "momentlab_reliability_" + std::to_string(getpid());
    ASSERT_EQ(std::system(("mkdir -p " + dir).c_str()), 0);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Row& row = rows[i];
        const std::string path = dir + "/row" + std::to_string(i) + ".json";
        if (row.input == "(a sparse file of 2 GiB)") {
            // Nothing on disk but its size: the size limit must answer before any reading.
            std::ofstream(path).close();
            ASSERT_EQ(::truncate(path.c_str(), off_t{1} << 31), 0);
        } else if (row.input != "-") {
            std::ofstream(path) << row.input;
        }
        const Outcome o = run(row, path);
        SCOPED_TRACE("row " + std::to_string(i + 1) + ": " + row.what);
        EXPECT_EQ(o.status, row.exit) << o.err;
        EXPECT_NE(o.err.find(row.stderr_contains), std::string::npos) << "stderr: " << o.err;
        if (row.exit == 2) {
            EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << "expected one line, got: " << o.err;
            EXPECT_EQ(o.err.rfind("momentlab: ", 0), 0U) << o.err;
        }
        if (row.exit == 0 && row.stderr_contains.empty()) {
            EXPECT_EQ(o.err, "");
        }
    }
    std::cout << "[Reliability] " << rows.size() << " rows of docs/reliability.md run\n";
    std::system(("rm -rf " + dir).c_str());
}

}  // namespace
