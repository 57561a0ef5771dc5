// .3Dscene files (MRPT's compressed scene serialization, opened by
// SceneViewer3D).
#pragma once

#include <mrpt/opengl/COpenGLScene.h>

#include <filesystem>

namespace pmap::scene {

/// Writes `scene` with COpenGLScene::saveToFile under a temporary name in the
/// target directory, then renames it into place. Throws OutputError naming
/// the file when the directory is missing or a write or rename fails.
void writeMapScene(const std::filesystem::path& file, const mrpt::opengl::COpenGLScene& scene);

/// Loads a .3Dscene file; throws InputError naming the file on failure.
mrpt::opengl::COpenGLScene::Ptr readMapScene(const std::filesystem::path& file);

}  // namespace pmap::scene
