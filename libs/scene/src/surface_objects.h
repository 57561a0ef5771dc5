// Scene objects of the map surfaces: rectangles and fine triangles.
#pragma once

#include <mrpt/opengl/CRenderizable.h>

#include "pmap/products/map_model.h"

namespace pmap::scene::detail {

/// One rectangle: textured (CSetOfTexturedTriangles) or in its colour
/// (CSetOfTriangles), named "surface_<id>".
mrpt::opengl::CRenderizable::Ptr quadObject(const products::TexturedQuad& quad);

/// All fine triangles as one CSetOfTriangles with vertex colours.
mrpt::opengl::CRenderizable::Ptr fineTrianglesObject(const products::ColoredTriangles& fine);

}  // namespace pmap::scene::detail
