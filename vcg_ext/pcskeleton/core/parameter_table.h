// The one description of every parameter a user can set: its name, what it does and which
// way to turn it, whether it is advanced, and how a dialog labels it. The command line's
// options and help, Python's keywords and docstrings, the MeshLab dialogs and the advice of
// every front end are made from this table; each front end only spells the names its way
// (the Python keyword is `name`, the option `--name` with dashes, the .mlx name `meshlabName`).
//
// What a parameter's value is bound to (its field, its default, its range check) is in
// pcskeleton/parameter_settings.h, next to the parameter structs.
#pragma once

#include "pcskeleton/core/advice.h"

#include <string>
#include <string_view>
#include <vector>

namespace pcskeleton {

enum class ValueType { Integer, Real, Switch };

// Which computation a parameter belongs to (and so which dialogs show it).
enum class Stage {
    Contraction,     // paper steps 1-3
    PointCleaning,   // which points the contraction works on: outliers, denoising
    Resolution,      // how many points are contracted, and memory
    Thinning,        // paper steps 4-5 and the steps after them
    Reconstruction,  // paper Sec. V
};

struct ParameterInfo {
    Parameter id;
    // snake_case: Python's keyword; the command line's option is "--" + name with dashes.
    const char* name;
    ValueType type;
    Stage stage;
    // Most users never change it: MeshLab shows it behind its advanced toggle, after the
    // common ones, and the help lists it last.
    bool advanced;
    // For a switch: true when the name says the opposite of the words ("keep_outliers" turns
    // off "outlier detection"); the dialogs show the words' way (a box "Detect outliers").
    bool inverted;
    const char* words;        // the library's words in a sentence: "the contraction scale s_L"
    const char* label;        // a dialog's label, the words' way round
    const char* meshlabName;  // the field's name in the dialogs and .mlx scripts; nullptr: not in them
    const char* help;         // what it does, which way to turn it, what 0 or -1 means
    const char* formerName = nullptr;  // an earlier name, still accepted by the command line and Python
};

// In the order the front ends list them.
const std::vector<ParameterInfo>& parameterTable();
const ParameterInfo& parameterInfo(Parameter id);
// nullptr for a name that is no parameter's.
const ParameterInfo* parameterNamed(std::string_view name);

}  // namespace pcskeleton
