// How planar-mapper --gui (live_view.cpp) keeps in step with MRPT 2.5.8's
// GUI thread, which draws a CDisplayWindow3D: it renders the window's scene
// only while it holds the scene lock, and it may paint the window, using the
// CDisplayWindow3D object, until it deletes the window's wx frame, some time
// after MRPT's close request returned (~CDisplayWindow3D does not wait for
// that: a program that then exits runs its exit handlers under a render).
#pragma once

#include <mrpt/gui/CDisplayWindow3D.h>
#include <mrpt/opengl/COpenGLViewport.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/system/CObserver.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

namespace pmap::mapper::detail {

using Clock = std::chrono::steady_clock;

/// Polls `done` every 10 ms; false if it is still false after `limit`.
template <class Pred>
bool waitUntil(Pred done, Clock::duration limit) {
  const auto until = Clock::now() + limit;
  while (!done()) {
    if (Clock::now() >= until) {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

/// CDisplayWindow3D that can be closed while the object lives on.
class ClosableWindow : public mrpt::gui::CDisplayWindow3D {
 public:
  using CDisplayWindow3D::CDisplayWindow3D;
  /// MRPT's close request; returns once the GUI thread handled the close
  /// event. The wx frame and its GL canvas are deleted later, when the GUI
  /// thread is next idle, and may be painted (using this object) until then.
  void requestClose() { destroyWxWindow(); }
};

/// Counts the frames MRPT's GUI thread renders: the main viewport publishes
/// mrptEventGLPostRender at the end of each render, under the scene lock.
class FrameCounter : public mrpt::system::CObserver {
 public:
  std::uint64_t count() const { return frames_.load(); }

 protected:
  void OnEvent(const mrpt::system::mrptEvent& e) override {
    if (e.isOfType<mrpt::opengl::mrptEventGLPostRender>()) {
      ++frames_;
    }
  }

 private:
  std::atomic<std::uint64_t> frames_{0};
};

/// An empty object in the window's scene. When MRPT's GUI thread destroys
/// the window's GL canvas, the canvas's destructor frees the OpenGL
/// resources of every object of the scene it rendered, this one included:
/// the canvas's last use of the CDisplayWindow3D.
class CanvasProbe : public mrpt::opengl::CSetOfObjects {
 public:
  void freeOpenGLResources() override {
    CSetOfObjects::freeOpenGLResources();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      freed_ = true;
    }
    freed_cv_.notify_all();
  }
  bool waitFreed(Clock::duration limit) {
    std::unique_lock<std::mutex> lock(mutex_);
    return freed_cv_.wait_for(lock, limit, [this] { return freed_; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable freed_cv_;
  bool freed_ = false;
};

/// Holds the window's scene lock for a scope: the GUI thread renders only
/// while it holds it.
class SceneLock {
 public:
  explicit SceneLock(mrpt::gui::CDisplayWindow3D& window)
      : window_(window), scene_(window.get3DSceneAndLock()) {}
  ~SceneLock() { window_.unlockAccess3DScene(); }
  SceneLock(const SceneLock&) = delete;
  SceneLock& operator=(const SceneLock&) = delete;
  mrpt::opengl::COpenGLViewport& viewport() { return *scene_->getViewport(); }

 private:
  mrpt::gui::CDisplayWindow3D& window_;
  mrpt::opengl::COpenGLScene::Ptr& scene_;
};

}  // namespace pmap::mapper::detail
