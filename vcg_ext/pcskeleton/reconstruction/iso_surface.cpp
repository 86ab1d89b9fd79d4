#include "pcskeleton/reconstruction/iso_surface.h"

#include "pcskeleton/internal/counted.h"

#include <vcg/complex/complex.h>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/create/marching_cubes.h>
#include <vcg/complex/algorithms/create/mc_trivial_walker.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <Eigen/Geometry>

#include <cmath>
#include <type_traits>

namespace pcskeleton {

namespace {
class IsoVertex;
class IsoFace;
struct IsoTypes : public vcg::UsedTypes<vcg::Use<IsoVertex>::AsVertexType, vcg::Use<IsoFace>::AsFaceType> {};
class IsoVertex : public vcg::Vertex<IsoTypes, vcg::vertex::Coord3f, vcg::vertex::BitFlags, vcg::vertex::Mark> {};
class IsoFace
    : public vcg::Face<IsoTypes, vcg::face::VertexRef, vcg::face::FFAdj, vcg::face::BitFlags, vcg::face::Mark> {};
class IsoMesh : public vcg::tri::TriMesh<std::vector<IsoVertex>, std::vector<IsoFace>> {};

using Volume = vcg::SimpleVolume<vcg::SimpleVoxel<float>>;
// The vcglib of MeshLab 2020.09 allocates the walker's slice caches with new[] and never
// frees them (50-66 KB per surface under LeakSanitizer); they are protected members, freed
// here. Later vcglib (MeshLab 2022.02 on) keeps them in std::vectors: nothing to free.
template <typename SliceCache>
void freeSliceCache(SliceCache& cache) {
    if constexpr (std::is_pointer_v<SliceCache>) delete[] cache;
}

class Walker : public vcg::tri::TrivialWalker<IsoMesh, Volume> {
public:
    Walker() = default;
    Walker(const Walker&) = delete;
    Walker& operator=(const Walker&) = delete;
    ~Walker() {
        if (_slice_dimension == 0) return;
        for (auto* cache : {&_x_cs, &_y_cs, &_z_cs, &_x_ns, &_z_ns}) freeSliceCache(*cache);
    }
};
using Extractor = vcg::tri::MarchingCubes<IsoMesh, Walker>;
using Clean = vcg::tri::Clean<IsoMesh>;

void toVcg(const TriangleMesh& mesh, IsoMesh& m) {
    auto vertex = vcg::tri::Allocator<IsoMesh>::AddVertices(m, mesh.vertices.size());
    for (const Point& p : mesh.vertices) (vertex++)->P() = vcg::Point3f(float(p.x()), float(p.y()), float(p.z()));
    auto face = vcg::tri::Allocator<IsoMesh>::AddFaces(m, mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        for (int c = 0; c < 3; ++c) face->V(c) = &m.vert[t[c]];
        ++face;
    }
}

double signedVolume(const TriangleMesh& mesh) {
    double volume = 0;
    for (const auto& t : mesh.triangles)
        volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
    return volume / 6;
}
}  // namespace

TriangleMesh extractZeroLevelSet(const FieldGrid& grid, const std::vector<double>& values) {
    if (values.size() != grid.size()) throw CallerError("extractZeroLevelSet: the field must give one value per grid node.");
    // vcglib's walker leaves out the last layer of cells: one more layer of nodes, outside.
    const vcg::Point3i size(grid.nodes[0] + 1, grid.nodes[1] + 1, grid.nodes[2] + 1);
    Volume volume;
    volume.Init(size, vcg::Box3f(vcg::Point3f(0, 0, 0), vcg::Point3f(float(size[0]), float(size[1]), float(size[2]))));
    const double offZero = 1e-3 * grid.spacing;
    for (int k = 0; k < size[2]; ++k)
        for (int j = 0; j < size[1]; ++j)
            for (int i = 0; i < size[0]; ++i) {
                const bool inside = i < grid.nodes[0] && j < grid.nodes[1] && k < grid.nodes[2];
                double v = inside ? values[grid.index(i, j, k)] : grid.spacing;
                if (std::abs(v) < offZero) v = v < 0 ? -offZero : offZero;
                volume.Val(i, j, k) = float(v);
            }

    IsoMesh m;
    Walker walker;
    Extractor extractor(m, walker);
    walker.BuildMesh<Extractor>(m, volume, extractor, 0.0f);

    Clean::RemoveDuplicateVertex(m);
    Clean::RemoveDegenerateFace(m);
    Clean::RemoveZeroAreaFace(m);
    Clean::RemoveDuplicateFace(m);
    Clean::RemoveUnreferencedVertex(m);
    vcg::tri::Allocator<IsoMesh>::CompactEveryVector(m);

    TriangleMesh result;
    result.vertices.reserve(m.vert.size());
    for (const IsoVertex& v : m.vert) result.vertices.push_back(grid.origin + grid.spacing * Point(v.cP()[0], v.cP()[1], v.cP()[2]));
    result.triangles.reserve(m.face.size());
    for (const IsoFace& f : m.face)
        result.triangles.push_back({int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))),
                                    int(vcg::tri::Index(m, f.cV(2)))});
    // Outward normals whatever vcglib's table orientation: inside is where the field is negative.
    if (signedVolume(result) < 0)
        for (auto& t : result.triangles) std::swap(t[1], t[2]);
    return result;
}

SurfaceTopology analyseSurface(const TriangleMesh& mesh) {
    IsoMesh m;
    toVcg(mesh, m);
    vcg::tri::UpdateTopology<IsoMesh>::FaceFace(m);
    SurfaceTopology topology;
    topology.vertices = m.vn;
    topology.triangles = m.fn;
    Clean::CountEdgeNum(m, topology.edges, topology.boundaryEdges, topology.nonManifoldEdges);
    topology.components = Clean::CountConnectedComponents(m);
    if (topology.nonManifoldEdges == 0) topology.genus = Clean::MeshGenus(m);
    return topology;
}

std::string describe(const SurfaceTopology& t) {
    std::string text = counted(std::size_t(t.components), "component") + ", genus " + std::to_string(t.genus) + ", ";
    if (t.closedManifold())
        text += "closed 2-manifold";
    else
        text += std::to_string(t.boundaryEdges) + " boundary edges, " + std::to_string(t.nonManifoldEdges) +
                " non-manifold edges";
    return text + ", " + std::to_string(t.triangles) + " triangles";
}

}  // namespace pcskeleton
