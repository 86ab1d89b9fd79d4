// The binary PLY files the library writes: vertices as doubles, and, for a surface, its
// triangles (list uchar int). Shared by point_cloud_io (contracted points) and mesh_io
// (reconstructed surfaces). Throws InvalidInput when the file cannot be written.
#pragma once

#include "pcskeleton/core/point.h"

#include <array>
#include <string>
#include <vector>

namespace pcskeleton {

// triangles == nullptr writes a point set (no face element).
void writeBinaryPly(const std::string& path, const PointList& vertices,
                    const std::vector<std::array<int, 3>>* triangles = nullptr);

}  // namespace pcskeleton
