// Geometric errors between a map rectangle and a reference rectangle.
#pragma once

#include <Eigen/Core>

#include "pmap/eval/reference_surfaces.h"

namespace pmap::eval {

/// Angle between two directions, sign-agnostic (0..90 degrees).
double normalAngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/// Distance from p to the plane n . x = offset_m (n unit).
double planeDistance(const Eigen::Vector3d& n, double offset_m, const Eigen::Vector3d& p);

/// Centre (mean of the corners) of a rectangle.
Eigen::Vector3d rectangleCentre(const Rectangle& r);

/// Mean distance between corresponding corners, minimised over the 8
/// correspondences of two quadrilaterals (4 cyclic shifts x 2 orientations),
/// so neither the starting corner nor the winding order matters.
double cornerError(const Rectangle& map, const Rectangle& reference);

}  // namespace pmap::eval
