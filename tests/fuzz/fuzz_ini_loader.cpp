// libFuzzer target: bytes -> an ini file -> the strict ini parser, the
// project's options (loadMapperConfig) and MRPT's ICP loaders through the
// strict wrapper, as planar-mapper reads its --config. Any outcome but a
// configuration or a ConfigError is a finding.
#include "fuzz_support.h"
#include "pmap/common/error.h"
#include "pmap/config/strict_mrpt_config.h"
#include "pmap/mapper/mapper_config.h"
#include "pmap/poses/icp_pose_tracker.h"

namespace {

// As the pipeline's makeTracker: every key of the MRPT sections must be read.
void loadIcp(const pmap::mapper::MapperConfig& config) {
  pmap::config::StrictMrptConfig mrpt_config(config.doc, pmap::mapper::mrptSections(),
                                             config.effective.get());
  mrpt_config.requireSection("ICP");
  mrpt_config.requireSection("MappingApplication");
  try {
    pmap::poses::IcpPoseTracker tracker(mrpt_config);
  } catch (const pmap::Error&) {
    throw;
  } catch (const std::exception& e) {
    mrpt_config.throwLoaderError(e);
  }
  mrpt_config.checkAllRead();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path path = pmap::fuzz::scratchFile("input.ini");
  pmap::fuzz::writeScratch(path, data, size);
  try {
    const pmap::mapper::MapperConfig config = pmap::mapper::loadMapperConfig(path);
    loadIcp(config);
  } catch (const pmap::ConfigError&) {
    // the documented outcome of a bad configuration
  }
  return 0;
}
