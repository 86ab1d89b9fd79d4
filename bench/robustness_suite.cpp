#include "robustness_suite.h"

#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <set>

namespace pcskeleton::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using FaceTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

struct Tube {
    shapes::Polyline curve;
    double radius;
};

// A sheet of a shape and, where it has one, its mid-line (its curve skeleton).
struct Sheet {
    shapes::Triangles triangles;
    shapes::Polyline midLine;
};

bool insideTube(const Tube& tube, const Point& p) { return shapes::distanceToCurve(p, tube.curve) < tube.radius; }

// Ends of a tube's curve (segment ends used once) that are not inside another tube, pushed
// out by the radius: the points where the shape ends.
PointList tubeEnds(const std::vector<Tube>& tubes) {
    PointList ends;
    for (std::size_t t = 0; t < tubes.size(); ++t) {
        std::map<std::array<long long, 3>, int> uses;
        // Rounded, so that the ends of segments meeting at a point computed twice match.
        auto key = [](const Point& p) {
            return std::array<long long, 3>{std::llround(p.x() * 1e9), std::llround(p.y() * 1e9), std::llround(p.z() * 1e9)};
        };
        for (const shapes::Segment& s : tubes[t].curve) ++uses[key(s.a)], ++uses[key(s.b)];
        for (const shapes::Segment& s : tubes[t].curve) {
            for (const auto& [end, other] : {std::pair{s.a, s.b}, std::pair{s.b, s.a}}) {
                if (uses[key(end)] != 1) continue;
                bool covered = false;
                for (std::size_t u = 0; u < tubes.size(); ++u) covered |= u != t && insideTube(tubes[u], end);
                // A curve that comes back onto itself (a curl) ends inside its own tube.
                for (const shapes::Segment& segment : tubes[t].curve) {
                    covered |= &segment != &s && shapes::distanceToSegment(end, segment.a, segment.b) < tubes[t].radius;
                }
                if (!covered) ends.push_back(end + tubes[t].radius * (end - other).normalized());
            }
        }
    }
    return ends;
}

// Tubes and sheets, sampled uniformly by area; the points of a sheet inside a tube (a leaf's
// base in its stem) are dropped. With a sheet the shape has no inside, and a centre curve
// only when every sheet has a mid-line.
Subject shapeSubject(const std::string& name, bool heldOut, const std::vector<Tube>& tubes,
                     const std::vector<Sheet>& sheets, int cycles, int tips, int components = 1) {
    Subject s;
    s.name = name;
    s.heldOut = heldOut;
    s.components = components;
    s.cycles = cycles;
    s.tips = tips;
    for (const Tube& t : tubes) {
        for (const shapes::Segment& segment : t.curve) s.area += 2.0 * M_PI * t.radius * (segment.b - segment.a).norm();
    }
    for (const Sheet& sheet : sheets) s.area += shapes::area(sheet.triangles);
    s.sample = [tubes, sheets, area = s.area](std::size_t n, std::uint32_t seed) {
        PointList points;
        for (std::size_t k = 0; k < sheets.size(); ++k) {
            const auto count = std::size_t(n * shapes::area(sheets[k].triangles) / area);
            for (const Point& p : shapes::sample(sheets[k].triangles, count, seed + 31 * k + 7)) {
                bool covered = false;
                for (const Tube& t : tubes) covered |= insideTube(t, p);
                if (!covered) points.push_back(p);
            }
        }
        for (std::size_t t = 0; t < tubes.size(); ++t) {
            double length = 0.0;
            for (const shapes::Segment& segment : tubes[t].curve) length += (segment.b - segment.a).norm();
            const auto count = std::size_t(n * 2.0 * M_PI * tubes[t].radius * length / area);
            for (const Point& p : shapes::tube(tubes[t].curve, tubes[t].radius, count, seed + 17 * t)) {
                bool covered = false;
                for (std::size_t u = 0; u < tubes.size(); ++u) covered |= u != t && insideTube(tubes[u], p);
                if (!covered) points.push_back(p);
            }
        }
        return points;
    };
    if (sheets.empty()) {
        s.inside = [tubes](const Point& p) {
            for (const Tube& t : tubes) {
                if (insideTube(t, p)) return true;
            }
            return false;
        };
    }
    const bool midLines = std::all_of(sheets.begin(), sheets.end(), [](const Sheet& k) { return !k.midLine.empty(); });
    if (midLines) {
        s.centreDistance = [tubes, sheets](const Point& p) {
            double d = std::numeric_limits<double>::infinity();
            for (const Tube& t : tubes) d = std::min(d, shapes::distanceToCurve(p, t.curve));
            for (const Sheet& k : sheets) d = std::min(d, shapes::distanceToCurve(p, k.midLine));
            return d;
        };
    }
    if (!sheets.empty()) {
        s.ends = tubeEnds(tubes);
        return s;
    }
    // Outside the union of tubes the nearest tube's wall is the nearest surface; inside, the
    // nearest wall (exact except near junctions, where tubes overlap).
    s.surfaceDistance = [tubes](const Point& p) {
        double outside = std::numeric_limits<double>::infinity(), inside = 0.0;
        for (const Tube& t : tubes) {
            const double d = shapes::distanceToCurve(p, t.curve) - t.radius;
            outside = std::min(outside, d);
            inside = std::max(inside, -d);
        }
        return outside > 0 ? outside : inside;
    };
    s.ends = tubeEnds(tubes);
    return s;
}

Subject tubeSubject(const std::string& name, bool heldOut, const std::vector<Tube>& tubes, int cycles, int tips,
                    int components = 1) {
    return shapeSubject(name, heldOut, tubes, {}, cycles, tips, components);
}

// A leaf-like ribbon along `centre` (u in [0, 1] to a point), `width` wide at its widest
// across the direction `across`, tapering to both ends and troughed upwards by `trough`
// times its half width at its edges: a sheet whose mid-line is the centre curve.
Sheet ribbon(const std::function<Point(double)>& centre, const Point& across, double width, double trough) {
    const auto halfWidth = [width](double u) { return 0.5 * width * std::sin(M_PI * (0.04 + 0.92 * u)); };
    Sheet sheet;
    sheet.triangles = shapes::sheet(
        [&](double u, double v) {
            const double w = (2 * v - 1) * halfWidth(u);
            return Point(centre(u) + w * across + Point(0, 0, trough * w * w / (0.5 * width)));
        },
        48, 8);
    for (int i = 0; i < 48; ++i) sheet.midLine.push_back({centre(i / 48.0), centre((i + 1) / 48.0)});
    return sheet;
}

// The shapes added for sheets, plants, mechanical parts, big trees, figures and tunnels.
std::vector<Subject> sheetAndMixedShapes() {
    using shapes::Polyline;
    std::vector<Subject> subjects;
    // A bent, troughed leaf blade 1.6 long and 0.3 wide.
    subjects.push_back(shapeSubject(
        "ribbon leaf", false, {},
        {ribbon([](double u) { return Point(1.6 * u, 0, 0.35 * std::sin(M_PI * u)); }, Point(0, 1, 0), 0.3, 0.15)}, 0,
        2));
    // A flat disc: no curve skeleton to speak of, one part without loops.
    subjects.push_back(shapeSubject(
        "disc", true, {},
        {{shapes::sheet([](double u, double v) {
              return Point(0.8 * u * std::cos(2 * M_PI * v), 0.8 * u * std::sin(2 * M_PI * v), 0);
          }, 24, 96),
          {}}},
        0, kUnknown));
    // A square plate with two round holes: a loop around each.
    subjects.push_back(shapeSubject(
        "plate with two holes", false, {},
        {{shapes::sheet([](double u, double v) { return Point(1.6 * u, 1.6 * v, 0); }, 64, 64,
                        [](double u, double v) {
                            return std::hypot(u - 0.28, v - 0.5) > 0.16 && std::hypot(u - 0.72, v - 0.5) > 0.16;
                        }),
          {}}},
        2, kUnknown));
    // A plant: a stem with six leaves arching out and drooping, turning around it.
    {
        std::vector<Sheet> leaves;
        for (int k = 0; k < 6; ++k) {
            const double height = 0.35 + 0.2 * k, azimuth = k * M_PI + 0.5 * k;
            const Point out(std::cos(azimuth), std::sin(azimuth), 0), side(-std::sin(azimuth), std::cos(azimuth), 0);
            leaves.push_back(ribbon(
                [=](double u) { return Point(Point(0, 0, height) + 0.6 * u * out + Point(0, 0, 0.25 * u - 0.35 * u * u)); },
                side, 0.12, 0.1));
        }
        subjects.push_back(
            shapeSubject("plant", true, {{Polyline{{Point(0, 0, 0), Point(0, 0, 1.6)}}, 0.035}}, leaves, 0, 8));
    }
    // A bracket: two plates at right angles sharing an edge, two bolt holes in each.
    {
        const auto holes = [](double u, double v) {
            return std::hypot((u - 0.25) * 1.2, (v - 0.55) * 0.8) > 0.12 &&
                   std::hypot((u - 0.75) * 1.2, (v - 0.55) * 0.8) > 0.12;
        };
        subjects.push_back(shapeSubject(
            "bracket", true, {},
            {{shapes::sheet([](double u, double v) { return Point(1.2 * u, 0.8 * v, 0); }, 60, 40, holes), {}},
             {shapes::sheet([](double u, double v) { return Point(1.2 * u, 0, 0.8 * v); }, 60, 40, holes), {}}},
            4, kUnknown));
    }
    // A tree: a trunk and three levels of three branches each, radius 0.1 down to 0.01.
    {
        std::vector<Tube> branches;
        std::function<void(const Point&, const Point&, double, double, int)> grow =
            [&](const Point& from, const Point& direction, double length, double radius, int level) {
                const Point to = from + length * direction;
                branches.push_back({{{from, to}}, radius});
                if (level == 3) return;
                const Point u = direction.unitOrthogonal(), v = direction.cross(u);
                for (int child = 0; child < 3; ++child) {
                    const double azimuth = 2 * M_PI * child / 3 + 0.6 * level, tilt = 0.6;
                    const Point d = (std::cos(tilt) * direction +
                                     std::sin(tilt) * (std::cos(azimuth) * u + std::sin(azimuth) * v))
                                        .normalized();
                    grow(to, d, 0.55 * length, 0.465 * radius, level + 1);
                }
            };
        grow(Point(0, 0, 0), Point(0, 0, 1), 0.7, 0.1, 0);
        subjects.push_back(tubeSubject("big tree", false, branches, 0, 28));
    }
    // A figure whose arms hang close to its body and whose legs are close to each other.
    {
        std::vector<Tube> figure{{{{Point(0, 0, 0.6), Point(0, 0, 1.35)}}, 0.2},
                                 {{{Point(0, 0, 1.35), Point(0, 0, 1.6)}}, 0.1}};
        for (double side : {-1.0, 1.0}) {
            figure.push_back({{{Point(0.2 * side, 0, 1.3), Point(0.31 * side, 0, 1.3)},
                               {Point(0.31 * side, 0, 1.3), Point(0.31 * side, 0, 0.75)}},
                              0.05});
            figure.push_back({{{Point(0.1 * side, 0, 0.6), Point(0.1 * side, 0, 0.0)}}, 0.07});
        }
        subjects.push_back(tubeSubject("figure, arms close", true, figure, 0, 5));
    }
    // A tube curled back onto itself, leaving a small tunnel (0.14 by 0.2).
    subjects.push_back(tubeSubject("curled tube", false,
                                   {{{{Point(0, 0, 0), Point(1, 0, 0)},
                                      {Point(1, 0, 0), Point(1, 0, 0.36)},
                                      {Point(1, 0, 0.36), Point(0.7, 0, 0.36)},
                                      {Point(0.7, 0, 0.36), Point(0.7, 0, 0)}},
                                     0.08}},
                                   1, 1));
    // A ring so thick that its hole (0.28 across) is narrower than half its tube (0.72
    // across): as contraction flattens it, its inner wall moves into the hole, and the hole
    // is lost (docs/benchmarks.md, "A thick ring loses its hole").
    subjects.push_back(tubeSubject("thick ring", false, {{shapes::circle(Point::Zero(), 0.5), 0.36}}, 1, 0));
    return subjects;
}

std::vector<Subject> knownShapes() {
    using shapes::Polyline;
    std::vector<Subject> subjects;
    subjects.push_back(tubeSubject("straight tube", false, {{Polyline{{Point(0, 0, 0), Point(0, 0, 1.6)}}, 0.1}}, 0, 2));
    Polyline y;
    for (int arm = 0; arm < 3; ++arm) {
        const double a = 2.0 * M_PI * arm / 3.0;
        y.push_back({Point(0, 0, 0), Point(0.8 * std::cos(a), 0.8 * std::sin(a), 0)});
    }
    subjects.push_back(tubeSubject("Y branch", true, {{y, 0.08}}, 0, 3));
    const Point fork(0, 0, 0.8), left(-0.4, 0, 1.3), right(0.4, 0, 1.3);
    const Polyline tree{{Point(0, 0, 0), fork},       {fork, left},
                        {fork, right},                {left, Point(-0.55, 0.25, 1.75)},
                        {left, Point(-0.65, -0.2, 1.65)}, {right, Point(0.55, 0.25, 1.75)},
                        {right, Point(0.65, -0.2, 1.65)}};
    subjects.push_back(tubeSubject("tree", false, {{tree, 0.06}}, 0, 5));
    subjects.push_back(tubeSubject("ring", true, {{shapes::circle(Point::Zero(), 0.8), 0.15}}, 1, 0));
    Polyline eight = shapes::circle(Point(-0.7, 0, 0), 0.6);
    const Polyline rightLoop = shapes::circle(Point(0.7, 0, 0), 0.6);
    eight.insert(eight.end(), rightLoop.begin(), rightLoop.end());
    eight.push_back({Point(-0.1, 0, 0), Point(0.1, 0, 0)});
    subjects.push_back(tubeSubject("genus 2 (figure eight)", false, {{eight, 0.18}}, 2, 0));
    std::vector<Tube> animal{{{{Point(-0.8, 0, 0), Point(0.8, 0, 0)}}, 0.3}};
    for (double x : {-0.5, 0.5}) {
        for (double side : {-0.15, 0.15}) animal.push_back({{{Point(x, side, 0), Point(x, side, -1.0)}}, 0.045});
    }
    subjects.push_back(tubeSubject("thin legs, thick body", true, animal, 0, 6));
    // Two parallel tubes (axes 0.28 apart, radius 0.08) whose surfaces are 0.12 apart, about
    // 3.6 node spacings: two parts.
    subjects.push_back(tubeSubject("two close tubes", false,
                                   {{{{Point(-0.14, 0, 0), Point(-0.14, 0, 1.6)}}, 0.08},
                                    {{{Point(0.14, 0, 0), Point(0.14, 0, 1.6)}}, 0.08}},
                                   0, 4, 2));
    // Three rings in a row, each joined to the next by a short bar: genus 3.
    Polyline three;
    for (double x : {-1.3, 0.0, 1.3}) {
        const Polyline ring = shapes::circle(Point(x, 0, 0), 0.5);
        three.insert(three.end(), ring.begin(), ring.end());
    }
    three.push_back({Point(-0.8, 0, 0), Point(-0.5, 0, 0)});
    three.push_back({Point(0.5, 0, 0), Point(0.8, 0, 0)});
    subjects.push_back(tubeSubject("genus 3 (three rings)", true, {{three, 0.12}}, 3, 0));
    return subjects;
}

// A closed mesh from libcgal-demo, sampled uniformly on its faces by CGAL.
bool addModel(std::vector<Subject>& subjects, const std::filesystem::path& folder, const std::string& name, int cycles,
              int tips, bool heldOut) {
    auto mesh = std::make_shared<Mesh>();
    if (!CGAL::IO::read_polygon_mesh((folder / (name + ".off")).string(), *mesh) || !CGAL::is_triangle_mesh(*mesh)) {
        return false;
    }
    Subject s;
    s.name = name + " (libcgal-demo)";
    s.heldOut = heldOut;
    s.cycles = cycles;
    s.tips = tips;
    s.area = CGAL::to_double(CGAL::Polygon_mesh_processing::area(*mesh));
    // Uniform on the faces, with our own seeded generator: CGAL's sample_triangle_mesh gave
    // different samples from run to run (its random_seed did not make it reproducible).
    auto triangles = std::make_shared<shapes::Triangles>();
    for (const auto f : mesh->faces()) {
        shapes::Triangle t;
        int c = 0;
        for (const auto v : CGAL::vertices_around_face(mesh->halfedge(f), *mesh)) {
            const Kernel::Point_3& p = mesh->point(v);
            t[c++] = Point(p.x(), p.y(), p.z());
        }
        triangles->push_back(t);
    }
    s.sample = [triangles](std::size_t n, std::uint32_t seed) { return shapes::sample(*triangles, n, seed); };
    auto faceTree = std::make_shared<FaceTree>(CGAL::faces(*mesh).first, CGAL::faces(*mesh).second, *mesh);
    faceTree->accelerate_distance_queries();
    s.surfaceDistance = [mesh, faceTree](const Point& p) {
        return std::sqrt(CGAL::to_double(faceTree->squared_distance(Kernel::Point_3(p.x(), p.y(), p.z()))));
    };
    if (CGAL::is_closed(*mesh)) {
        auto side = std::make_shared<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(*mesh);
        s.inside = [mesh, side](const Point& p) {
            return (*side)(Kernel::Point_3(p.x(), p.y(), p.z())) != CGAL::ON_UNBOUNDED_SIDE;
        };
    }
    subjects.push_back(std::move(s));
    return true;
}

std::filesystem::path extractModels(const std::vector<std::string>& names) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "pcskeleton_bench_models";
    std::string command = "mkdir -p '" + folder.string() + "' && tar -xzf /usr/share/doc/libcgal-demo/data.tar.gz -C '" +
                          folder.string() + "' --strip-components=2";
    for (const std::string& name : names) command += " data/meshes/" + name + ".off";
    if (std::system((command + " 2>/dev/null").c_str()) != 0) return {};
    return folder;
}



// Pixel of a virtual scanner: three sample spacings of a uniform sample of `n` points, so
// that no pixel of a front surface is empty (which would let the back show through).
double scanPixel(const Subject& s, std::size_t n) { return 3.0 * std::sqrt(s.area / double(n)); }


}  // namespace

std::vector<Condition> conditions() {
    using namespace shapes;
    auto noisy = [](double share) {
        return [share](const Subject& s, std::size_t n, std::uint32_t seed) { return withNoise(s.sample(n, seed), share, seed); };
    };
    auto outliers = [](double share) {
        return [share](const Subject& s, std::size_t n, std::uint32_t seed) {
            return withOutliers(s.sample(n, seed), share, seed);
        };
    };
    auto misaligned = [](double share) {
        return [share](const Subject& s, std::size_t n, std::uint32_t seed) {
            return misalignedScans(s.sample(n, seed), 5, scanPixel(s, n), share, seed);
        };
    };
    return {
        {"clean", [](const Subject& s, std::size_t n, std::uint32_t seed) { return s.sample(n, seed); }},
        {"noise 0.5%", noisy(0.005)},
        {"noise 1%", noisy(0.01)},
        {"noise 2%", noisy(0.02)},
        {"outliers 1%", outliers(0.01)},
        {"outliers 5%", outliers(0.05)},
        {"half in 10%", [](const Subject& s, std::size_t n, std::uint32_t seed) {
             return unevenlyDense(s.sample(5 * n, seed), n, 0.1, seed);
         }},
        {"scan 1 view", [](const Subject& s, std::size_t n, std::uint32_t seed) {
             return virtualScans(s.sample(2 * n, seed), 1, scanPixel(s, 2 * n));
         }},
        // The same from two other directions: one view must not be one lucky direction.
        {"1 view, side", [](const Subject& s, std::size_t n, std::uint32_t seed) {
             return visibleFrom(s.sample(2 * n, seed), Point(1, 0.3, -0.55), scanPixel(s, 2 * n));
         }},
        {"1 view, above", [](const Subject& s, std::size_t n, std::uint32_t seed) {
             return visibleFrom(s.sample(2 * n, seed), Point(0.2, 0.3, -1), scanPixel(s, 2 * n));
         }},
        {"scan 4 views", [](const Subject& s, std::size_t n, std::uint32_t seed) {
             return virtualScans(s.sample(n, seed), 4, scanPixel(s, n));
         }},
        {"misaligned 0.5%", misaligned(0.005)},
        {"misaligned 1%", misaligned(0.01)},
    };
}

std::vector<Subject> robustnessSubjects() {
    std::vector<Subject> subjects = knownShapes();
    const std::vector<std::string> models{"elephant", "knot1", "eight", "hand"};
    const std::filesystem::path folder = extractModels(models);
    // hand.off is a fist: four fingers curled onto the palm and each other, one closed
    // genus-0 surface from which only the thumb and the wrist stand out. Its tips are not a
    // known answer (the table expected 6, five fingers and the wrist, until 2026-11-30;
    // the shape has no free fingers to give them), as the elephant's are not.
    // elephant.off is genus 3 (its Euler characteristic is -4). One handle is plain to see:
    // the trunk curls back onto the head, leaving a slit about 0.1 long and 0.04 wide; the
    // other two are smaller. The table expected a tree until 2026-12-03, which hid the
    // loss of those tunnels.
    const std::map<std::string, std::pair<int, int>> modelTopology{
        {"elephant", {3, kUnknown}}, {"knot1", {1, 0}}, {"eight", {2, 0}}, {"hand", {0, kUnknown}}};
    const std::set<std::string> heldOutModels{"knot1", "hand"};
    for (const std::string& model : models) {
        const auto [cycles, tips] = modelTopology.at(model);
        if (folder.empty() || !addModel(subjects, folder, model, cycles, tips, heldOutModels.count(model) > 0)) {
            std::printf("(%s skipped: install libcgal-demo)\n", model.c_str());
        }
    }
    for (Subject& subject : sheetAndMixedShapes()) subjects.push_back(std::move(subject));
    return subjects;
}

}  // namespace pcskeleton::bench
