#include "pcskeleton/io/input_file.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <csignal>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <locale>
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

bool parseNumber(const char* first, const char* last, double& value) {
    if (first != last && *first == '+') ++first;  // strtod's, not from_chars'
    // from_chars reads the same digits in every locale (MeshLab runs in the user's, where
    // strtod may take a comma for the decimal point).
    const auto [end, error] = std::from_chars(first, last, value);
    if (end != last || end == first) return false;
    if (error == std::errc::result_out_of_range) {
        // Beyond a double's range: to infinity or zero, as strtod rounds, for the checks
        // of finite coordinates to name.
        const char* exponent = std::find_if(first, last, [](char c) { return c == 'e' || c == 'E'; });
        const bool negative = *first == '-';
        const bool tiny = exponent != last && exponent + 1 != last && exponent[1] == '-';
        value = tiny ? (negative ? -0.0 : 0.0)
                     : (negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity());
    } else if (error != std::errc()) {
        return false;
    }
    return true;
}

bool readNumber(const char*& cursor, double& value, NumberSeparators separators) {
    const auto isSeparator = [&](char c) {
        return c == ' ' || c == '\t' || (separators == NumberSeparators::BlanksOrCommas && c == ',');
    };
    while (isSeparator(*cursor)) ++cursor;
    const char* end = cursor;
    while (*end != '\0' && !isSeparator(*end)) ++end;
    if (end == cursor || !parseNumber(cursor, end, value)) return false;
    cursor = end;
    return true;
}

bool mixesCommasAndBlanks(const std::string& line) {
    // Each separator between two numbers, as (holds a comma, holds a blank).
    int kinds = 0;  // bit per kind seen: 1 comma only, 2 blank only, 4 comma and blank
    bool inNumber = false, sawNumber = false, comma = false, blank = false;
    for (char c : line) {
        const bool isComma = c == ',', isBlank = c == ' ' || c == '\t';
        if (!isComma && !isBlank) {
            if (!inNumber && sawNumber) kinds |= comma && blank ? 4 : comma ? 1 : 2;
            inNumber = sawNumber = true;
            comma = blank = false;
        } else {
            inNumber = false;
            comma = comma || isComma;
            blank = blank || isBlank;
        }
    }
    // One kind throughout ("1 2 3", "1,2,3", "1, 2, 3"), else "1,5 2,5" or "0,5, 1,5".
    return kinds != 0 && (kinds & (kinds - 1)) != 0;
}

std::string decimalCommaHint(const std::string& line) {
    return line.find(',') == std::string::npos ? "" : " (decimal commas such as '1,5' are not read: write '1.5')";
}

std::string extensionOf(const std::string& path) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

std::optional<FileIdentity> fileIdentity(const std::string& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return std::nullopt;
    return FileIdentity{std::uint64_t(status.st_dev), std::uint64_t(status.st_ino)};
}

bool sameFile(const std::string& a, const std::string& b) {
    const std::optional<FileIdentity> first = fileIdentity(a);
    return first && first == fileIdentity(b);
}

bool fileExists(const std::string& path) {
    struct stat status {};
    return ::stat(path.c_str(), &status) == 0;
}

namespace {

struct TemporaryName {
    std::string folder;  // "" for the current one
    std::string prefix;  // "<name>.partial-": the pid and a unique suffix follow
};

// The temporary sits next to the target, so that rename() stays on one file system; its
// name holds the writing process's id, so that a later write to the same file can tell
// the leftovers of a killed run from the temporaries of a live one. A long name is
// shortened so that the temporary's fits where the file's does.
TemporaryName temporaryName(const std::string& path) {
    const auto slash = path.find_last_of('/');
    TemporaryName name;
    name.folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string file = slash == std::string::npos ? path : path.substr(slash + 1);
    constexpr std::size_t kRoomForSuffix = 40;  // ".partial-" + pid + "-XXXXXX"
    name.prefix = file.substr(0, std::min(file.size(), std::size_t(NAME_MAX) - kRoomForSuffix)) + ".partial-";
    return name;
}

// Removes "<prefix><pid>-XXXXXX" files of processes that no longer run.
void removeStaleTemporaries(const TemporaryName& name) {
    DIR* folder = ::opendir(name.folder.empty() ? "." : name.folder.c_str());
    if (!folder) return;
    std::vector<std::string> stale;
    while (const dirent* entry = ::readdir(folder)) {
        const std::string file = entry->d_name;
        if (file.compare(0, name.prefix.size(), name.prefix) != 0) continue;
        const char* digits = file.c_str() + name.prefix.size();
        char* end = nullptr;
        const long pid = std::strtol(digits, &end, 10);
        if (end == digits || *end != '-' || pid <= 0) continue;
        if (::kill(pid_t(pid), 0) != 0 && errno == ESRCH) stale.push_back(name.folder + file);
    }
    ::closedir(folder);
    for (const std::string& file : stale) std::remove(file.c_str());
}

// Creates an empty temporary for `path`: its name, or "" and the errno that prevented it.
std::string createTemporary(const std::string& path, int& error) {
    const TemporaryName name = temporaryName(path);
    removeStaleTemporaries(name);
    std::string pattern = name.folder + name.prefix + std::to_string(::getpid()) + "-XXXXXX";
    const int descriptor = ::mkstemp(pattern.data());
    if (descriptor < 0) {
        error = errno;
        return "";
    }
    ::close(descriptor);
    return pattern;
}

}  // namespace

void checkWritable(const std::string& path) {
    const auto refuse = [&](const std::string& why) { throw InvalidInput("Cannot write '" + path + "': " + why); };
    const TemporaryName name = temporaryName(path);
    const std::string file = path.substr(name.folder.size());
    const long longest = ::pathconf(name.folder.empty() ? "." : name.folder.c_str(), _PC_NAME_MAX);
    if (file.empty()) refuse("no file name.");
    if (file.size() > std::size_t(longest > 0 ? longest : NAME_MAX)) {
        refuse("the file name is " + std::to_string(file.size()) + " bytes long, longer than the " +
               std::to_string(longest > 0 ? longest : NAME_MAX) + " its folder allows.");
    }
    struct stat status {};
    if (::stat(path.c_str(), &status) == 0) {
        if (S_ISDIR(status.st_mode)) refuse("it is a directory.");
    } else if (errno != ENOENT) {
        refuse(std::string(std::strerror(errno)) + ".");
    }
    // The folder must exist and take a new file: made and removed at once.
    int error = 0;
    const std::string probe = createTemporary(path, error);
    if (probe.empty()) {
        std::string folder = name.folder.empty() ? "." : name.folder;
        if (folder.size() > 1) folder.pop_back();  // its '/'
        struct stat folderStatus {};
        if (error == ENOENT && ::stat(folder.c_str(), &folderStatus) != 0) {
            refuse("the folder '" + folder + "' does not exist.");
        }
        refuse("a file cannot be created in the folder '" + folder + "' (" + std::strerror(error) + ").");
    }
    std::remove(probe.c_str());
}

void writeTextFile(const std::string& path, const std::function<void(std::ostream&)>& write) {
    std::ofstream out(path);
    if (!out) throw InvalidInput("Cannot write '" + path + "': the file cannot be created.");
    out.imbue(std::locale::classic());
    out << std::setprecision(17);
    write(out);
    out.close();
    if (!out) throw InvalidInput("Cannot write '" + path + "': writing failed (disk full?).");
}

void writeFileAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    int error = 0;
    const std::string temporary = createTemporary(path, error);
    if (temporary.empty()) throw InvalidInput("Cannot write '" + path + "': " + std::strerror(error) + ".");
    try {
        write(temporary);
    } catch (const InvalidInput& e) {
        std::remove(temporary.c_str());
        // The writer names the temporary; the user knows the file by its real name.
        std::string message = e.problem().description;
        for (auto at = message.find(temporary); at != std::string::npos; at = message.find(temporary)) {
            message.replace(at, temporary.size(), path);
        }
        throw InvalidInput(message);
    } catch (...) {
        std::remove(temporary.c_str());
        throw;
    }
    // mkstemp makes the file private (0600); give it the permissions a new file would get.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::chmod(temporary.c_str(), 0666 & ~mask);
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        throw InvalidInput("Cannot write '" + path + "': " + reason + ".");
    }
}

}  // namespace pcskeleton
