// Triangle meshes out (the reconstructed surface): .ply (binary little endian, double
// coordinates, int indices), .off or .obj, by extension; the file appears only once complete.
#pragma once

#include "pcskeleton/reconstruction/iso_surface.h"

#include <string>

namespace pcskeleton {

void writeTriangleMesh(const TriangleMesh& mesh, const std::string& path);

// True for the extensions writeTriangleMesh() understands.
bool isMeshFileName(const std::string& path);

}  // namespace pcskeleton
