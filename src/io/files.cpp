// Reading input files safely (io/files.hpp), with POSIX calls: every error has its reason.
#include "momentlab/io/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "momentlab/io/input_error.hpp"

namespace momentlab {
namespace {

std::string reason(int error) { return std::strerror(error); }

// Opens a file for reading; a directory or an unreadable file is an InputError at `where`.
int open_input(const std::string& path, const std::string& where, struct stat& st) {
    if (::stat(path.c_str(), &st) != 0) {
        throw InputError(where, "cannot read file \"" + path + "\" (" + reason(errno) + ")");
    }
    if (S_ISDIR(st.st_mode)) throw InputError(where, "cannot read file \"" + path + "\" (a directory)");
    if (S_ISREG(st.st_mode) && static_cast<unsigned long long>(st.st_size) > kMaxInputBytes) {
        throw InputError(where, "cannot read file \"" + path + "\" (" + std::to_string(st.st_size) +
                                    " bytes: larger than the limit of 1 GiB)");
    }
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw InputError(where, "cannot read file \"" + path + "\" (" + reason(errno) + ")");
    return fd;
}

// One read(2), retried when interrupted; -1 with errno on error.
ssize_t read_some(int fd, char* data, std::size_t size) {
    for (;;) {
        const ssize_t n = ::read(fd, data, size);
        if (n >= 0 || errno != EINTR) return n;
    }
}

class FileCloser {
public:
    explicit FileCloser(int fd) : fd_(fd) {}
    ~FileCloser() { ::close(fd_); }
    FileCloser(const FileCloser&) = delete;
    FileCloser& operator=(const FileCloser&) = delete;

private:
    int fd_;
};

[[noreturn]] void not_json(const std::string& path, const std::string& where, std::size_t offset, unsigned char byte,
                           const char* what) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02x", byte);
    throw InputError(where, "cannot read file \"" + path + "\" (not a JSON document: " + what + ", byte " + hex +
                                " at offset " + std::to_string(offset) + ")");
}

}  // namespace

std::string read_json_file(const std::string& path, const std::string& where) {
    struct stat st {};
    const int fd = open_input(path, where, st);
    FileCloser closer(fd);
    std::string text;
    if (S_ISREG(st.st_mode)) text.reserve(static_cast<std::size_t>(st.st_size));
    char chunk[1 << 16];
    bool looked = false;
    for (;;) {
        const ssize_t n = read_some(fd, chunk, sizeof chunk);
        if (n < 0) throw InputError(where, "cannot read file \"" + path + "\" (" + reason(errno) + ")");
        if (n == 0) break;
        const std::size_t from = text.size();
        text.append(chunk, static_cast<std::size_t>(n));
        // JSON text holds no control bytes but blanks (inside strings they are escaped), and its
        // first byte that is not blank (after an optional UTF-8 byte order mark) opens an object or
        // a list: a binary file or a device fails at its first bad byte, not at the size limit.
        for (std::size_t i = from; i < text.size(); ++i) {
            const auto c = static_cast<unsigned char>(text[i]);
            const bool blank = c == ' ' || c == '\t' || c == '\n' || c == '\r';
            if (c < 0x20 && !blank) not_json(path, where, i, c, "a control byte");
            if (!looked && !blank && !(i < 3 && text.compare(0, i + 1, std::string("\xEF\xBB\xBF").substr(0, i + 1)) == 0)) {
                looked = true;
                if (c != '{' && c != '[') not_json(path, where, i, c, "expected { or [");
            }
        }
        if (text.size() > kMaxInputBytes) {
            throw InputError(where, "cannot read file \"" + path + "\" (more than the limit of 1 GiB)");
        }
    }
    return text;
}

LineReader::LineReader(const std::string& path, std::string option) : path_(path), option_(std::move(option)) {
    struct stat st {};
    fd_ = open_input(path, option_, st);
}

LineReader::~LineReader() {
    if (fd_ >= 0) ::close(fd_);
}

bool LineReader::next(std::string& line) {
    for (;;) {
        const std::size_t end = buffer_.find('\n', start_);
        if (end != std::string::npos || (eof_ && start_ < buffer_.size())) {
            const std::size_t stop = end == std::string::npos ? buffer_.size() : end;
            line.assign(buffer_, start_, stop - start_);
            start_ = stop + (end == std::string::npos ? 0 : 1);
            ++number_;
            return true;
        }
        if (eof_) return false;
        if (buffer_.size() - start_ > kMaxLineBytes) {
            throw InputError(path_ + ":" + std::to_string(number_ + 1), "a line longer than 1 MiB (expected [fx, fy, tau])");
        }
        buffer_.erase(0, start_);
        start_ = 0;
        char chunk[1 << 16];
        const ssize_t n = read_some(fd_, chunk, sizeof chunk);
        if (n < 0) throw InputError(option_, "cannot read file \"" + path_ + "\" (" + reason(errno) + ")");
        if (n == 0) eof_ = true;
        buffer_.append(chunk, static_cast<std::size_t>(n));
    }
}

}  // namespace momentlab
