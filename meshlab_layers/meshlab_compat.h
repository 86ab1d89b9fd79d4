// One codebase for MeshLab 2020.09 (Debian 12), 2022.02 (Debian 13) and 2025.07.
//
// MeshLab 2021.05 renamed the plugin interfaces (MeshFilterInterface -> FilterPlugin,
// MeshEditInterface(Factory) -> EditTool/EditPlugin), made actions const, returns the
// parameter list instead of filling one, reports errors by exception, hid the document's
// layer list and renamed Log() to log(); 2025.07 also renamed the file parameters. What
// the plugins need of those is here, chosen by PCSKELETON_MESHLAB_VERSION (YYYYMM, set by
// CMake from the MeshLab tree it builds against); the interface entry points themselves
// are small #if blocks in the plugin headers, forwarding to version-neutral members.
#pragma once

#ifndef PCSKELETON_MESHLAB_VERSION
#error "PCSKELETON_MESHLAB_VERSION is set by CMake from the MeshLab source tree (cmake/MeshLabSDK.cmake)"
#endif

// MeshLab 2021.05 and later: the plugin API of 2022.02 and 2025.07.
#define PCSKELETON_MESHLAB_2021_API (PCSKELETON_MESHLAB_VERSION >= 202105)

#if PCSKELETON_MESHLAB_2021_API
#include <common/plugins/interfaces/edit_plugin.h>
#include <common/plugins/interfaces/filter_plugin.h>
#else
#include <common/interfaces.h>
#endif

#include <QString>

#include <utility>
#include <vector>

namespace pcskeleton::meshlab {

#if PCSKELETON_MESHLAB_2021_API
using FilterPluginBase = FilterPlugin;
using EditToolBase = EditTool;
using EditPluginBase = EditPlugin;
using FilterAction = const QAction*;
#else
using FilterPluginBase = MeshFilterInterface;
using EditToolBase = MeshEditInterface;
using EditPluginBase = MeshEditInterfaceFactory;
using FilterAction = QAction*;
#endif

#if PCSKELETON_MESHLAB_VERSION >= 202507
using FileSaveParameter = RichFileSave;
#else
using FileSaveParameter = RichSaveFile;
#endif

// A dialog field that MeshLab 2021.05 and later show behind their advanced toggle; 2020.09
// has none, and shows it where it is added (after the common fields).
template <class Field, class Value>
Field richParameter(const QString& name, Value value, const QString& label, const QString& help, bool advanced) {
#if PCSKELETON_MESHLAB_2021_API
    return Field(name, value, label, help, advanced);
#else
    (void)advanced;
    return Field(name, value, label, help);
#endif
}

// Every layer of the document, in MeshLab's order.
inline std::vector<MeshModel*> layersOf(MeshDocument& md) {
    std::vector<MeshModel*> layers;
#if PCSKELETON_MESHLAB_2021_API
    for (MeshModel& m : md.meshIterator()) layers.push_back(&m);
#else
    for (MeshModel* m : md.meshList) layers.push_back(m);
#endif
    return layers;
}

inline std::vector<const MeshModel*> layersOf(const MeshDocument& md) {
    std::vector<const MeshModel*> layers;
#if PCSKELETON_MESHLAB_2021_API
    for (const MeshModel& m : md.meshIterator()) layers.push_back(&m);
#else
    for (const MeshModel* m : md.meshList) layers.push_back(m);
#endif
    return layers;
}

// A "choose a layer" parameter whose default is `layer` (or the current one).
inline RichMesh layerParameter(const QString& name, MeshModel* layer, MeshDocument& md, const QString& label,
                               const QString& help) {
#if PCSKELETON_MESHLAB_2021_API
    if (!layer) layer = md.mm();
    return RichMesh(name, layer ? layer->id() : 0u, &md, label, help);
#else
    return RichMesh(name, layer, &md, label, help);
#endif
}

// The layer a "choose a layer" parameter names, or nullptr.
inline MeshModel* layerParameterValue(MeshDocument& md, const RichParameterList& parameters, const QString& name) {
#if PCSKELETON_MESHLAB_2021_API
    return md.getMesh(parameters.getMeshId(name));
#else
    (void)md;
    return parameters.getMesh(name);
#endif
}

// The layer's bounding box and normals, after its vertices or faces changed.
inline void updateBoxAndNormals(MeshModel& layer) {
#if PCSKELETON_MESHLAB_2021_API
    layer.updateBoxAndNormals();
#else
    layer.UpdateBoxAndNormals();
#endif
}

// MeshLab's log window (and the runner's output) for a filter plugin or an edit tool.
template <typename Plugin, typename... Args>
void writeLog(Plugin& plugin, Args&&... args) {
#if PCSKELETON_MESHLAB_2021_API
    plugin.log(std::forward<Args>(args)...);
#else
    plugin.Log(std::forward<Args>(args)...);
#endif
}

}  // namespace pcskeleton::meshlab
