#include <mid/discovery/impl/multi_instance_discovery.hpp>

#include <pcl/point_types.h>

template class mid::MultiInstanceDiscovery<pcl::PointXYZRGB>;
template class mid::MultiInstanceDiscovery<pcl::PointXYZRGBA>;
