// The zero level set of a grid field as a triangle mesh (vcglib's marching cubes), and
// the topology numbers that say whether a reconstruction is what the skeleton asked for.
#pragma once

#include "pcskeleton/reconstruction/field_grid.h"

#include <array>
#include <string>
#include <vector>

namespace pcskeleton {

struct TriangleMesh {
    PointList vertices;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

// Marching cubes with vcglib's topologically consistent case table, then cleaned: no
// duplicate vertex, no degenerate, zero-area or duplicate triangle, no unused vertex.
// Negative values are inside. Boundary nodes must be positive for the result to be
// closed (the caller decides how to make them so). Values within a thousandth of a cell
// of zero are pushed off it, so that no triangle collapses onto a grid node.
TriangleMesh extractZeroLevelSet(const FieldGrid& grid, const std::vector<double>& values);

struct SurfaceTopology {
    int vertices = 0, edges = 0, triangles = 0;
    int components = 0;
    int boundaryEdges = 0;     // edges with one triangle
    int nonManifoldEdges = 0;  // edges with three or more
    int genus = 0;             // summed over components (meaningful when closed)
    bool closedManifold() const { return boundaryEdges == 0 && nonManifoldEdges == 0 && triangles > 0; }
};
SurfaceTopology analyseSurface(const TriangleMesh& mesh);
// "1 component, genus 1, closed 2-manifold, 5120 triangles"
std::string describe(const SurfaceTopology& topology);

}  // namespace pcskeleton
