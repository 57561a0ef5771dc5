// Scene objects around the map: robot path, raw points, ground grid, axes.
#pragma once

#include <mrpt/opengl/CRenderizable.h>

#include <Eigen/Core>
#include <vector>

#include "pmap/products/map_model.h"
#include "pmap/scene/map_scene.h"

namespace pmap::scene::detail {

/// The path as a line strip (no segment for fewer than two positions).
mrpt::opengl::CRenderizable::Ptr pathObject(const std::vector<Eigen::Vector3d>& path,
                                            const Eigen::Vector3f& rgb);

/// The points, coloured per point when `colors` is given.
mrpt::opengl::CRenderizable::Ptr pointsObject(const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<Eigen::Vector3f>* colors,
                                              const SceneOptions& options);

/// A grid covering the map's xy extent (whole cells), 5 cm under its lowest
/// point; a one-cell grid at the origin for an empty map.
mrpt::opengl::CRenderizable::Ptr gridObject(const products::MapModel& model,
                                            const SceneOptions& options);

/// World axes from the origin.
mrpt::opengl::CRenderizable::Ptr axesObject(const SceneOptions& options);

}  // namespace pmap::scene::detail
