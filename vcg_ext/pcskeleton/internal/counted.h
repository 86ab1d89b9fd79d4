// "1 node", "3 nodes", "1 node has", "2 nodes have": counts in the reports and messages.
#pragma once

#include <cstddef>
#include <string>

namespace pcskeleton {

// `n` followed by `one` or `many`.
inline std::string counted(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// `n` followed by `noun`, with an "s" unless n is 1.
inline std::string counted(std::size_t n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace pcskeleton
