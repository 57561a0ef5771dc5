#include "pmap/sim/rawlog_writer.h"

#include <unistd.h>

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

RawlogWriter::RawlogWriter(const std::filesystem::path& final_path, RawlogFormat format)
    : final_path_(final_path),
      tmp_path_(final_path.string() + ".tmp-" + std::to_string(::getpid())),
      format_(format),
      stream_(std::make_unique<Stream>()) {
  bool ok = false;
  try {
    ok = stream_->file.open(tmp_path_.string(), 1);
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok) {
    throw OutputError(final_path_.string() + ": cannot create the rawlog (temporary file " +
                      tmp_path_.string() + ")");
  }
}

RawlogWriter::~RawlogWriter() {
  if (!committed_) {
    stream_.reset();
    std::error_code ec;
    std::filesystem::remove(tmp_path_, ec);
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
    throw OutputError(final_path_.string() + ": write failed: " + e.what());
  }
}

void RawlogWriter::commit() {
  stream_->file.close();
  std::error_code ec;
  std::filesystem::rename(tmp_path_, final_path_, ec);
  if (ec) {
    throw OutputError(final_path_.string() +
                      ": cannot rename the temporary rawlog into place: " + ec.message());
  }
  committed_ = true;
}

}  // namespace pmap::sim
