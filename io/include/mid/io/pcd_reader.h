#pragma once

#include <Eigen/Geometry>
#include <pcl/PCLPointCloud2.h>

#include <string>

namespace mid {
namespace io {

/** \brief Read any PCD file (ascii, binary or binary_compressed) into a pcl::PCLPointCloud2,
  * refusing every file that PCL's own reader would mishandle.
  *
  * PCL's pcl::PCDReader trusts the header it reads: fuzzing found headers that make it allocate
  * gigabytes, read or write past its buffers, throw, or leave a blob that
  * pcl::fromPCLPointCloud2 cannot convert safely (see doc/quality_gates.md). This function accepts
  * only a header written exactly as the PCD format specifies (keywords in their order, plain
  * numbers, one value per field) that announces no more data than the file could hold, then
  * checks the field layout against the point step, a compressed body against the header, and
  * the data read against the header, before and after PCL reads it.
  * A blob it returns can be passed to pcl::fromPCLPointCloud2 for any point type. Every point
  * cloud file this project reads (frames and model data) goes through it.
  * \param[in] path the PCD file
  * \param[out] blob the points as read; cleared when false is returned
  * \param[out] origin the sensor origin of the file's VIEWPOINT line
  * \param[out] orientation the sensor orientation of the file's VIEWPOINT line
  * \param[out] problem one sentence naming the file and what is wrong with it; empty on success
  * \return true on success
  */
bool
readCheckedPCD (const std::string& path,
                pcl::PCLPointCloud2& blob,
                Eigen::Vector4f& origin,
                Eigen::Quaternionf& orientation,
                std::string& problem);

} // namespace io
} // namespace mid
