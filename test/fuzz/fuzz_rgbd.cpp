// libFuzzer target: a packed color + depth image pair (see mid::fuzz::loadRGBDBytes), decoded
// with cv::imdecode and turned into a cloud by mid::io::rgbdToCloud.
//   build-fuzz/test/fuzz/fuzz_rgbd NEW_CORPUS_DIR test/fuzz/corpus/rgbd -max_total_time=60
#include "fuzz_inputs.h"

#include <opencv2/core/utils/logger.hpp>
#include <pcl/console/print.h>

#include <cstdlib>

extern "C" int
LLVMFuzzerInitialize (int* /*argc*/, char*** /*argv*/)
{
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  cv::utils::logging::setLogLevel (cv::utils::logging::LOG_LEVEL_SILENT);
  return 0;
}

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  mid::fuzz::Cloud cloud;
  const bool loaded = mid::fuzz::loadRGBDBytes (data, size, cloud);
  if (!mid::fuzz::keepsTheContract (loaded, cloud))
    std::abort();
  return 0;
}
