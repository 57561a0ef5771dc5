#include "guarded_classes.h"

#include <fcntl.h>
#include <unistd.h>

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace pmap::input {
namespace {

using mrpt::obs::CActionRobotMovement2D;
using mrpt::serialization::CArchive;

/// Bytes already taken from `rest` (re-encoded), then `rest` itself.
class PrefixedArchive : public CArchive {
 public:
  PrefixedArchive(std::vector<std::uint8_t> prefix, CArchive& rest)
      : prefix_(std::move(prefix)), rest_(rest) {}

 protected:
  size_t write(const void*, size_t) override {
    throw std::logic_error("PrefixedArchive is read-only");
  }
  size_t read(void* buf, size_t len) override {
    const size_t n = std::min(len, prefix_.size() - at_);
    std::memcpy(buf, prefix_.data() + at_, n);
    at_ += n;
    if (n < len) {
      rest_.ReadBuffer(static_cast<std::uint8_t*>(buf) + n, len - n);  // throws at the end
    }
    return len;
  }

 private:
  std::vector<std::uint8_t> prefix_;
  std::size_t at_ = 0;
  CArchive& rest_;
};

// MRPT 2.5.8 reads an action's estimation method, and for anything but
// odometry reads the next object as the pose PDF without checking its class:
// a corrupted method (or PDF) leaves a null PDF that serializeFrom then
// dereferences (SIGSEGV). This decoder reads the method (and the PDF) first,
// refuses what MRPT would crash on, re-encodes what it read with MRPT's own
// writer and lets MRPT's decoder read it again followed by the rest.
class GuardedMovement2D : public CActionRobotMovement2D {
 public:
  void serializeFrom(CArchive& in, uint8_t version) override {
    if (version < 4) {  // older layouts put the PDF first; MRPT reads those
      CActionRobotMovement2D::serializeFrom(in, version);
      return;
    }
    std::int32_t method = 0;
    in >> method;
    mrpt::io::CMemoryStream buffer;
    auto out = mrpt::serialization::archiveFrom(buffer);
    out << method;
    if (method == emScan2DMatching) {
      const auto pdf = in.ReadObject<mrpt::poses::CPosePDF>();
      if (!pdf) {
        throw std::runtime_error("CActionRobotMovement2D: the pose PDF is not a pose PDF");
      }
      out << *pdf;
    } else if (method != emOdometry) {
      throw std::runtime_error("CActionRobotMovement2D: invalid estimation method " +
                               std::to_string(method));
    }
    const auto* bytes = static_cast<const std::uint8_t*>(buffer.getRawBufferData());
    PrefixedArchive prefixed({bytes, bytes + buffer.getTotalBytesCount()}, in);
    CActionRobotMovement2D::serializeFrom(prefixed, version);
  }
};

const mrpt::rtti::TRuntimeClassId* actionBase() {
  return CLASS_ID(mrpt::obs::CAction);
}

const mrpt::rtti::TRuntimeClassId kGuardedMovement2D = {
    "mrpt::obs::CActionRobotMovement2D",
    []() -> std::shared_ptr<mrpt::rtti::CObject> { return std::make_shared<GuardedMovement2D>(); },
    &actionBase};

// MRPT prints a warning when a class name is registered again: expected here.
class QuietStderr {
 public:
  QuietStderr() : saved_(::dup(2)) {
    const int null = ::open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0) {
      ::dup2(null, 2);
    }
    if (null >= 0) {
      ::close(null);
    }
  }
  ~QuietStderr() {
    if (saved_ >= 0) {
      ::dup2(saved_, 2);
      ::close(saved_);
    }
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_;
};

}  // namespace

void registerGuardedClasses() {
  // MRPT's registerAllClasses_*() registers its own decoders again (any
  // library may call it): check, cheaply, before every use.
  if (mrpt::rtti::findRegisteredClass(kGuardedMovement2D.className) != &kGuardedMovement2D) {
    QuietStderr quiet;
    mrpt::rtti::registerClass(&kGuardedMovement2D);
  }
}

}  // namespace pmap::input
