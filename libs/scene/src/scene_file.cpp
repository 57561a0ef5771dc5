#include "pmap/scene/scene_file.h"

#include <unistd.h>

#include <exception>
#include <string>
#include <system_error>

#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::scene {
namespace fs = std::filesystem;

namespace {

void removeQuietly(const fs::path& path) {
  std::error_code ignored;
  fs::remove(path, ignored);
}

}  // namespace

void writeMapScene(const fs::path& file, const mrpt::opengl::COpenGLScene& scene) {
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw OutputError(file.string() + ": directory does not exist");
  }
  const fs::path tmp = file.string() + ".tmp-" + std::to_string(::getpid());
  bool saved = false;
  std::string why = "write failed";
  try {
    saved = scene.saveToFile(tmp.string());
  } catch (const std::exception& e) {
    why = oneLineError(e.what());
  }
  if (!saved) {
    removeQuietly(tmp);
    throw OutputError(file.string() + ": cannot write scene: " + why);
  }
  fs::rename(tmp, file, ec);
  if (ec) {
    removeQuietly(tmp);
    throw OutputError(file.string() + ": cannot rename temporary file into place: " + ec.message());
  }
}

mrpt::opengl::COpenGLScene::Ptr readMapScene(const fs::path& file) {
  auto scene = mrpt::opengl::COpenGLScene::Create();
  bool loaded = false;
  std::string why = "not a readable .3Dscene file";
  try {
    loaded = fs::is_regular_file(file) && scene->loadFromFile(file.string());
  } catch (const std::exception& e) {
    why = oneLineError(e.what());
  }
  if (!loaded) {
    throw InputError(file.string() + ": cannot load scene: " + why);
  }
  return scene;
}

}  // namespace pmap::scene
