// Section V's promise kept: the reconstructed solid has the skeleton's topology, one
// component per skeleton component and one handle per independent cycle, whatever noise
// or missing data make the fitted field do.
//
// The inside {u < 0} is grown again from the skeleton, one grid node at a time, the most
// negative first, and a node is taken only if it is a simple point of the region grown so
// far: adding it changes neither the number of components, nor of tunnels, nor of
// cavities (digital topology, the inside 6-connected and the outside 26-connected). The
// skeleton's bones, drawn into the grid as 6-connected chains of nodes, are the seed; a
// loop that a bone's chain cannot close where bones crowd (it would close two at once) is
// closed, once the region has grown, at the inside node near that bone that closes
// exactly one.
// Inside nodes never taken (a handle or a bridge the skeleton does not have, an island
// away from it) are set just outside. Elsewhere the field is left as it was, so where the
// data and the skeleton agree the surface does not move.
//
// Marching cubes then has to read the region with the same connectivity: where two inside
// nodes of a cell touch only diagonally, the values there are nudged (without changing a
// sign) so that its ambiguity tests separate them, as 6-connectivity does.
#pragma once

#include "pcskeleton/reconstruction/field_grid.h"
#include "pcskeleton/skeleton/skeleton_graph.h"

#include <cstddef>
#include <vector>

namespace pcskeleton {

struct TopologyControl {
    std::size_t insideNodes = 0;   // u < 0 before
    std::size_t removedNodes = 0;  // of those, set outside: unsupported handles, bridges, islands
    std::size_t seedNodes = 0;     // grid nodes on the skeleton's bones
    // The largest group of removed nodes (26-connected): where the data disagrees most with
    // the skeleton, in the grid's frame; empty when nothing was removed.
    std::size_t largestRemoval = 0;
    Point largestRemovalCentre = Point::Zero();
};

// `skeleton` is in the grid's frame; `values` are the field at the grid's nodes (negative
// inside), with the grid's boundary already outside. Changes `values` in place.
TopologyControl constrainToSkeletonTopology(const FieldGrid& grid, const SkeletonGraph& skeleton,
                                            std::vector<double>& values);

}  // namespace pcskeleton
