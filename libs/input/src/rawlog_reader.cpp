#include "pmap/input/rawlog_reader.h"

#include <mrpt/io/CStream.h>
#include <mrpt/obs/registerAllClasses.h>
#include <mrpt/serialization/CArchive.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "allocation_guard.h"
#include "guarded_classes.h"
#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::input {
namespace fs = std::filesystem;

/// A read-only mrpt::io::CStream over a plain or gzip file. gzip is decoded
/// member by member with zlib's inflate: unlike gzread (and MRPT's
/// CFileGZInputStream), which stop silently at data after a member that is
/// not a valid gzip header, every byte of the file must belong to a member.
/// A member cut short is a truncation; a bad header, bad deflate data or a
/// CRC / length mismatch is corruption.
class RawlogReader::Stream : public mrpt::io::CStream {
 public:
  explicit Stream(const fs::path& path) : file_(std::fopen(path.c_str(), "rb")) {
    if (file_ == nullptr) {
      return;
    }
    unsigned char magic[2] = {0, 0};
    const size_t n = std::fread(magic, 1, 2, file_);
    gzip_ = n == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
    std::rewind(file_);
    if (gzip_ && inflateInit2(&zs_, 15 + 16) != Z_OK) {  // 15 + 16: gzip wrapper only
      std::fclose(file_);
      file_ = nullptr;
    }
  }
  ~Stream() override {
    if (gzip_ && file_ != nullptr) {
      inflateEnd(&zs_);
    }
    if (file_ != nullptr) {
      std::fclose(file_);
    }
  }
  bool isOpen() const { return file_ != nullptr; }

  size_t Read(void* buffer, size_t count) override {
    auto* out = static_cast<unsigned char*>(buffer);
    const size_t ahead = std::min(count, peeked_.size() - peek_used_);
    std::copy_n(peeked_.begin() + static_cast<std::ptrdiff_t>(peek_used_), ahead, out);
    peek_used_ += ahead;
    const size_t done = ahead + decode(out + ahead, count - ahead);
    position_ += done;
    return done;
  }

  /// The first `n` decoded bytes (fewer at the end of the data), without
  /// consuming them. Only before the first Read.
  const std::vector<unsigned char>& peek(size_t n) {
    if (peeked_.empty() && position_ == 0) {
      peeked_.resize(n);
      peeked_.resize(decode(peeked_.data(), n));
    }
    return peeked_;
  }
  size_t Write(const void*, size_t) override { return 0; }
  uint64_t Seek(int64_t, TSeekOrigin) override { return position_; }
  uint64_t getTotalBytesCount() const override { return 0; }
  uint64_t getPosition() const override { return position_; }
  uint64_t compressedPosition() const { return gzip_ ? file_read_ - zs_.avail_in : position_; }

  bool eof() const { return eof_; }
  bool hasError() const { return error_; }
  /// A gzip member cut short (the file ends inside it), as opposed to corrupt data.
  bool truncatedGzip() const { return truncated_; }
  const std::string& errorText() const { return error_text_; }

 private:
  size_t decode(unsigned char* out, size_t count) {
    return count == 0 ? 0 : gzip_ ? readGzip(out, count) : readPlain(out, count);
  }

  size_t readPlain(unsigned char* out, size_t count) {
    const size_t n = error_ || eof_ ? 0 : std::fread(out, 1, count, file_);
    if (n < count && std::ferror(file_) != 0) {
      fail(std::string("read error: ") + std::strerror(errno));
    } else if (n < count) {
      eof_ = true;
    }
    return n;
  }

  // Refills the input buffer; false at the end of the file (or a read error).
  bool refill() {
    const size_t n = std::fread(in_.data(), 1, in_.size(), file_);
    if (n == 0 && std::ferror(file_) != 0) {
      fail(std::string("read error: ") + std::strerror(errno));
    }
    file_read_ += n;
    zs_.next_in = in_.data();
    zs_.avail_in = static_cast<uInt>(n);
    return n > 0;
  }

  size_t readGzip(unsigned char* out, size_t count) {
    size_t done = 0;
    while (done < count && !error_ && !eof_) {
      if (zs_.avail_in == 0 && !refill()) {
        eof_ = true;
        truncated_ = in_member_ && !error_;  // the file ends inside a member
        if (truncated_) {
          error_ = true;
          error_text_ = "unexpected end of file inside gzip member " + std::to_string(members_);
        }
        break;
      }
      if (!in_member_) {  // more bytes after a complete member: the next member
        inflateReset(&zs_);
        in_member_ = true;
      }
      const size_t want = std::min<size_t>(count - done, 1u << 30);
      zs_.next_out = out + done;
      zs_.avail_out = static_cast<uInt>(want);
      const int ret = inflate(&zs_, Z_NO_FLUSH);
      done += want - zs_.avail_out;
      if (ret == Z_STREAM_END) {
        in_member_ = false;
        ++members_;
      } else if (ret != Z_OK && ret != Z_BUF_ERROR) {
        fail("member " + std::to_string(members_) + ": " +
             (zs_.msg != nullptr ? zs_.msg : "zlib error " + std::to_string(ret)));
      }
    }
    return done;
  }

  void fail(const std::string& text) {
    error_ = true;
    eof_ = true;
    error_text_ = text;
  }

  std::FILE* file_;
  bool gzip_ = false;
  z_stream zs_{};
  std::array<unsigned char, 1 << 16> in_{};
  uint64_t file_read_ = 0;  // compressed bytes read from the file
  std::vector<unsigned char> peeked_;
  size_t peek_used_ = 0;
  bool in_member_ = false;
  std::size_t members_ = 0;  // complete gzip members decoded
  uint64_t position_ = 0;
  bool eof_ = false;
  bool error_ = false;
  bool truncated_ = false;
  std::string error_text_;
};

namespace {

bool nameChar(unsigned char c) {
  return std::isalnum(c) != 0 || c == '_' || c == ':';
}

bool nameAt(const std::vector<unsigned char>& b, std::size_t from, std::size_t n) {
  if (n == 0 || n > 127 || from + n > b.size()) {
    return false;
  }
  return std::all_of(b.begin() + static_cast<std::ptrdiff_t>(from),
                     b.begin() + static_cast<std::ptrdiff_t>(from + n), nameChar);
}

// An MRPT archive starts with the first object's class name: one byte
// 0x80 | n then n name characters (MRPT >= 1.5), or a 4-byte little-endian
// length then the name (older archives).
bool startsLikeRawlog(const std::vector<unsigned char>& b) {
  if (b.empty()) {
    return false;
  }
  if ((b[0] & 0x80) != 0) {
    return nameAt(b, 1, b[0] & 0x7fu);
  }
  if (b.size() < 4) {
    return false;
  }
  const std::uint32_t n =
      b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
  return nameAt(b, 4, n);
}

// The first bytes for a message: text as text, else in hex.
std::string firstBytes(const std::vector<unsigned char>& b) {
  const std::size_t n = std::min<std::size_t>(b.size(), 12);
  const bool text = std::all_of(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n),
                                [](unsigned char c) { return std::isprint(c) || std::isspace(c); });
  std::string out;
  char hex[4];
  for (std::size_t i = 0; i < n; ++i) {
    if (text) {
      out += std::isspace(b[i]) != 0 ? ' ' : static_cast<char>(b[i]);
    } else {
      std::snprintf(hex, sizeof hex, "%02x ", b[i]);
      out += hex;
    }
  }
  return text ? "text \"" + out + "\"" : "bytes " + trim(out);
}

}  // namespace

RawlogReader::RawlogReader(const fs::path& path, RawlogReaderOptions options)
    : path_(path), options_(options) {
  // Once per process: registering MRPT's classes again would overwrite the
  // guarded decoders (guarded_classes.h), with a warning from MRPT.
  static const bool registered = [] {
    mrpt::obs::registerAllClasses_mrpt_obs();
    return true;
  }();
  (void)registered;
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
  if (records_ == 0 && start == 0) {
    const std::vector<unsigned char>& head = stream_->peek(132);
    if (!stream_->hasError() && !head.empty() && !startsLikeRawlog(head)) {
      done_ = true;
      fail("not a rawlog: it does not start with an MRPT serialized object (" + firstBytes(head) +
               ")",
           0);
    }
  }
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
