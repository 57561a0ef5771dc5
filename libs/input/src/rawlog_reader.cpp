#include "pmap/input/rawlog_reader.h"

#include <mrpt/io/CStream.h>
#include <mrpt/obs/registerAllClasses.h>
#include <mrpt/serialization/CArchive.h>
#include <zlib.h>

#include <cstring>
#include <system_error>

#include "allocation_guard.h"
#include "guarded_classes.h"
#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::input {
namespace fs = std::filesystem;

/// A read-only mrpt::io::CStream over zlib's gz* API (plain files pass
/// through). Unlike CFileGZInputStream it tells a clean end of data from a
/// truncated or corrupt gzip stream.
class RawlogReader::Stream : public mrpt::io::CStream {
 public:
  explicit Stream(const fs::path& path) : file_(gzopen(path.c_str(), "rb")) {}
  ~Stream() override {
    if (file_ != nullptr) {
      gzclose(file_);
    }
  }
  bool isOpen() const { return file_ != nullptr; }

  size_t Read(void* buffer, size_t count) override {
    size_t done = 0;
    auto* out = static_cast<unsigned char*>(buffer);
    while (done < count && !error_ && !eof_) {
      const unsigned chunk = static_cast<unsigned>(std::min<size_t>(count - done, 1u << 30));
      const int n = gzread(file_, out + done, chunk);
      if (n < 0) {
        recordError();
        break;
      }
      if (n == 0) {
        eof_ = true;
        recordError();  // a gzip stream cut before its trailer reports Z_BUF_ERROR here
        break;
      }
      done += static_cast<size_t>(n);
    }
    position_ += done;
    return done;
  }
  size_t Write(const void*, size_t) override { return 0; }
  uint64_t Seek(int64_t, TSeekOrigin) override { return position_; }
  uint64_t getTotalBytesCount() const override { return 0; }
  uint64_t getPosition() const override { return position_; }
  uint64_t compressedPosition() const {
    const z_off_t off = gzoffset(file_);
    return off < 0 ? position_ : static_cast<uint64_t>(off);
  }

  bool eof() const { return eof_; }
  bool hasError() const { return error_; }
  /// Truncated gzip (unexpected end) as opposed to corrupt data.
  bool truncatedGzip() const { return zerr_ == Z_BUF_ERROR; }
  const std::string& errorText() const { return error_text_; }

 private:
  void recordError() {
    int err = Z_OK;
    const char* msg = gzerror(file_, &err);
    if (err != Z_OK && err != Z_STREAM_END) {
      error_ = true;
      zerr_ = err;
      error_text_ = msg != nullptr ? msg : "zlib error";
    }
  }

  gzFile file_;
  uint64_t position_ = 0;
  bool eof_ = false;
  bool error_ = false;
  int zerr_ = Z_OK;
  std::string error_text_;
};

RawlogReader::RawlogReader(const fs::path& path, RawlogReaderOptions options)
    : path_(path), options_(options) {
  mrpt::obs::registerAllClasses_mrpt_obs();
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    throw InputError(path.string() + ": rawlog not found");
  }
  if (fs::is_directory(path, ec)) {
    throw InputError(path.string() + ": is a directory, not a rawlog file");
  }
  file_size_ = fs::file_size(path, ec);
  if (ec) {
    throw InputError(path.string() + ": cannot read file size: " + ec.message());
  }
  if (file_size_ == 0) {
    throw InputError(path.string() + ": empty file (0 bytes), not a rawlog");
  }
  stream_ = std::make_unique<Stream>(path);
  if (!stream_->isOpen()) {
    throw InputError(path.string() + ": cannot open for reading: " + std::strerror(errno));
  }
}

RawlogReader::~RawlogReader() = default;

std::uint64_t RawlogReader::position() const {
  return stream_->getPosition();
}
std::uint64_t RawlogReader::compressedPosition() const {
  return stream_->compressedPosition();
}

void RawlogReader::fail(const std::string& what, std::uint64_t offset) const {
  throw InputError(path_.string() + ": record " + std::to_string(records_) + " at byte " +
                   std::to_string(offset) + ": " + what);
}

bool RawlogReader::handleEnd(std::uint64_t start, const std::string& what) {
  done_ = true;
  const bool nothing_read = stream_->getPosition() == start;
  if (nothing_read && !stream_->hasError()) {
    if (records_ == 0) {
      fail("no records: not a rawlog", start);
    }
    return false;  // clean end
  }
  if (stream_->hasError() && !stream_->truncatedGzip()) {
    fail("corrupt gzip data (" + stream_->errorText() + ")", start);
  }
  const std::string message = path_.string() + ": record " + std::to_string(records_) +
                              " at byte " + std::to_string(start) + ": truncated file (" + what +
                              ")";
  if (!options_.accept_truncated) {
    throw InputError(message + "; use --accept-truncated to keep the " + std::to_string(records_) +
                     " complete records");
  }
  truncation_ = message;
  return false;
}

bool RawlogReader::next(RawlogRecord& record) {
  if (done_) {
    return false;
  }
  registerGuardedClasses();  // stands in for MRPT's crashing decoders
  const std::uint64_t start = stream_->getPosition();
  auto archive = mrpt::serialization::archiveFrom(*stream_);
  mrpt::serialization::CSerializable::Ptr object;
  bool refused = false;
  try {
    ScopedAllocationLimit limit(options_.max_allocation_mb << 20, options_.max_record_mb << 20);
    try {
      object = archive.ReadObject();
    } catch (...) {
      refused = limit.refused();
      throw;
    }
  } catch (const mrpt::serialization::CExceptionEOF& e) {
    return handleEnd(start, "unexpected end of data");
  } catch (const std::bad_alloc&) {
    done_ = true;
    fail(refused ? "corrupt record (a size field asks for more than " +
                       std::to_string(options_.max_allocation_mb) +
                       " MiB, or the record for more than " +
                       std::to_string(options_.max_record_mb) + " MiB in all)"
                 : "out of memory while decoding",
         start);
  } catch (const std::exception& e) {
    if (stream_->eof() || stream_->hasError()) {
      return handleEnd(start, oneLineError(e.what()));
    }
    done_ = true;
    fail("corrupt record: " + oneLineError(e.what()), start);
  }
  if (!object) {
    done_ = true;
    fail("corrupt record: null object", start);
  }
  record.index = records_++;
  record.offset = start;
  record.object = std::move(object);
  return true;
}

}  // namespace pmap::input
