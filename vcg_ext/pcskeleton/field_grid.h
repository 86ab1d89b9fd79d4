// The regular grid of nodes on which Section V's scalar field lives, and trilinear
// interpolation on it (how a point constraint sees the field).
#pragma once

#include "pcskeleton/point_cloud_input.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace pcskeleton {

struct FieldGrid {
    Point origin = Point::Zero();  // position of node (0, 0, 0)
    double spacing = 1.0;          // distance between neighbouring nodes
    std::array<int, 3> nodes{1, 1, 1};

    std::size_t size() const { return std::size_t(nodes[0]) * nodes[1] * nodes[2]; }
    std::size_t index(int i, int j, int k) const { return std::size_t(i) + std::size_t(nodes[0]) * (j + std::size_t(nodes[1]) * k); }
    Point position(int i, int j, int k) const { return origin + spacing * Point(i, j, k); }
    bool isBoundary(int i, int j, int k) const {
        return i == 0 || j == 0 || k == 0 || i == nodes[0] - 1 || j == nodes[1] - 1 || k == nodes[2] - 1;
    }
    // Every other node, twice the spacing; needs an even number of cells on each axis.
    bool canCoarsen() const {
        for (int n : nodes)
            if ((n - 1) % 2 != 0 || n < 5) return false;
        return true;
    }
    FieldGrid coarser() const {
        FieldGrid result{origin, 2 * spacing, {(nodes[0] - 1) / 2 + 1, (nodes[1] - 1) / 2 + 1, (nodes[2] - 1) / 2 + 1}};
        return result;
    }
};

// The eight nodes of the cell holding a point and their trilinear weights (summing to 1).
// Points outside the grid are clamped to its boundary cells.
struct TrilinearStencil {
    std::array<std::size_t, 8> node{};
    std::array<double, 8> weight{};
};

inline TrilinearStencil trilinearStencil(const FieldGrid& grid, const Point& p) {
    std::array<int, 3> cell{};
    std::array<double, 3> fraction{};
    for (int axis = 0; axis < 3; ++axis) {
        const double t = (p[axis] - grid.origin[axis]) / grid.spacing;
        const int lastCell = grid.nodes[axis] - 2;
        cell[axis] = std::min(std::max(int(std::floor(t)), 0), lastCell);
        fraction[axis] = std::min(std::max(t - cell[axis], 0.0), 1.0);
    }
    TrilinearStencil stencil;
    for (int corner = 0; corner < 8; ++corner) {
        const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
        stencil.node[corner] = grid.index(cell[0] + di, cell[1] + dj, cell[2] + dk);
        stencil.weight[corner] = (di ? fraction[0] : 1 - fraction[0]) * (dj ? fraction[1] : 1 - fraction[1]) *
                                 (dk ? fraction[2] : 1 - fraction[2]);
    }
    return stencil;
}

}  // namespace pcskeleton
