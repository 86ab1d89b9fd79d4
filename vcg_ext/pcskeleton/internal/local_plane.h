// The least-squares plane of some points (principal component analysis): their centroid,
// the axes by increasing spread (column 0 is the plane's normal) and the variance along
// each. The point denoising and the reconstruction's point weights fit the same planes.
#pragma once

#include "pcskeleton/core/point.h"

#include <Eigen/Eigenvalues>

#include <vector>

namespace pcskeleton {

struct LocalPlane {
    Point centroid;
    Eigen::Matrix3d axes;       // eigenvectors by increasing variance; col(0) the normal
    Eigen::Vector3d variances;  // mean squared offsets along the axes, increasing
};

// `subset` indexes `points`; it must not be empty.
inline LocalPlane fitLocalPlane(const PointList& points, const std::vector<int>& subset) {
    LocalPlane plane{Point::Zero(), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()};
    for (int j : subset) plane.centroid += points[std::size_t(j)];
    plane.centroid /= double(subset.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (int j : subset) {
        const Point d = points[std::size_t(j)] - plane.centroid;
        covariance += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    plane.axes = eigen.eigenvectors();
    plane.variances = eigen.eigenvalues() / double(subset.size());
    return plane;
}

}  // namespace pcskeleton
