#include "pcskeleton/io/input_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace pcskeleton {

namespace {
constexpr std::size_t kBufferSize = 1u << 20;
}

InputFile::InputFile(const std::string& path) : path_(path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) fail(std::string("the file cannot be opened (") + std::strerror(errno) + ").");
    if (S_ISDIR(status.st_mode)) fail("it is a directory, not a file.");
    file_ = std::fopen(path.c_str(), "rb");
    if (!file_) fail(std::string("the file cannot be opened (") + std::strerror(errno) + ").");
    // A pipe or a device has no size to check counts against: treat it as unbounded.
    size_ = S_ISREG(status.st_mode) ? std::uint64_t(status.st_size) : std::numeric_limits<std::uint64_t>::max();
    buffer_.resize(kBufferSize);
}

InputFile::~InputFile() {
    if (file_) std::fclose(file_);
}

bool InputFile::fill() {
    if (begin_ > 0) {
        std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
        end_ -= begin_;
        begin_ = 0;
    }
    if (end_ == buffer_.size()) buffer_.resize(buffer_.size() * 2);
    const std::size_t got = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, file_);
    if (got == 0 && std::ferror(file_)) fail(std::string("reading failed (") + std::strerror(errno) + ").");
    end_ += got;
    if (got == 0 && size_ != std::numeric_limits<std::uint64_t>::max() && offset_ + (end_ - begin_) < size_) {
        // The file shrank while we read it: count what is there.
        size_ = offset_ + (end_ - begin_);
    }
    return got > 0;
}

bool InputFile::readLine(std::string& line) {
    std::size_t scanned = 0;  // bytes after begin_ known to hold no '\n'
    for (;;) {
        const char* start = buffer_.data() + begin_;
        const void* newline = std::memchr(start + scanned, '\n', end_ - begin_ - scanned);
        if (newline) {
            const std::size_t length = static_cast<const char*>(newline) - start;
            line.assign(start, length);
            begin_ += length + 1;
            offset_ += length + 1;
            break;
        }
        scanned = end_ - begin_;
        if (scanned > kMaxLineLength) {
            ++lineNumber_;
            failAtLine("the line is longer than " + std::to_string(kMaxLineLength >> 20) + " MiB.");
        }
        if (!fill()) {
            if (scanned == 0) return false;
            line.assign(buffer_.data() + begin_, scanned);  // last line without '\n'
            begin_ += scanned;
            offset_ += scanned;
            break;
        }
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    ++lineNumber_;
    return true;
}

std::size_t InputFile::reservable(std::uint64_t declared, std::uint64_t minimumBytes) const {
    const bool sizeKnown = size_ != std::numeric_limits<std::uint64_t>::max();
    const std::uint64_t fits = sizeKnown ? remaining() / std::max<std::uint64_t>(minimumBytes, 1) : 1u << 20;
    return std::size_t(std::min(declared, fits));
}

bool InputFile::readBytes(void* out, std::size_t n) {
    while (end_ - begin_ < n) {
        if (!fill()) return false;
    }
    std::memcpy(out, buffer_.data() + begin_, n);
    begin_ += n;
    offset_ += n;
    return true;
}

void InputFile::fail(const std::string& why) const { throw InvalidInput("Cannot read '" + path_ + "': " + why); }

void InputFile::failAtLine(const std::string& why) const { fail("line " + std::to_string(lineNumber_) + ": " + why); }

bool readNumber(const char*& cursor, double& value) {
    while (*cursor == ' ' || *cursor == '\t' || *cursor == ',') ++cursor;
    char* end = nullptr;
    value = std::strtod(cursor, &end);
    if (end == cursor) return false;
    if (*end != '\0' && *end != ' ' && *end != '\t' && *end != ',') return false;
    cursor = end;
    return true;
}

std::string extensionOf(const std::string& path) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

bool sameFile(const std::string& a, const std::string& b) {
    struct stat first {}, second {};
    if (::stat(a.c_str(), &first) != 0 || ::stat(b.c_str(), &second) != 0) return false;
    return first.st_dev == second.st_dev && first.st_ino == second.st_ino;
}

bool fileExists(const std::string& path) {
    struct stat status {};
    return ::stat(path.c_str(), &status) == 0;
}

void writeFileAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    // The temporary sits next to the target, so that rename() stays on one file system.
    std::string pattern = path + ".partial-XXXXXX";
    const int descriptor = ::mkstemp(pattern.data());
    if (descriptor < 0) {
        throw InvalidInput("Cannot write '" + path + "': " + std::strerror(errno) + ".");
    }
    ::close(descriptor);
    try {
        write(pattern);
    } catch (const InvalidInput& e) {
        std::remove(pattern.c_str());
        // The writer names the temporary; the user knows the file by its real name.
        std::string message = e.problem().description;
        for (auto at = message.find(pattern); at != std::string::npos; at = message.find(pattern)) {
            message.replace(at, pattern.size(), path);
        }
        throw InvalidInput(message);
    } catch (...) {
        std::remove(pattern.c_str());
        throw;
    }
    // mkstemp makes the file private (0600); give it the permissions a new file would get.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::chmod(pattern.c_str(), 0666 & ~mask);
    if (std::rename(pattern.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(pattern.c_str());
        throw InvalidInput("Cannot write '" + path + "': " + reason + ".");
    }
}

}  // namespace pcskeleton
