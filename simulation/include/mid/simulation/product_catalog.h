#pragma once

#include <mid/simulation/shape.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mid {
namespace simulation {

/** \brief One way a product rests on a table. */
struct RestingOrientation
{
  /** \brief Rotation from the product's model frame to the table frame (z up) before the
    * heading is applied: a signed permutation of the axes.
    */
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  /** \brief Direction in the model frame that should face the camera (the printed label), or
    * zero if any heading will do.
    */
  Eigen::Vector3d front = Eigen::Vector3d::Zero();
  /** \brief Low and natural (lying carton, flat box, standing can): used in easy scenes;
    * tall ones (a carton on its end, a box on its edge) occlude what stands behind them.
    */
  bool easy = true;
};

/** \brief A product type of the synthetic benchmark: one shape shared by all its instances. */
struct ProductType
{
  /** \brief Object id in BOP files (obj_id), 1-based; the product is catalog[id - 1]. */
  int id = 0;
  /** \brief The textured shape; its name (Shape::getName()) is the product's name. */
  Shape::Ptr shape;
  /** \brief Edge lengths of its model-frame bounding box (centred at the origin), metres. */
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  /** \brief How it may rest on the table; the first one is the most natural. */
  std::vector<RestingOrientation> rests;
  /** \brief The photographs it shows: two products sharing one look alike and are never put in
    * one benchmark scene.
    */
  std::vector<std::string> photos;
};

/** \brief The products, in id order. */
using ProductCatalog = std::vector<ProductType>;

/** \brief The product with the given id, 1 .. catalog.size() (not checked). */
inline const ProductType&
getProduct (const ProductCatalog& catalog, int id)
{
  return catalog[static_cast<std::size_t> (id - 1)];
}

/** \brief Product ids (obj_id) of makeProductCatalog(), and the number of products. */
enum ProductId {
  PRODUCT_JUICE_CARTON = 1,
  PRODUCT_COOKIE_BOX = 2,
  PRODUCT_SOY_MILK_CAN = 3,
  PRODUCT_APPLE_JUICE_SMALL = 4,
  PRODUCT_ORANGE_JUICE_LARGE = 5,
  PRODUCT_SOY_MILK_CARTON = 6,
  PRODUCT_TEA_BOX = 7,
  PRODUCT_MUG = 8,
  PRODUCT_COUNT = 8
};

/** \brief Names of the photographs makeProductCatalog() reads from its texture folder (the
  * repository's data/textures).
  */
constexpr const char* CARTON_FRONT_TEXTURE = "tropicana_apple_juice_front.jpg";
constexpr const char* CARTON_BACK_TEXTURE = "god_morgon_orange_juice_front.jpg";
constexpr const char* COOKIE_BOX_TEXTURE = "bastoncini_cookie_box.png";
constexpr const char* SOY_MILK_LABEL_TEXTURE = "alpro_soya_front.jpg";

/** \brief Build the products of the synthetic scenes (sizes in millimetres, x y z):
  *
  * | id | name | shape | photographs |
  * |---|---|---|---|
  * | 1 | juice_carton | box 70 x 70 x 200 | apple juice front, orange juice back, noise sides |
  * | 2 | cookie_box | box 160 x 110 x 50 | cookie box on top |
  * | 3 | soy_milk_can | cylinder 70 x 160 (diameter x height) | soy milk label |
  * | 4 | apple_juice_small | box 55 x 55 x 157 | apple juice front |
  * | 5 | orange_juice_large | box 84 x 84 x 240 | orange juice front |
  * | 6 | soy_milk_carton | box 66 x 66 x 189 | soy milk front |
  * | 7 | tea_box | box 130 x 75 x 95 | none (procedural pattern) |
  * | 8 | mug | cylinder 82 x 95 | none (procedural glaze) |
  *
  * Boxes show their front (the photograph) on the -y face and stand along z (BoxShape's face
  * conventions); the cookie box shows its photograph on the top face. Photographs keep their
  * aspect ratio. The other faces of the cartons are printed with noise patterns that differ
  * from face to face, so that no product looks the same after a half turn (its pose is never
  * ambiguous to appearance). Products 1 to 3 are the objects of makeTabletopScene().
  * \param[in] texture_dir folder holding the *_TEXTURE files
  * \param[out] catalog the PRODUCT_COUNT products; cleared when false is returned
  * \return false (with a PCL_ERROR) if a photograph cannot be read
  */
bool
makeProductCatalog (const std::string& texture_dir, ProductCatalog& catalog);

} // namespace simulation
} // namespace mid
