#include "pcskeleton/io/mesh_io.h"

#include "pcskeleton/io/input_file.h"
#include "pcskeleton/io/ply_writer.h"

#include <ostream>

namespace pcskeleton {

namespace {

// OFF and OBJ: text, vertices then triangles (OBJ's indices are 1-based).
void writeText(const TriangleMesh& mesh, const std::string& path, bool obj) {
    writeTextFile(path, [&](std::ostream& out) {
        if (!obj) out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
        for (const Point& p : mesh.vertices) out << (obj ? "v " : "") << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
        for (const auto& t : mesh.triangles) {
            if (obj) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
            else out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
        }
    });
}

}  // namespace

bool isMeshFileName(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == "ply" || ext == "off" || ext == "obj";
}

void writeTriangleMesh(const TriangleMesh& mesh, const std::string& path) {
    if (!isMeshFileName(path)) throw InvalidInput("Cannot write '" + path + "': surfaces are written as .ply, .off or .obj.");
    const std::string ext = extensionOf(path);
    writeFileAtomically(path, [&](const std::string& temporary) {
        if (ext == "ply") writeBinaryPly(temporary, mesh.vertices, &mesh.triangles);
        else writeText(mesh, temporary, ext == "obj");
    });
}

}  // namespace pcskeleton
