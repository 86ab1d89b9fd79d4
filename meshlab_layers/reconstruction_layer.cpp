#include "reconstruction_layer.h"

#include "skeleton_layer.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

namespace pcskeleton::meshlab {

namespace {
bool isSkeleton(const MeshModel& layer) { return notASkeletonReason(layer).isEmpty(); }
}  // namespace

MeshModel* defaultSkeletonLayer(MeshDocument& md) {
    MeshModel* current = md.mm();
    if (current && isSkeleton(*current)) return current;
    MeshModel* any = nullptr;
    for (MeshModel* m : layersOf(md)) {
        if (!isSkeleton(*m)) continue;
        if (current && sourceLayerOf(md, *m) == current) return m;
        if (!any) any = m;
    }
    return any ? any : current;
}

MeshModel* defaultPointsLayer(MeshDocument& md) {
    MeshModel* current = md.mm();
    if (current && !isSkeleton(*current)) return current;
    if (current)
        if (MeshModel* source = sourceLayerOf(md, *current)) return source;
    for (MeshModel* m : layersOf(md))
        if (!isSkeleton(*m) && m->cm.vn > 0) return m;
    return current;
}

ReconstructedLayer addReconstructionLayer(MeshDocument& md, const MeshModel& points, const MeshModel& skeleton,
                                          const ReconstructionParameters& parameters,
                                          const ProgressCallback& progress, bool makeCurrent) {
    if (&points == &skeleton)
        throw InvalidInput("Choose two different layers: the point cloud and the skeleton computed from it.");
    const QString skeletonProblem = notASkeletonReason(skeleton);
    if (!skeletonProblem.isEmpty()) throw InvalidInput(qUtf8Printable(skeletonProblem));
    if (points.cm.vn == 0)
        throw InvalidInput(qUtf8Printable(QString("Layer '%1' is empty: choose the point cloud the skeleton was "
                                                  "computed from.").arg(points.label())));
    if (points.cm.en > 0 && points.cm.fn == 0)
        throw InvalidInput(qUtf8Printable(QString("Layer '%1' is a skeleton, not a point cloud: choose the points "
                                                  "to reconstruct as the point layer.").arg(points.label())));

    const Reconstruction result =
        reconstructFromSkeleton(collectPoints(points).points, readSkeletonLayer(skeleton), parameters, progress);

    MeshModel* layer = md.addNewMesh("", derivedLabel(points, "reconstruction"), makeCurrent);
    CMeshO& m = layer->cm;
    auto vertex = vcg::tri::Allocator<CMeshO>::AddVertices(m, result.mesh.vertices.size());
    for (const Point& p : result.mesh.vertices) (vertex++)->P() = CMeshO::CoordType(p.x(), p.y(), p.z());
    auto face = vcg::tri::Allocator<CMeshO>::AddFaces(m, result.mesh.triangles.size());
    for (const auto& t : result.mesh.triangles) {
        for (int c = 0; c < 3; ++c) face->V(c) = &m.vert[t[c]];
        ++face;
    }
    m.Tr = points.cm.Tr;  // same placement as the points
    updateBoxAndNormals(*layer);
    return {layer, result.report};
}

}  // namespace pcskeleton::meshlab
