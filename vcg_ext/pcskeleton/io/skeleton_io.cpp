#include "pcskeleton/io/skeleton_io.h"

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_obj.h>
#include <wrap/io_trimesh/import_ply.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace pcskeleton {

namespace {

// A vcglib mesh just rich enough for its importers and the PLY exporter.
class IoVertex;
class IoEdge;
class IoFace;
struct IoTypes : vcg::UsedTypes<vcg::Use<IoVertex>::AsVertexType, vcg::Use<IoEdge>::AsEdgeType,
                                vcg::Use<IoFace>::AsFaceType> {};
class IoVertex : public vcg::Vertex<IoTypes, vcg::vertex::Coord3d, vcg::vertex::Qualityd, vcg::vertex::Radiusf,
                                    vcg::vertex::BitFlags> {};
class IoEdge : public vcg::Edge<IoTypes, vcg::edge::VertexRef, vcg::edge::BitFlags> {};
class IoFace : public vcg::Face<IoTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class IoMesh : public vcg::tri::TriMesh<std::vector<IoVertex>, std::vector<IoEdge>, std::vector<IoFace>> {};

std::string extensionOf(const std::string& path) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw InvalidInput("Cannot read '" + path + "': " + why);
}

std::ifstream openForReading(const std::string& path) {
    std::ifstream in(path);
    if (!in) fail(path, "the file cannot be opened.");
    return in;
}

std::ofstream openForWriting(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw InvalidInput("Cannot write '" + path + "': the file cannot be created.");
    out << std::setprecision(17);
    return out;
}

void finishWriting(std::ofstream& out, const std::string& path) {
    out.close();
    if (!out) throw InvalidInput("Cannot write '" + path + "': writing failed (disk full?).");
}

void loadWithVcg(IoMesh& mesh, const std::string& path, const std::string& ext, int& mask) {
    mask = 0;
    int error = 0;
    std::string message;
    if (ext == "ply") {
        vcg::tri::io::PlyInfo info;
        error = vcg::tri::io::ImporterPLY<IoMesh>::Open(mesh, path.c_str(), info);
        mask = info.mask;
        if (error) message = vcg::tri::io::ImporterPLY<IoMesh>::ErrorMsg(error);
    } else {
        error = vcg::tri::io::ImporterOBJ<IoMesh>::Open(mesh, path.c_str(), mask);
        if (!vcg::tri::io::ImporterOBJ<IoMesh>::ErrorCritical(error)) error = 0;
        if (error) message = vcg::tri::io::ImporterOBJ<IoMesh>::ErrorMsg(error);
    }
    if (error) fail(path, message + ".");
}

void saveWithVcg(IoMesh& mesh, const std::string& path, int mask, bool binary) {
    if (vcg::tri::io::ExporterPLY<IoMesh>::Save(mesh, path.c_str(), mask, binary) != 0) {
        throw InvalidInput("Cannot write '" + path + "': the file cannot be created.");
    }
}

PointList readXyz(const std::string& path) {
    std::ifstream in = openForReading(path);
    PointList points;
    std::string line;
    for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        // strtod, unlike istream, reads "nan" and "inf": the cloud check then names them.
        Point p;
        const char* cursor = line.c_str();
        for (int axis = 0; axis < 3; ++axis) {
            char* end = nullptr;
            p[axis] = std::strtod(cursor, &end);
            if (end == cursor) fail(path, "line " + std::to_string(lineNumber) + " does not start with three numbers.");
            cursor = end;
        }
        points.push_back(p);
    }
    return points;
}

// Only the vertices of an OFF file, read leniently: vcglib's reader rejects the two-count
// headers ("NOFF / 9471 0") of the paper's own files and degenerate faces, which a point
// cloud does not need anyway. Extra values per vertex (normals, colours) are ignored.
PointList readOffVertices(const std::string& path) {
    std::ifstream in = openForReading(path);
    std::string line;
    auto nextLine = [&](std::istringstream& fields) {
        while (std::getline(in, line)) {
            line = line.substr(0, line.find('#'));
            if (line.find_first_not_of(" \t\r") != std::string::npos) {
                fields.clear();
                fields.str(line);
                return true;
            }
        }
        return false;
    };
    std::istringstream fields;
    std::string keyword;
    if (!nextLine(fields) || !(fields >> keyword) || keyword.size() < 3 ||
        keyword.compare(keyword.size() - 3, 3, "OFF") != 0) {
        fail(path, "an OFF file starts with OFF (or NOFF, COFF, ...).");
    }
    if (keyword.find('4') != std::string::npos || keyword.find('n') != std::string::npos) {
        fail(path, "OFF files with other than three dimensions are not supported.");
    }
    long count = -1;
    if (!(fields >> count) && !(nextLine(fields) && fields >> count)) fail(path, "the vertex count is missing.");
    if (count < 0) fail(path, "the vertex count is negative.");
    PointList points;
    points.reserve(std::size_t(count));
    for (long i = 0; i < count; ++i) {
        Point p;
        if (!nextLine(fields) || !(fields >> p.x() >> p.y() >> p.z())) {
            fail(path, "vertex " + std::to_string(i) + " of " + std::to_string(count) + " is missing or incomplete.");
        }
        points.push_back(p);
    }
    return points;
}

void writeSkeletonPly(const SkeletonGraph& skeleton, const std::string& path) {
    IoMesh mesh;
    auto vertex = vcg::tri::Allocator<IoMesh>::AddVertices(mesh, skeleton.nodeCount());
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n, ++vertex) {
        vertex->P() = vcg::Point3d(skeleton.nodes[n].x(), skeleton.nodes[n].y(), skeleton.nodes[n].z());
        vertex->Q() = vertex->R() = float(skeleton.radii.empty() ? 0.0 : skeleton.radii[n]);
    }
    for (const Edge& e : skeleton.edges) vcg::tri::Allocator<IoMesh>::AddEdge(mesh, e[0], e[1]);
    const int mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_VERTQUALITY |
                     vcg::tri::io::Mask::IOM_VERTRADIUS | vcg::tri::io::Mask::IOM_EDGEINDEX;
    saveWithVcg(mesh, path, mask, /*binary=*/false);
}

// .obj (v/l) and .cg (v/e): a header line, the nodes, then 1-based edges.
void writeSkeletonLines(const SkeletonGraph& skeleton, const std::string& path, const std::string& header,
                        char edgeKeyword) {
    std::ofstream out = openForWriting(path);
    out << header << '\n';
    for (const Point& p : skeleton.nodes) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const Edge& e : skeleton.edges) out << edgeKeyword << ' ' << e[0] + 1 << ' ' << e[1] + 1 << '\n';
    finishWriting(out, path);
}

SkeletonGraph readSkeletonPly(const std::string& path) {
    IoMesh mesh;
    int mask = 0;
    loadWithVcg(mesh, path, "ply", mask);
    SkeletonGraph skeleton;
    const bool hasRadius = mask & vcg::tri::io::Mask::IOM_VERTRADIUS;
    const bool hasQuality = mask & vcg::tri::io::Mask::IOM_VERTQUALITY;
    for (const IoVertex& v : mesh.vert) {
        skeleton.nodes.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
        skeleton.radii.push_back(hasRadius ? v.cR() : hasQuality ? v.cQ() : 0.0);
    }
    for (const IoEdge& e : mesh.edge) {
        skeleton.edges.push_back({int(vcg::tri::Index(mesh, e.cV(0))), int(vcg::tri::Index(mesh, e.cV(1)))});
    }
    return skeleton;
}

// .obj (v/l) and .cg (v/e) are line formats with 1-based edge lists.
SkeletonGraph readSkeletonLines(const std::string& path, const std::string& edgeKeyword) {
    std::ifstream in = openForReading(path);
    SkeletonGraph skeleton;
    std::vector<std::vector<long>> polylines;
    std::string line, keyword;
    for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
        std::istringstream fields(line);
        if (!(fields >> keyword)) continue;
        const std::string where = "line " + std::to_string(lineNumber);
        if (keyword == "v") {
            Point p;
            if (!(fields >> p.x() >> p.y() >> p.z())) fail(path, where + ": a vertex needs three coordinates.");
            double radius = 0.0;
            fields >> radius;
            skeleton.nodes.push_back(p);
            skeleton.radii.push_back(std::isfinite(radius) ? radius : 0.0);
        } else if (keyword == edgeKeyword) {
            std::vector<long> ids;
            std::string token;
            while (fields >> token) ids.push_back(std::atol(token.c_str()));  // "12/5" reads as 12
            if (ids.size() < 2) fail(path, where + ": a line element needs two vertices.");
            polylines.push_back(ids);
        }
    }
    const long n = long(skeleton.nodes.size());
    for (const auto& ids : polylines) {
        for (std::size_t k = 0; k + 1 < ids.size(); ++k) {
            long a = ids[k], b = ids[k + 1];
            if (a < 0) a += n + 1;  // OBJ's relative indices
            if (b < 0) b += n + 1;
            if (a < 1 || b < 1 || a > n || b > n) fail(path, "an edge refers to a vertex that does not exist.");
            skeleton.edges.push_back({int(a - 1), int(b - 1)});
        }
    }
    return skeleton;
}

}  // namespace

PointList readPointCloud(const std::string& path) {
    const std::string ext = extensionOf(path);
    if (ext == "xyz" || ext == "txt" || ext == "pts") return readXyz(path);
    if (ext == "off") return readOffVertices(path);
    if (ext != "ply" && ext != "obj") {
        fail(path, "unknown extension; use .ply, .off, .obj, .xyz, .txt or .pts.");
    }
    openForReading(path);
    IoMesh mesh;
    int mask = 0;
    loadWithVcg(mesh, path, ext, mask);
    PointList points;
    points.reserve(mesh.vert.size());
    for (const IoVertex& v : mesh.vert) points.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
    return points;
}

void writePointCloud(const PointList& points, const std::string& path) {
    const std::string ext = extensionOf(path);
    if (ext == "xyz") {
        std::ofstream out = openForWriting(path);
        for (const Point& p : points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
        finishWriting(out, path);
        return;
    }
    if (ext != "ply") throw InvalidInput("Cannot write '" + path + "': point sets are written as .ply or .xyz.");
    IoMesh mesh;
    auto vertex = vcg::tri::Allocator<IoMesh>::AddVertices(mesh, points.size());
    for (const Point& p : points) (vertex++)->P() = vcg::Point3d(p.x(), p.y(), p.z());
    saveWithVcg(mesh, path, vcg::tri::io::Mask::IOM_VERTCOORD, /*binary=*/true);
}

bool isSkeletonFileName(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == "ply" || ext == "obj" || ext == "cg";
}

void writeSkeleton(const SkeletonGraph& skeleton, const std::string& path) {
    const std::string ext = extensionOf(path);
    if (ext == "ply") return writeSkeletonPly(skeleton, path);
    const std::string nodes = std::to_string(skeleton.nodeCount()), edges = std::to_string(skeleton.edgeCount());
    if (ext == "obj") {
        return writeSkeletonLines(skeleton, path, "# curve skeleton: " + nodes + " nodes, " + edges + " edges", 'l');
    }
    if (ext == "cg") return writeSkeletonLines(skeleton, path, "# D:3 NV:" + nodes + " NE:" + edges, 'e');
    throw InvalidInput("Cannot write '" + path + "': skeletons are written as .ply, .obj or .cg.");
}

SkeletonGraph readSkeleton(const std::string& path) {
    const std::string ext = extensionOf(path);
    SkeletonGraph skeleton;
    if (ext == "ply") {
        skeleton = readSkeletonPly(path);
    } else if (ext == "obj" || ext == "cg") {
        skeleton = readSkeletonLines(path, ext == "obj" ? "l" : "e");
    } else {
        fail(path, "skeletons are read from .ply, .obj or .cg files.");
    }
    normalizeEdges(skeleton.edges);
    return skeleton;
}

}  // namespace pcskeleton
