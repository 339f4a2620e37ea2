#pragma once

/// \file
/// Reading input files safely (the CLI's file arguments, the Python module's Scene.from_file):
/// every read error reported, directories refused, sizes limited, and a file that cannot be
/// JSON refused at its first bad byte, so that a device such as /dev/zero fails at once.

#include <cstddef>
#include <string>

namespace momentlab {

/// The largest input file read (scene, force set, wrench file): 1 GiB.
inline constexpr std::size_t kMaxInputBytes = std::size_t{1} << 30;
/// The longest line of a wrench file: 1 MiB.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

/// The whole of a JSON file. Throws InputError at `where` ("$" for the file argument) for a
/// missing file, a directory, a read error, a file over kMaxInputBytes, or one that cannot be
/// JSON text: a first non-blank byte other than { or [, or a control byte other than a blank
/// (checked as the bytes arrive: /dev/zero and /dev/urandom fail in the first read).
std::string read_json_file(const std::string& path, const std::string& where = "$");

/// A text file read line by line with POSIX reads: every read error is reported, a directory
/// is refused when opened, and a line longer than kMaxLineBytes is an error (a device that
/// never ends fails within a megabyte).
class LineReader {
public:
    /// Throws InputError at `option` when the file cannot be opened or is a directory.
    LineReader(const std::string& path, std::string option);
    ~LineReader();
    LineReader(const LineReader&) = delete;
    LineReader& operator=(const LineReader&) = delete;
    /// The next line (without its newline), false at the end of the file.
    bool next(std::string& line);
    /// The number of the line last returned (1-based).
    [[nodiscard]] std::size_t number() const { return number_; }

private:
    std::string path_, option_;
    int fd_ = -1;
    std::string buffer_;
    std::size_t start_ = 0;
    std::size_t number_ = 0;
    bool eof_ = false;
};

}  // namespace momentlab
