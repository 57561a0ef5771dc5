// libFuzzer target: bytes -> a rawlog file -> the streaming reader -> the
// structure points of every observation (the validation boundary). Any
// outcome but records or an InputError (another exception, a crash, a
// sanitizer report, an allocation above the fuzzer's malloc limit) is a
// finding. Odd sizes read with accept_truncated.
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cmath>

#include "fuzz_support.h"
#include "pmap/common/error.h"
#include "pmap/input/rawlog_reader.h"
#include "pmap/input/structure_points.h"

namespace {

void checkPoints(const pmap::input::StructureScan& scan) {
  for (const auto& p : scan.points) {
    if (!p.allFinite()) {
      pmap::fuzz::invariantFailed("a structure point is not finite");
    }
  }
}

void visit(const mrpt::serialization::CSerializable::Ptr& object, std::int64_t index) {
  if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object)) {
    checkPoints(pmap::input::extractStructureScan(*obs, index));
  } else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object)) {
    for (const auto& o : *sf) {
      if (o) {
        checkPoints(pmap::input::extractStructureScan(*o, index));
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path path = pmap::fuzz::scratchFile("input.rawlog");
  pmap::fuzz::writeScratch(path, data, size);
  pmap::input::RawlogReaderOptions options;
  options.accept_truncated = (size % 2) == 1;
  options.max_allocation_mb = 64;
  options.max_record_mb = 256;
  try {
    pmap::input::RawlogReader reader(path, options);
    pmap::input::RawlogRecord record;
    while (reader.next(record)) {
      visit(record.object, static_cast<std::int64_t>(record.index));
    }
  } catch (const pmap::InputError&) {
    // the documented outcome of bad data
  }
  return 0;
}
