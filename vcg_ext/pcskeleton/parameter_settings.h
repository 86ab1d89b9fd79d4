// Every parameter of the parameter table (core/parameter_table.h) bound to its field: read,
// set with its range check, and the settings a front end's options give.
//
//     Settings s = settingsFrom(paper, {{Parameter::NodeSpacing, 0.03}, ...});
//     computeCurveSkeleton(points, s.skeleton);
#pragma once

#include "pcskeleton/core/parameter_table.h"
#include "pcskeleton/curve_skeleton.h"
#include "pcskeleton/reconstruction/skeleton_reconstruction.h"

#include <utility>
#include <vector>

namespace pcskeleton {

struct Settings {
    SkeletonParameters skeleton;
    ReconstructionParameters reconstruction;

    // The paper's pipeline, skeleton and surface, with its defaults.
    static Settings paper();
};

// The value in the user's units (GB for the memory limit; 1 or 0 for a switch, true meaning
// what its name says: keep_outliers = 1 when outlier detection is off).
double parameterValue(const Settings& settings, Parameter id);
inline double defaultValue(Parameter id) { return parameterValue(Settings{}, id); }

// Throws InvalidInput naming the parameter when the library would refuse `value` (not a
// whole number for an integer, out of range, not finite), else sets it.
void setParameter(Settings& settings, Parameter id, double value);

// What a front end's options mean, in one way everywhere: the defaults, or the paper's
// pipeline when `paper`, then every given value, whatever order they were given in (a
// parameter given twice takes its last value). Each value is checked as it is set.
Settings settingsFrom(bool paper, const std::vector<std::pair<Parameter, double>>& given);
// The same starting from `settings` instead of the defaults.
Settings withParameters(Settings settings, const std::vector<std::pair<Parameter, double>>& given);

}  // namespace pcskeleton
