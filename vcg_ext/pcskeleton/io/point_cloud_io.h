// Point sets in and out, for the command-line tool, the benchmarks and the tests. Every
// reader streams the file through InputFile and checks it as it goes: a malformed file
// is refused with InvalidInput naming the line or byte offset, never trusted.
//
// Read:  .ply (ascii, binary little or big endian, any scalar types; only the vertex
//        element's x y z are used, faces and other elements are not read),
//        .off (also NOFF/COFF and the two-count headers of the paper's files; vertices only),
//        .obj (v lines only; faces, normals and materials are ignored, no other file opened),
//        .xyz/.txt/.pts (one point per line: the first three numbers; more are ignored).
// Write: .ply (binary little endian, double) or .xyz, replacing the file only once complete.
#pragma once

#include "pcskeleton/core/point.h"

#include <string>

namespace pcskeleton {

PointList readPointCloud(const std::string& path);
void writePointCloud(const PointList& points, const std::string& path);

// True for the extensions readPointCloud() understands.
bool isPointCloudFileName(const std::string& path);

}  // namespace pcskeleton
