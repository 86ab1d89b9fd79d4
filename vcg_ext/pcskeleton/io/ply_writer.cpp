#include "pcskeleton/io/ply_writer.h"

#include "pcskeleton/core/errors.h"

#include <cstdint>
#include <cstdio>

namespace pcskeleton {

void writeBinaryPly(const std::string& path, const PointList& vertices,
                    const std::vector<std::array<int, 3>>* triangles) {
    std::FILE* out = std::fopen(path.c_str(), "wb");
    if (!out) throw InvalidInput("Cannot write '" + path + "': the file cannot be created.");
    std::fprintf(out,
                 "ply\nformat binary_little_endian 1.0\nelement vertex %zu\n"
                 "property double x\nproperty double y\nproperty double z\n",
                 vertices.size());
    if (triangles) std::fprintf(out, "element face %zu\nproperty list uchar int vertex_indices\n", triangles->size());
    std::fprintf(out, "end_header\n");
    bool ok = true;
    for (const Point& p : vertices) ok = ok && std::fwrite(p.data(), sizeof(double), 3, out) == 3;
    if (triangles) {
        const std::uint8_t corners = 3;
        for (const auto& t : *triangles) {
            const std::int32_t indices[3] = {t[0], t[1], t[2]};
            ok = ok && std::fwrite(&corners, 1, 1, out) == 1 && std::fwrite(indices, sizeof(indices), 1, out) == 1;
        }
    }
    ok = std::fclose(out) == 0 && ok;
    if (!ok) throw InvalidInput("Cannot write '" + path + "': writing failed (disk full?).");
}

}  // namespace pcskeleton
