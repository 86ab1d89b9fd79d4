#include "pcskeleton/contraction/cotangent_laplacian.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace pcskeleton {

namespace {

int slotOf(const CotangentLaplacian::Matrix& m, int row, int column) {
    const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[row];
    const int* end = m.innerIndexPtr() + m.outerIndexPtr()[row + 1];
    const int* it = std::lower_bound(begin, end, column);
    return static_cast<int>(it - m.innerIndexPtr());
}

}  // namespace

double cotangentAt(const Point& apex, const Point& p, const Point& q) {
    const Point u = p - apex, v = q - apex;
    const double uv = u.norm() * v.norm();
    if (!(uv > 0.0)) return 0.0;
    // Relative floor on the sine: a flat triangle gives cot ~ 1e8, which the row limit tames.
    const double sine = std::max(u.cross(v).norm(), 1e-8 * uv);
    const double cot = u.dot(v) / sine;
    return std::isfinite(cot) ? cot : 0.0;
}

CotangentLaplacian::CotangentLaplacian(const OneRings& rings, double rowWeightLimit)
    : rings_(rings), rowWeightLimit_(rowWeightLimit) {
    const std::size_t n = rings.size();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(rings.totalRingEntries() + n);
    for (std::size_t i = 0; i < n; ++i) {
        entries.emplace_back(int(i), int(i), 0.0);
        for (const int* j = rings.ringBegin(i); j != rings.ringEnd(i); ++j) entries.emplace_back(int(i), *j, 0.0);
    }
    matrix_.resize(int(n), int(n));
    matrix_.setFromTriplets(entries.begin(), entries.end());
    matrix_.makeCompressed();

    diagonalSlot_.resize(n);
    edgeSlots_.reserve(rings.fanEnd(n - 1) - rings.fanBegin(0));
    for (std::size_t i = 0; i < n; ++i) {
        diagonalSlot_[i] = slotOf(matrix_, int(i), int(i));
        for (auto t = rings.fanBegin(i); t != rings.fanEnd(i); ++t) {
            edgeSlots_.push_back({slotOf(matrix_, int(i), (*t)[0]), slotOf(matrix_, int(i), (*t)[1])});
        }
    }
}

void CotangentLaplacian::update(const PointList& positions) {
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(rings_.size());
    double* value = matrix_.valuePtr();
    const int* outer = matrix_.outerIndexPtr();
    const OneRings::FanTriangle* firstTriangle = rings_.fanBegin(0);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        std::fill(value + outer[i], value + outer[i + 1], 0.0);
        const Point& pi = positions[i];
        for (auto t = rings_.fanBegin(i); t != rings_.fanEnd(i); ++t) {
            const Point& pa = positions[(*t)[0]];
            const Point& pb = positions[(*t)[1]];
            const auto& slot = edgeSlots_[t - firstTriangle];
            value[slot[0]] += cotangentAt(pb, pi, pa);  // edge (i, a) is opposite b
            value[slot[1]] += cotangentAt(pa, pi, pb);  // edge (i, b) is opposite a
        }
        double absoluteSum = 0.0;
        for (int s = outer[i]; s < outer[i + 1]; ++s) absoluteSum += std::abs(value[s]);
        if (absoluteSum > rowWeightLimit_) {
            const double shrink = rowWeightLimit_ / absoluteSum;
            for (int s = outer[i]; s < outer[i + 1]; ++s) value[s] *= shrink;
        }
        double sum = 0.0;
        for (int s = outer[i]; s < outer[i + 1]; ++s) sum += value[s];
        value[diagonalSlot_[i]] = -sum;
    }
}

}  // namespace pcskeleton
