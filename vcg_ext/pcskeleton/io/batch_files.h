// The files of a batch and the names of their outputs, the same for every front end that
// runs many scans (the command line's -O, Python's skeletonize_files).
#pragma once

#include <string>
#include <vector>

namespace pcskeleton {

// The point files an input argument names: itself (a file, even a missing one: its run
// then reports it), the point files of a folder (not its subfolders), or a glob's matches.
// Sorted within each argument; each file once. Throws InvalidInput for a glob that
// matches nothing and a folder without point files.
std::vector<std::string> expandInputs(const std::vector<std::string>& arguments);

// A name per input for its outputs: its file name without extension, told apart when two
// inputs share it by their folders (a_scan, b_scan), or by their extensions if in one folder.
std::vector<std::string> outputStems(const std::vector<std::string>& inputs);

// "{stem}" in a pattern replaced by `stem`.
std::string fromPattern(const std::string& pattern, const std::string& stem);

}  // namespace pcskeleton
