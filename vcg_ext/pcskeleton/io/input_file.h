// A file read front to back through a buffer, knowing where it is. Every reader of the
// library reads through it, so that a malformed file cannot crash us or make us allocate
// what it merely claims: error messages name the line or the byte offset, and a count
// declared in a header can be checked against the bytes that are really left.
#pragma once

#include "pcskeleton/core/errors.h"

#include <cstdint>
#include <cstdio>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pcskeleton {

class InputFile {
public:
    // Refuses a missing, unreadable or non-regular file (a directory) with InvalidInput.
    explicit InputFile(const std::string& path);
    ~InputFile();
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    const std::string& path() const { return path_; }
    std::uint64_t size() const { return size_; }
    std::uint64_t offset() const { return offset_; }
    std::uint64_t remaining() const { return size_ - offset_; }
    // 1-based number of the last line readLine() returned.
    std::uint64_t lineNumber() const { return lineNumber_; }

    // The next line without its '\n' or "\r\n"; false at the end of the file. A line longer
    // than kMaxLineLength is refused rather than held in memory whole.
    bool readLine(std::string& line);
    // How many of `declared` records to reserve memory for: never more than the bytes left
    // could hold at minimumBytes each, nor more than a million when the size is unknown
    // (a pipe), whatever a header claims.
    std::size_t reservable(std::uint64_t declared, std::uint64_t minimumBytes) const;
    // Exactly n bytes, or false (and nothing consumed that matters) when fewer are left.
    bool readBytes(void* out, std::size_t n);

    // "Cannot read '<path>': <why>" as InvalidInput.
    [[noreturn]] void fail(const std::string& why) const;
    // The same, prefixed with "line N: ".
    [[noreturn]] void failAtLine(const std::string& why) const;

    static constexpr std::size_t kMaxLineLength = 64u << 20;

private:
    bool fill();  // false when nothing more can be read

    std::string path_;
    std::FILE* file_ = nullptr;
    std::uint64_t size_ = 0, offset_ = 0, lineNumber_ = 0;
    std::vector<char> buffer_;
    std::size_t begin_ = 0, end_ = 0;
};

// Reads the whole of [first, last) as one number, in the same way in every locale; false
// when it is not one ("1.5abc", "1,5"). "nan" and "inf" are read, and numbers beyond a
// double's range become infinite or zero, for the checks of coordinates to name them.
bool parseNumber(const char* first, const char* last, double& value);

// Which characters may stand between the numbers of a line: blanks (OFF, OBJ, PLY), or
// blanks and commas (XYZ files are often comma separated).
enum class NumberSeparators { Blanks, BlanksOrCommas };

// Reads the next number of a text line and moves the cursor past it; false when the
// line has no further number or when one is glued to other characters ("1.5abc", or
// "1,5" where commas do not separate numbers).
bool readNumber(const char*& cursor, double& value, NumberSeparators separators = NumberSeparators::Blanks);

// True when the separators between the numbers of a line are not all of one kind (a
// comma, blanks, or a comma with blanks), as in "1,5 2,5 3,5" or "0,5, 1,5, 2,5" (decimal
// commas), which must not be read as six numbers. Comma-separated values keep one kind.
bool mixesCommasAndBlanks(const std::string& line);

// For a number line that could not be read: " (decimal commas such as '1,5' are not read:
// write '1.5')" when it holds a comma, else "".
std::string decimalCommaHint(const std::string& line);

// The lower-case extension of a file name without the dot ("" if none).
std::string extensionOf(const std::string& path);

// Which existing file a name leads to (device and inode: hard links and "./a" vs "a" lead
// to one); none when it does not exist.
using FileIdentity = std::pair<std::uint64_t, std::uint64_t>;
std::optional<FileIdentity> fileIdentity(const std::string& path);

// True when both names lead to the same existing file (hard links and "./a" vs "a"
// included); false when either does not exist.
bool sameFile(const std::string& a, const std::string& b);

bool fileExists(const std::string& path);

// Throws InvalidInput, naming the reason, unless a file can be written at `path`: it is
// not a directory, its name fits the folder, and the folder exists and takes a new file
// (tried by making and removing a temporary there). For checks before any work.
void checkWritable(const std::string& path);

// Writes a file through write(temporaryPath) and renames it to path only once it is
// complete, so that a failed or interrupted write never leaves a truncated file in place
// of an existing one. write() throws (InvalidInput) on failure; the temporary is removed.
// Temporaries are "<name>.partial-<pid>-XXXXXX": those of processes that are gone (a
// killed run) are removed by the next write to the same file.
void writeFileAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

// Writes the text file `path` (typically writeFileAtomically's temporary): `write` fills a
// stream that formats numbers in the classic locale, whatever the program's, with 17
// significant digits. Throws InvalidInput when the file cannot be created or written.
void writeTextFile(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace pcskeleton
