// Writes the seed corpus of the fuzz targets: tiny valid inputs in every encoding the input
// path reads. Run from the repository root after changing the input formats:
//   build-fuzz/test/fuzz/make_fuzz_corpus test/fuzz/corpus
#include "fuzz_inputs.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/io/pcd_io.h>

#include <cstdio>
#include <exception>
#include <fstream>
#include <string>

namespace {

/** A 4 x 3 frame at about 1 m, one pixel without depth. */
void
makeFrame (cv::Mat& color, cv::Mat& depth)
{
  color.create (3, 4, CV_8UC3);
  depth.create (3, 4, CV_16UC1);
  for (int v = 0; v < 3; ++v)
    for (int u = 0; u < 4; ++u) {
      color.at<cv::Vec3b> (v, u) =
          cv::Vec3b (static_cast<uchar> (60 * u), static_cast<uchar> (80 * v), 200);
      depth.at<std::uint16_t> (v, u) =
          u == 3 && v == 2 ? 0 : static_cast<std::uint16_t> (1000 + 10 * (v * 4 + u));
    }
}

bool
writeBytes (const std::string& path, const mid::fuzz::Bytes& bytes)
{
  std::ofstream file (path, std::ios::binary);
  file.write (reinterpret_cast<const char*> (bytes.data()),
              static_cast<std::streamsize> (bytes.size()));
  return file.good();
}

mid::fuzz::Bytes
encode (const char* extension, const cv::Mat& image)
{
  std::vector<uchar> bytes;
  cv::imencode (extension, image, bytes);
  return {bytes.begin(), bytes.end()};
}

/** Writes the seed corpus into `dir`; 0 on success. */
int
writeCorpus (const std::string& dir)
{
  cv::Mat color, depth, gray;
  makeFrame (color, depth);
  cv::cvtColor (color, gray, cv::COLOR_BGR2GRAY);

  mid::fuzz::Cloud cloud;
  const mid::fuzz::Bytes depth_png = encode (".png", depth);
  const mid::fuzz::Bytes packed =
      mid::fuzz::packRGBD (encode (".png", color), depth_png);
  if (!mid::fuzz::loadRGBDBytes (packed.data(), packed.size(), cloud))
    return 1;
  pcl::PointCloud<pcl::PointXYZRGB> rgb;
  pcl::copyPointCloud (cloud, rgb);

  bool ok = writeBytes (dir + "/rgbd/bgr.bin", packed) &&
            writeBytes (dir + "/rgbd/gray.bin",
                        mid::fuzz::packRGBD (encode (".png", gray), depth_png)) &&
            writeBytes (dir + "/rgbd/jpeg.bin",
                        mid::fuzz::packRGBD (encode (".jpg", color), depth_png));
  ok = ok && pcl::io::savePCDFileASCII (dir + "/pcd/ascii_rgb.pcd", rgb) == 0 &&
       pcl::io::savePCDFileASCII (dir + "/pcd/ascii_rgba.pcd", cloud) == 0 &&
       pcl::io::savePCDFileBinary (dir + "/pcd/binary_rgb.pcd", rgb) == 0 &&
       pcl::io::savePCDFileBinaryCompressed (dir + "/pcd/compressed_rgba.pcd", cloud) ==
           0;
  return ok ? 0 : 1;
}

} // namespace

int
main (int argc, char** argv)
{
  if (argc != 2) {
    std::fprintf (
        stderr, "usage: %s CORPUS_DIR (with pcd/ and rgbd/ inside)\n", argv[0]);
    return 2;
  }
  try {
    return writeCorpus (argv[1]);
  }
  catch (
      const std::exception& error) { // OpenCV and PCL report some failures by throwing
    std::fprintf (stderr, "make_fuzz_corpus: %s\n", error.what());
    return 1;
  }
}
