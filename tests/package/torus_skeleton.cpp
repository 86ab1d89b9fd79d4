// The skeleton of points on a torus: one cycle.
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/version.h>

#include <cmath>
#include <iostream>

int main() {
    pcskeleton::PointList points;
    for (int i = 0; i < 60; ++i) {
        for (int j = 0; j < 40; ++j) {
            const double t = 2 * M_PI * i / 60, u = 2 * M_PI * j / 40;
            points.emplace_back((1 + 0.25 * std::cos(u)) * std::cos(t), (1 + 0.25 * std::cos(u)) * std::sin(t), 0.25 * std::sin(u));
        }
    }
    const pcskeleton::SkeletonResult result = pcskeleton::computeCurveSkeleton(points);
    std::cout << "pcskeleton " PCSKELETON_VERSION ": cycles " << pcskeleton::analyseTopology(result.skeleton).cycles << "\n";
}
