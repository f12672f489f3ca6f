#include <mid/features/impl/sift_keypoint_extractor.hpp>

#include <pcl/point_types.h>

template class mid::SIFTKeypointExtractor<pcl::PointXYZRGB>;
template class mid::SIFTKeypointExtractor<pcl::PointXYZRGBA>;
