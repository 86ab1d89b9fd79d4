// Skeleton files, in the formats other tools read. Readers check everything they use (see
// input_file.h and ply_reader.h) and throw InvalidInput naming the line or byte offset;
// writers replace a file only once the new one is complete.
//
// Skeletons:  .ply  vertex x y z quality radius (quality = radius) + element edge (vertex1
//                   vertex2 inferred, 1 for a bone the data does not show); MeshLab reads
//                   it back with its edges, the radius in vertex quality.
//             .obj  v x y z lines and l a b lines (1-based).
//             .cg   the Starlab curve-skeleton format ("# D:3 NV:n NE:m", v x y z, e a b
//                   1-based) used by skeleton benchmarks; it keeps cycles (SWC cannot)
//                   but no radius; read back with radius 0 unless a v line has a 4th value.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <string>

namespace pcskeleton {

SkeletonGraph readSkeleton(const std::string& path);
void writeSkeleton(const SkeletonGraph& skeleton, const std::string& path);

// True for the extensions writeSkeleton() understands.
bool isSkeletonFileName(const std::string& path);

}  // namespace pcskeleton
