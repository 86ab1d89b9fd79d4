// The regular grid of nodes on which Section V's scalar field lives.
#pragma once

#include "pcskeleton/contraction/point_cloud_input.h"

#include <array>
#include <cstddef>

namespace pcskeleton {

struct FieldGrid {
    Point origin = Point::Zero();  // position of node (0, 0, 0)
    double spacing = 1.0;          // distance between neighbouring nodes
    std::array<int, 3> nodes{1, 1, 1};

    std::size_t size() const { return std::size_t(nodes[0]) * nodes[1] * nodes[2]; }
    std::size_t index(int i, int j, int k) const { return std::size_t(i) + std::size_t(nodes[0]) * (j + std::size_t(nodes[1]) * k); }
    // The (i, j, k) of index n: the inverse of index().
    std::array<int, 3> coordinates(std::size_t n) const {
        return {int(n % nodes[0]), int(n / nodes[0] % nodes[1]), int(n / (std::size_t(nodes[0]) * nodes[1]))};
    }
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

}  // namespace pcskeleton
