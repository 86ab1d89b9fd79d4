// How the MeshLab plugins word the library's advice: each parameter by its label in the
// filter dialogs, each step by the MeshLab menu or tool that takes it.
#pragma once

#include <pcskeleton/core/advice.h>

#include <QString>

namespace pcskeleton::meshlab {

// The parameter's label in the filter dialogs (one source for the dialogs and the advice).
QString parameterLabel(Parameter parameter);

// For the filters' log and error messages.
const Terms& filterTerms();

// For the Edit Skeleton tool's panel: the hand edits are its own keys.
const Terms& editorTerms();

// "pcskeleton 0.1.0": the plugins' vendor column in Help > Plugin Info (MeshLab 2021+).
QString pluginVendor();

// A filter's or tool's description with the version on a line of its own under it:
// MeshLab 2020.09's Help > Plugin Info shows the descriptions and nothing else.
QString withVersion(const QString& description);

// The problem worded for MeshLab, as a QString.
QString describeForMeshLab(const Problem& problem, const Terms& terms = filterTerms());

}  // namespace pcskeleton::meshlab
