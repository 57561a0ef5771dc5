#include "pmap/sim/rawlog_writer.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include "pmap/common/error.h"

namespace pmap::sim {

struct RawlogWriter::Stream {
  mrpt::io::CFileGZOutputStream file;
};

std::optional<RawlogFormat> parseRawlogFormat(std::string_view name) {
  if (name == "obs") {
    return RawlogFormat::kObservations;
  }
  if (name == "sf") {
    return RawlogFormat::kSensoryFrames;
  }
  return std::nullopt;
}

const char* rawlogFormatName(RawlogFormat format) {
  return format == RawlogFormat::kObservations ? "obs" : "sf";
}

RawlogWriter::RawlogWriter(const std::filesystem::path& path, RawlogFormat format)
    : path_(path), format_(format), stream_(std::make_unique<Stream>()) {
  bool ok = false;
  try {
    ok = stream_->file.open(path_.string(), 1);
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok) {
    throw OutputError(path_.string() + ": cannot create the rawlog");
  }
}

RawlogWriter::~RawlogWriter() {
  if (!finished_) {
    stream_.reset();
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
}

void RawlogWriter::write(const CycleRecord& cycle) {
  try {
    auto archive = mrpt::serialization::archiveFrom(stream_->file);
    if (format_ == RawlogFormat::kObservations) {
      archive << *cycle.odometry;
      ++objects_;
      for (const auto& obs : cycle.observations) {
        archive << *obs;
        ++objects_;
      }
    } else {
      mrpt::obs::CSensoryFrame frame;
      for (const auto& obs : cycle.observations) {
        frame.insert(obs);
      }
      archive << *cycle.action << frame;
      objects_ += 2;
    }
  } catch (const std::exception& e) {
    throw OutputError(path_.string() + ": write failed: " + e.what());
  }
}

void RawlogWriter::finish() {
  stream_->file.close();
  finished_ = true;
}

}  // namespace pmap::sim
