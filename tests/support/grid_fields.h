// Fields sampled on a cubic FieldGrid, for the tests of the reconstruction's grid steps
// (marching cubes, topology control).
#pragma once

#include <pcskeleton/reconstruction/field_grid.h>

#include <functional>
#include <vector>

namespace pcskeleton::shapes {

// A grid of `cells` cells per side over [-halfSide, halfSide]^3.
inline FieldGrid cubeGrid(int cells, double halfSide) {
    FieldGrid grid;
    grid.origin = Point::Constant(-halfSide);
    grid.spacing = 2 * halfSide / cells;
    grid.nodes = {cells + 1, cells + 1, cells + 1};
    return grid;
}

// `field` at every node of `grid`.
inline std::vector<double> sampleField(const FieldGrid& grid, const std::function<double(const Point&)>& field) {
    std::vector<double> values(grid.size());
    for (int k = 0; k < grid.nodes[2]; ++k)
        for (int j = 0; j < grid.nodes[1]; ++j)
            for (int i = 0; i < grid.nodes[0]; ++i) values[grid.index(i, j, k)] = field(grid.position(i, j, k));
    return values;
}

}  // namespace pcskeleton::shapes
