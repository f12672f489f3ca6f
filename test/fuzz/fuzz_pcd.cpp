// libFuzzer target: arbitrary bytes as a PCD file, through mid::io::loadOrganizedPCD.
//   build-fuzz/test/fuzz/fuzz_pcd NEW_CORPUS_DIR test/fuzz/corpus/pcd -max_total_time=60
#include "fuzz_inputs.h"

#include <pcl/console/print.h>

#include <cstdlib>

extern "C" int
LLVMFuzzerInitialize (int* /*argc*/, char*** /*argv*/)
{
  // One PCL_ERROR line per refused input would make the run I/O-bound.
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  return 0;
}

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  mid::fuzz::Cloud cloud;
  const bool loaded = mid::fuzz::loadPCDBytes (data, size, cloud);
  if (!mid::fuzz::keepsTheContract (loaded, cloud))
    std::abort();
  return 0;
}
