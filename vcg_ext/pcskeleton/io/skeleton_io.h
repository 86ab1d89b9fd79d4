// Files in and out: point sets for the command-line tool, skeletons in the formats
// other tools read. Errors are thrown as InvalidInput with a sentence for the user.
//
// Point sets: .ply (ascii or binary), .off (also NOFF/COFF), .obj (faces ignored),
//             .xyz/.txt/.pts (one point per line, first three numbers; more are ignored).
// Skeletons:  .ply  vertex x y z radius quality(= radius) + element edge (vertex1 vertex2);
//                   MeshLab reads it back with its edges, the radius in vertex quality.
//             .obj  v x y z lines and l a b lines (1-based).
//             .cg   the Starlab curve-skeleton format ("# D:3 NV:n NE:m", v x y z, e a b
//                   1-based) used by skeleton benchmarks; it keeps cycles (SWC cannot)
//                   but no radius; read back with radius 0 unless a v line has a 4th value.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <string>

namespace pcskeleton {

PointList readPointCloud(const std::string& path);
// .ply (binary) or .xyz, by extension.
void writePointCloud(const PointList& points, const std::string& path);

SkeletonGraph readSkeleton(const std::string& path);
void writeSkeleton(const SkeletonGraph& skeleton, const std::string& path);

// True for the extensions writeSkeleton() understands.
bool isSkeletonFileName(const std::string& path);

}  // namespace pcskeleton
