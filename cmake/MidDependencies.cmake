# Every dependency comes from Debian 12's packages (see run.sh). The list of
# components here is repeated in cmake/midConfig.cmake.in for downstream projects.
set(MID_PCL_COMPONENTS common io features search kdtree registration recognition visualization)
set(MID_OPENCV_COMPONENTS core imgproc imgcodecs features2d)

find_package(PCL 1.12 REQUIRED COMPONENTS ${MID_PCL_COMPONENTS})
find_package(OpenCV 4 REQUIRED COMPONENTS ${MID_OPENCV_COMPONENTS})
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Boost 1.65 REQUIRED)   # header-only: Boost Graph (Dijkstra over the model graph)
find_package(nlohmann_json 3 REQUIRED)   # header-only: BOP and result JSON reading
