// The two ways the library refuses work: the user's input cannot be processed (a Problem
// to show, with its remedies), or a caller broke a precondition (a bug to report).
#pragma once

#include "pcskeleton/core/advice.h"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace pcskeleton {

// Thrown for data or parameters the algorithm cannot work on. what() is the problem in the
// library's words; a front end shows describe(problem(), its own terms).
class InvalidInput : public std::runtime_error {
public:
    explicit InvalidInput(Problem problem) : std::runtime_error(describe(problem)), problem_(std::move(problem)) {}
    explicit InvalidInput(const std::string& description, std::vector<Remedy> remedies = {})
        : InvalidInput(Problem{description, std::move(remedies)}) {}

    const Problem& problem() const { return problem_; }

private:
    Problem problem_;
};

// Thrown when a caller breaks a precondition no user input can cause (mismatched array
// sizes, an index out of range): front ends report it as an internal error.
class CallerError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

}  // namespace pcskeleton
