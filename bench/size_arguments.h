// The point counts a benchmark is given on its command line: whole positive numbers only,
// so that a misspelt option or a typo stops the run with its usage instead of being read
// as a size of 0 (an empty cloud) or of its leading digits.
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstdlib>

// The count `text` spells, or 0 if it is not a whole number from 1 to 2^63.
inline unsigned long long pointCount(const char* text) {
    if (text[0] < '0' || text[0] > '9') return 0;
    char* end = nullptr;
    errno = 0;
    const unsigned long long n = std::strtoull(text, &end, 10);
    return *end == '\0' && errno == 0 && n < (1ull << 63) ? n : 0;
}

// Prints `usage` to stderr and ends the program with status 2 (a bad command line).
[[noreturn]] inline void exitWithUsage(const char* problem, const char* argument, const char* usage) {
    std::fprintf(stderr, "%s: %s\nusage: %s\n", problem, argument, usage);
    std::exit(2);
}
