// Writes a simulated run as an MRPT rawlog (gzip, MRPT serialization):
//  - obs format: a flat, time-ordered sequence of CObservation objects
//    (odometry as absolute CObservationOdometry);
//  - sf format: alternating CActionCollection (the odometry increment as
//    CActionRobotMovement2D) and CSensoryFrame (that cycle's other observations).
// The writer fills the path it is given, normally a temporary name that the
// caller renames into place (pmap::OutputSet); a writer destroyed without
// finish() removes its file.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservationOdometry.h>

namespace pmap::sim {

enum class RawlogFormat { kObservations, kSensoryFrames };

/// "obs" or "sf".
std::optional<RawlogFormat> parseRawlogFormat(std::string_view name);
const char* rawlogFormatName(RawlogFormat format);

/// Everything one cycle logs: odometry (both as observation and as action)
/// and the other observations in time order.
struct CycleRecord {
  mrpt::obs::CObservationOdometry::Ptr odometry;
  mrpt::obs::CActionCollection::Ptr action;
  std::vector<mrpt::obs::CObservation::Ptr> observations;
};

class RawlogWriter {
 public:
  /// Throws OutputError if the file cannot be created.
  RawlogWriter(const std::filesystem::path& path, RawlogFormat format);
  ~RawlogWriter();
  RawlogWriter(const RawlogWriter&) = delete;
  RawlogWriter& operator=(const RawlogWriter&) = delete;

  /// Throws OutputError on write failure.
  void write(const CycleRecord& cycle);
  /// Closes the stream; the file is complete.
  void finish();

  std::size_t objectsWritten() const { return objects_; }

 private:
  struct Stream;
  std::filesystem::path path_;
  RawlogFormat format_;
  std::unique_ptr<Stream> stream_;
  std::size_t objects_ = 0;
  bool finished_ = false;
};

}  // namespace pmap::sim
