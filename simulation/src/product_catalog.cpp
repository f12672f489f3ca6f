#include <mid/simulation/box_shape.h>
#include <mid/simulation/cylinder_shape.h>
#include <mid/simulation/print_texture.h>
#include <mid/simulation/procedural_texture.h>
#include <mid/simulation/product_catalog.h>
#include <mid/simulation/texture.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>

namespace mid {
namespace simulation {

namespace {

constexpr double kPi = 3.14159265358979323846;

/** The photographs, in the order loadPhotos() returns them. */
enum Photo { APPLE_JUICE = 0, ORANGE_JUICE = 1, COOKIE_BOX = 2, SOY_MILK = 3 };

bool
loadPhotos (const std::string& texture_dir, std::vector<cv::Mat>& photos)
{
  const char* const names[] = {CARTON_FRONT_TEXTURE,
                               CARTON_BACK_TEXTURE,
                               COOKIE_BOX_TEXTURE,
                               SOY_MILK_LABEL_TEXTURE};
  photos.clear();
  for (const char* name : names) {
    cv::Mat photo;
    if (!loadTexture (texture_dir + "/" + name, photo))
      return false;
    photos.push_back (photo);
  }
  return true;
}

/** The label centred on a canvas of its border colour, as wide as aspect times its height:
  * a can's side texture that shows the label once, undistorted.
  */
cv::Mat
makeLabelTexture (const cv::Mat& label, double aspect)
{
  const int width =
      std::max (label.cols, static_cast<int> (std::lround (aspect * label.rows)));
  const cv::Scalar border =
      cv::mean (label.colRange (0, 1)) * 0.5 +
      cv::mean (label.colRange (label.cols - 1, label.cols)) * 0.5;
  cv::Mat canvas (label.rows, width, CV_8UC3, border);
  label.copyTo (canvas.colRange ((width - label.cols) / 2,
                                 (width - label.cols) / 2 + label.cols));
  return canvas;
}

/** Side face of a carton: a printed noise pattern between a colour and an off-white. */
cv::Mat
makeCartonSide (const cv::Vec3b& color, const cv::Vec3b& light, std::uint32_t seed)
{
  return makeNoiseTexture (120, 343, 24.0, 24.0, color, light, seed);
}

/** Pixels per metre of the printed faces: finer than any camera sees them at 0.5 m. */
constexpr double kPrintResolution = 3500.0;

/** Colours of a printed face. */
struct PrintColors
{
  cv::Vec3b paper, ink, accent;
};

/** A printed face of the given size (metres), at kPrintResolution. */
cv::Mat
makePrint (double width, double height, const PrintColors& colors, std::uint32_t seed)
{
  return makePrintTexture (static_cast<int> (std::lround (width * kPrintResolution)),
                           static_cast<int> (std::lround (height * kPrintResolution)),
                           colors.paper,
                           colors.ink,
                           colors.accent,
                           seed);
}

/** Colours of the printed faces of the cartons (BGR: paper, ink, accent) and the tea box. */
const PrintColors kApplePrint = {{235, 245, 240}, {40, 60, 30}, {40, 150, 60}};
const PrintColors kOrangePrint = {{225, 240, 250}, {30, 40, 90}, {20, 120, 235}};
const PrintColors kSoyPrint = {{240, 240, 235}, {110, 60, 20}, {170, 110, 40}};
const PrintColors kTeaPrint = {{200, 225, 235}, {30, 30, 110}, {40, 30, 150}};

/** A carton standing along z: front photo on -y, back photo on +y, printed sides. */
BoxShape::Ptr
makeCarton (const std::string& name,
            double width,
            double height,
            const cv::Mat& front,
            const cv::Mat& back,
            const cv::Mat& side_pos_x,
            const cv::Mat& side_neg_x)
{
  auto carton = std::make_shared<BoxShape> (width, width, height);
  carton->setName (name);
  carton->setTexture (makeUniformTexture (cv::Vec3b (225, 230, 232)));
  carton->setFaceTexture (BoxShape::NEG_Y, front);
  carton->setFaceTexture (BoxShape::POS_Y, back);
  carton->setFaceTexture (BoxShape::POS_X, side_pos_x);
  carton->setFaceTexture (BoxShape::NEG_X, side_neg_x);
  return carton;
}

Eigen::Matrix3d
rotation (double angle_deg, const Eigen::Vector3d& axis)
{
  return Eigen::AngleAxisd (angle_deg * kPi / 180.0, axis).toRotationMatrix();
}

/** A carton lies on any of its four long sides, or stands with its front to the camera. */
std::vector<RestingOrientation>
cartonRests ()
{
  std::vector<RestingOrientation> rests;
  rests.reserve (5);
  for (int spin = 0; spin < 4; ++spin)
    rests.push_back ({rotation (90.0, Eigen::Vector3d::UnitY()) *
                          rotation (90.0 * spin, Eigen::Vector3d::UnitZ()),
                      Eigen::Vector3d::Zero(),
                      true});
  rests.push_back ({Eigen::Matrix3d::Identity(), -Eigen::Vector3d::UnitY(), false});
  return rests;
}

ProductType
makeProduct (int id,
             const Shape::Ptr& shape,
             const Eigen::Vector3d& size,
             const std::vector<RestingOrientation>& rests,
             const std::vector<std::string>& photos)
{
  ProductType product;
  product.id = id;
  product.shape = shape;
  product.size = size;
  product.rests = rests;
  product.photos = photos;
  return product;
}

ProductType
makeCartonProduct (int id,
                   const BoxShape::Ptr& box,
                   const std::vector<std::string>& photos)
{
  return makeProduct (id, box, box->getSize(), cartonRests(), photos);
}

ProductType
makeCookieBox (const cv::Mat& top)
{
  auto box = std::make_shared<BoxShape> (0.16, 0.11, 0.05);
  box->setName ("cookie_box");
  box->setTexture (makeUniformTexture (cv::Vec3b (120, 150, 175)));
  box->setFaceTexture (BoxShape::POS_Z, top);
  // Flat, or on its long edge with the picture to the camera.
  return makeProduct (
      PRODUCT_COOKIE_BOX,
      box,
      box->getSize(),
      {{Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), true},
       {rotation (90.0, Eigen::Vector3d::UnitX()), Eigen::Vector3d::UnitZ(), false}},
      {COOKIE_BOX_TEXTURE});
}

ProductType
makeCan (const cv::Mat& label)
{
  constexpr double radius = 0.035, height = 0.16;
  auto can = std::make_shared<CylinderShape> (radius, height);
  can->setName ("soy_milk_can");
  can->setTexture (makeUniformTexture (cv::Vec3b (200, 205, 210)));
  can->setFaceTexture (CylinderShape::SIDE,
                       makeLabelTexture (label, 2.0 * kPi * radius / height));
  // Standing with the label (model +x) to the camera, or lying with the label up.
  return makeProduct (PRODUCT_SOY_MILK_CAN,
                      can,
                      Eigen::Vector3d (2.0 * radius, 2.0 * radius, height),
                      {{Eigen::Matrix3d::Identity(), Eigen::Vector3d::UnitX(), true},
                       {rotation (90.0, Eigen::Vector3d::UnitY()) *
                            rotation (180.0, Eigen::Vector3d::UnitZ()),
                        Eigen::Vector3d::Zero(),
                        false}},
                      {SOY_MILK_LABEL_TEXTURE});
}

ProductType
makeTeaBox ()
{
  auto box = std::make_shared<BoxShape> (0.13, 0.075, 0.095);
  box->setName ("tea_box");
  // Printed all over: front and back (x by z), sides (y by z), top and bottom (x by y).
  const Eigen::Vector3d& size = box->getSize();
  for (int face = 0; face < BoxShape::FACE_COUNT; ++face) {
    const double width =
        face == BoxShape::POS_X || face == BoxShape::NEG_X ? size.y() : size.x();
    const double height = face >= BoxShape::POS_Z ? size.y() : size.z();
    box->setFaceTexture (
        static_cast<BoxShape::Face> (face),
        makePrint (width, height, kTeaPrint, static_cast<std::uint32_t> (701 + face)));
  }
  return makeProduct (
      PRODUCT_TEA_BOX,
      box,
      box->getSize(),
      {{Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), true},
       {rotation (90.0, Eigen::Vector3d::UnitX()), Eigen::Vector3d::Zero(), true}},
      {});
}

ProductType
makeMug ()
{
  constexpr double radius = 0.041, height = 0.095;
  auto mug = std::make_shared<CylinderShape> (radius, height);
  mug->setName ("mug");
  mug->setTexture (makeUniformTexture (cv::Vec3b (150, 110, 60)));
  mug->setFaceTexture (CylinderShape::SIDE,
                       makeNoiseTexture (520,
                                         190,
                                         40.0,
                                         25.0,
                                         cv::Vec3b (120, 60, 20),
                                         cv::Vec3b (210, 190, 150),
                                         801));
  return makeProduct (PRODUCT_MUG,
                      mug,
                      Eigen::Vector3d (2.0 * radius, 2.0 * radius, height),
                      {{Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), true}},
                      {});
}

} // namespace

bool
makeProductCatalog (const std::string& texture_dir, ProductCatalog& catalog)
{
  catalog.clear();
  std::vector<cv::Mat> photos;
  if (!loadPhotos (texture_dir, photos)) {
    PCL_ERROR (
        "[mid::simulation::makeProductCatalog] cannot read the textures in '%s'\n",
        texture_dir.c_str());
    return false;
  }
  catalog.push_back (makeCartonProduct (
      PRODUCT_JUICE_CARTON,
      makeCarton (
          "juice_carton",
          0.07,
          0.2,
          photos[APPLE_JUICE],
          photos[ORANGE_JUICE],
          makeCartonSide (cv::Vec3b (40, 120, 50), cv::Vec3b (215, 235, 235), 101),
          makeCartonSide (cv::Vec3b (20, 80, 190), cv::Vec3b (210, 230, 240), 102)),
      {CARTON_FRONT_TEXTURE, CARTON_BACK_TEXTURE}));
  catalog.push_back (makeCookieBox (photos[COOKIE_BOX]));
  catalog.push_back (makeCan (photos[SOY_MILK]));
  catalog.push_back (
      makeCartonProduct (PRODUCT_APPLE_JUICE_SMALL,
                         makeCarton ("apple_juice_small",
                                     0.055,
                                     0.157,
                                     photos[APPLE_JUICE],
                                     makePrint (0.055, 0.157, kApplePrint, 401),
                                     makePrint (0.055, 0.157, kApplePrint, 402),
                                     makePrint (0.055, 0.157, kApplePrint, 403)),
                         {CARTON_FRONT_TEXTURE}));
  catalog.push_back (
      makeCartonProduct (PRODUCT_ORANGE_JUICE_LARGE,
                         makeCarton ("orange_juice_large",
                                     0.084,
                                     0.24,
                                     photos[ORANGE_JUICE],
                                     makePrint (0.084, 0.24, kOrangePrint, 501),
                                     makePrint (0.084, 0.24, kOrangePrint, 502),
                                     makePrint (0.084, 0.24, kOrangePrint, 503)),
                         {CARTON_BACK_TEXTURE}));
  catalog.push_back (
      makeCartonProduct (PRODUCT_SOY_MILK_CARTON,
                         makeCarton ("soy_milk_carton",
                                     0.066,
                                     0.189,
                                     photos[SOY_MILK],
                                     makePrint (0.066, 0.189, kSoyPrint, 601),
                                     makePrint (0.066, 0.189, kSoyPrint, 602),
                                     makePrint (0.066, 0.189, kSoyPrint, 603)),
                         {SOY_MILK_LABEL_TEXTURE}));
  catalog.push_back (makeTeaBox());
  catalog.push_back (makeMug());
  return true;
}

} // namespace simulation
} // namespace mid
