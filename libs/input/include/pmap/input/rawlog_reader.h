// Streaming reader of MRPT rawlogs (.rawlog, plain or gzip), one top-level
// serialized object ("record") at a time.
//
// Reading object by object (rather than CRawlog::getActionObservationPair-
// OrObservation) keeps a leading sensory frame that has no action before it;
// MRPT's pair reader silently drops it (doc/input.md).
//
// MRPT's own loaders report corruption only on stderr. This reader turns every
// problem into an InputError naming the file, the record index and the byte
// offset (in the uncompressed stream) where the bad record starts:
//  - missing / directory / unreadable / empty file;
//  - truncated plain or gzip file (a record cut short, or a gzip stream that
//    ends without its trailer);
//  - corrupt data (gzip CRC or deflate errors, unknown classes, impossible
//    sizes: a single allocation above `max_allocation_mb`, or more than
//    `max_record_mb` in all, while decoding a record is reported as
//    corruption instead of reserving gigabytes).
// With `accept_truncated`, a truncated tail is not an error: the complete
// records before it are delivered and truncated() reports what was dropped.
#pragma once

#include <mrpt/serialization/CSerializable.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace pmap::input {

struct RawlogReaderOptions {
  /// Deliver the complete records of a truncated file instead of failing.
  bool accept_truncated = false;
  /// Largest single allocation (MiB) allowed while decoding one record.
  std::size_t max_allocation_mb = 256;
  /// Most memory (MiB) all allocations of one record may ask for together.
  std::size_t max_record_mb = 512;
};

struct RawlogRecord {
  std::size_t index = 0;     ///< 0-based index of the top-level object
  std::uint64_t offset = 0;  ///< uncompressed byte offset where it starts
  mrpt::serialization::CSerializable::Ptr object;
};

class RawlogReader {
 public:
  /// Opens `path`. Throws InputError if it is missing, a directory,
  /// unreadable or empty.
  explicit RawlogReader(const std::filesystem::path& path, RawlogReaderOptions options = {});
  ~RawlogReader();
  RawlogReader(const RawlogReader&) = delete;
  RawlogReader& operator=(const RawlogReader&) = delete;

  /// Reads the next record. Returns false at the clean end of the file (or at
  /// an accepted truncation). Throws InputError on bad data.
  bool next(RawlogRecord& record);

  /// True when accept_truncated let a truncated tail pass; the message says
  /// where (same wording as the error would have had).
  bool truncated() const { return !truncation_.empty(); }
  const std::string& truncationMessage() const { return truncation_; }

  const std::filesystem::path& path() const { return path_; }
  /// Uncompressed bytes consumed so far.
  std::uint64_t position() const;
  /// Size of the file on disk (compressed size for .gz).
  std::uint64_t fileSize() const { return file_size_; }
  /// Compressed bytes consumed so far (for progress; equals position() for plain files).
  std::uint64_t compressedPosition() const;
  std::size_t recordsRead() const { return records_; }

 private:
  class Stream;
  [[noreturn]] void fail(const std::string& what, std::uint64_t offset) const;
  bool handleEnd(std::uint64_t start, const std::string& what);

  std::filesystem::path path_;
  RawlogReaderOptions options_;
  std::unique_ptr<Stream> stream_;
  std::uint64_t file_size_ = 0;
  std::size_t records_ = 0;
  std::string truncation_;
  bool done_ = false;
};

}  // namespace pmap::input
