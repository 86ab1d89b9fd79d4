// The least-squares plane of some points (principal component analysis): their centroid,
// the axes by increasing spread (column 0 is the plane's normal) and the variance along
// each. The point denoising and the reconstruction's point weights fit the same planes.
// Over such a plane, a quadratic height field: the surface noise measure and the fit of
// the reconstructed surface to its points follow the surface's curvature with it.
#pragma once

#include "pcskeleton/core/point.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <cmath>

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

// h(x, y) = c0 + c1 x + c2 y + c3 x² + c4 xy + c5 y²: the height along the plane's normal
// (axes.col(0)) of the point at x, y along its two spread axes (col(2), col(1)), all
// measured from its centroid.
struct LocalQuadric {
    LocalPlane plane;
    Eigen::Matrix<double, 6, 1> coefficients;
    double residual = 0;  // root mean square of the points' heights off the fit
    double extent = 0;    // root mean square of the points' distances from the centroid in the plane

    Eigen::Vector3d local(const Point& p) const {  // (x, y, height) of p
        const Point d = p - plane.centroid;
        return {d.dot(plane.axes.col(2)), d.dot(plane.axes.col(1)), d.dot(plane.axes.col(0))};
    }
    double heightAt(double x, double y) const {
        return coefficients.dot((Eigen::Matrix<double, 6, 1>() << 1, x, y, x * x, x * y, y * y).finished());
    }
};

// `subset` indexes `points`; it must not be empty (fewer than 6 points: the least-norm fit).
inline LocalQuadric fitLocalQuadric(const PointList& points, const std::vector<int>& subset) {
    LocalQuadric quadric;
    quadric.plane = fitLocalPlane(points, subset);
    Eigen::MatrixXd basis(subset.size(), 6);
    Eigen::VectorXd height(subset.size());
    for (std::size_t r = 0; r < subset.size(); ++r) {
        const Eigen::Vector3d l = quadric.local(points[std::size_t(subset[r])]);
        basis.row(Eigen::Index(r)) << 1, l.x(), l.y(), l.x() * l.x(), l.x() * l.y(), l.y() * l.y();
        height[Eigen::Index(r)] = l.z();
        quadric.extent += l.x() * l.x() + l.y() * l.y();
    }
    quadric.extent = std::sqrt(quadric.extent / double(subset.size()));
    quadric.coefficients = basis.colPivHouseholderQr().solve(height);
    quadric.residual = std::sqrt((basis * quadric.coefficients - height).squaredNorm() / double(subset.size()));
    return quadric;
}

}  // namespace pcskeleton
