#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>

#include <string>

namespace mid {

/** \brief Finds the copies of a model that show none of its landmarks, and when asked the
  * objects that repeat without any two copies showing the same surface, by the size of the box
  * they occupy on the support plane (not in the paper).
  *
  * A copy lying with a face up that no other copy shows has nothing to match: no descriptor,
  * no cluster, no RANSAC can find it, whatever the method's thresholds (on the benchmark, most
  * of the instances that share fewer than 10 cm^2 of textured surface with any other copy).
  * Its depth still says that it is a box of the model's size. This step:
  *
  * 1. fits the frame's support plane and measures the box each model's copies occupy on it
  *    (measureModelSizes()); a model takes part when at least `min_agreeing` of its measured
  *    copies agree on one size;
  * 2. grows the surfaces of all instances and of every keypoint that no instance observes at
  *    once (growInstanceSurfaces(): stopped at creases and depth steps), and joins the
  *    surfaces that touch along a border (touchingSurfaces(), 3 pairs of neighbouring pixels
  *    at least: two objects that touch at a point stay apart) into objects; and once more
  *    with the points inside the boxes of
  *    the found copies of the measured models (their poses times the model's box, grown by
  *    2 mm) left out, so that a copy touching a found one flush, their surfaces one, is
  *    measured on its own part alone;
  * 3. fits a box to each object that holds no instance's keypoint and at least
  *    `min_keypoints` free keypoints, and gives it to the model whose size it agrees with
  *    (the closest, edge by edge, if several do), else to a model whose size rests on one
  *    measured copy alone and which has another measured copy of the object's size
  *    (boxOfSize(): no two of its copies agree, as all but one are joined with a neighbour or
  *    hidden in part, and with the object two do), as a new instance, the objects beside the
  *    found copies first, none that shares a keypoint with an instance added before, and
  *    none where one of the model's instances lies already (its box centre within 0.8
  *    shortest edges of the object's: the object is that copy seen again). Its
  *    pose is the one that brings the model's box onto the object's, right up to the box's
  *    symmetries (a half turn of a box, a quarter turn of a square one; which face the copy
  *    shows is what is not known); its free keypoints become landmarks of the model, with
  *    their descriptors. An object of no model's size whose height is an edge of a model's
  *    box may be copies of it touching each other flush: splitFootprint() cuts its footprint
  *    into the box's rectangles, and each part, measured on its own outline (the points
  *    nearest its rectangle), joins the model when it has its size. When no such cut does,
  *    a copy joined with a box of another height may show its flat top at one of the box's
  *    edges (flatTopParts()): the part under that top, measured on its own, joins the model
  *    when it has its size;
  * 4. with setDiscoverModels(), groups the objects (as they lie) of no model's size, sharing
  *    no keypoint with an instance, whose shortest edge is at least `min_model_edge` and,
  *    when asked (setMaxSurroundedShare() below 1), that stand alone on the plane (at most
  *    `max_surrounded_share` of the pixels around their surface hold something else than
  *    the plane and the object's own box: not in a pile, a bin or a row of touching
  *    objects), by size: two or more of one size (or two that no other agrees with, at 1.5
  *    times the tolerances, whose colours overlap by half at least, when the frame's
  *    chromaticities are given: copies measured a little off, a hidden end or a rim that
  *    shows)
  *    become a new model, in the box frame of the copy with the most keypoints,
  *    each copy an instance posed by its box (up to the box's symmetries), all their
  *    keypoints landmarks. Such a group also cuts, as in step 3, the other objects of no
  *    model's size (standing alone or not) that are two or more of its copies touching each
  *    other flush, largest groups first. The size of an object seen once cuts nothing: a
  *    box of another size that two of its footprints tile (a cookie box, two juice cartons
  *    lying flush) is too common. But a group, even of one object, takes a copy of its size
  *    that an object of no model's size holds, joined with a box of another height, whose
  *    flat top shows at the copy's height (flatTopParts(); the part under it, measured on
  *    its own, has the size; the rest of that object is not looked at again), and a group
  *    of two or more takes an object that is a copy of its size hidden in part by something
  *    in front (as below) and whose colours overlap its first copy's by half, its box
  *    completed. What is left may be copies of one box joined with each other, none seen
  *    alone. With their tops at the heights of different edges (one standing, one lying),
  *    each top suggests a box (flatTopSizes()), and when two or more of the parts under the
  *    tops of one suggestion (flatTopParts()), measured on their own, agree in size (a
  *    keypoint two hold is neither's), they make a model (or join the model of their size).
  *    With their tops at one
  *    height: when the object's footprint is no rectangle (no one box could have made it)
  *    and nothing in front hides much of its outline (occludedOutlineShare()), the edges of
  *    its outline between right angles give the copies' rectangle (footprintCopySizes()),
  *    the object's height the third edge, and a cut into parts of one size, which do not
  *    tile a rectangle (rectanglesFill()), makes a model of them. Last, two of the objects
  *    that may found a model and are left, one a copy of the other's box that something in
  *    front hides at one end (their boxes agree on two edges, its third is 60 % of the
  *    other's at least, and half of its outline at that end lies beside a nearer point,
  *    occludedOutline()), whose colours overlap by half (with the frame's chromaticities),
  *    make a model in the frame of the whole one, the hidden copy's box lengthened beyond
  *    the hidden end. Two objects of a new model that may be the two ends of one box that
  *    something in front hides in the middle (of one cross-section, on one axis, with
  *    something nearer the camera between them) are one object seen twice: the second is no
  *    copy.
  *
  * An object touching another is measured with it and agrees with no model's size, unless
  * the other is a found copy of a measured model, both are copies of one touching flush, or
  * the object shows its flat top beside a box of another height;
  * an object occluded in part is measured too small, and is left alone unless a copy seen
  * whole that looks like it (step 4) gives it its length. A product of
  * another type that has the same size within the tolerance is taken for a copy, and so are
  * touching boxes of another size whose footprint the model's rectangles tile and whose
  * parts have its size: the step trades those for the copies that show an unmatched face,
  * far more common on a table of several copies of one product. The models of step 4 rest on
  * the size alone: two different products of one size standing apart become one model,
  * which is why it is asked for separately, and why it keeps to edges that the tolerance
  * measures well: in a pile or a bin the surfaces are fragments, and thin fragments agree in
  * size by chance (without the edge bound, the real Zivid bin of pins and pulleys gave five
  * models of fragments). Whether an object stands alone mattered less than the edge: with
  * the edge bound, asking for it (0.25) kept every real frame as it was and lost copies in
  * the benchmark's piles (doc/benchmark.md, session 35).
  * Deterministic (the plane's hypotheses are drawn with a fixed seed).
  */
class SizeInstanceSearch : public ModelSizeMeasurement
{
public:
  /** \brief The keypoints' descriptors (one per keypoint), which the new landmarks keep.
    * Required.
    */
  ///@{
  void
  setInputDescriptors (const SIFTDescriptorCloud::ConstPtr& descriptors)
  {
    descriptors_ = descriptors;
  }
  const SIFTDescriptorCloud::ConstPtr&
  getInputDescriptors () const
  {
    return descriptors_;
  }
  ///@}

  /** \brief Free keypoints an object must hold to become an instance (default 2, >= 1): what
    * the instance reports as its keypoints, and a guard against plain boxes.
    */
  ///@{
  void
  setMinKeypoints (int count)
  {
    min_keypoints_ = count;
  }
  int
  getMinKeypoints () const
  {
    return min_keypoints_;
  }
  ///@}

  /** \brief Also make models of the objects that share a size that no model has (step 4
    * above; default false).
    */
  ///@{
  void
  setDiscoverModels (bool discover)
  {
    discover_models_ = discover;
  }
  bool
  getDiscoverModels () const
  {
    return discover_models_;
  }
  ///@}

  /** \brief Largest share of the pixels around an object's surface (within 4 pixels) that may
    * hold a point off the support plane (farther than twice the plane tolerance from it) and
    * outside the object's box (grown by 3 mm: the steep sides of a can, where its surface
    * did not grow, are its own) for the object to stand alone (default 1: any object; in
    * [0, 1]; missing depth counts as free). Isolated cartons on a table measure 0 to 0.01,
    * the fragments of a pile 0.29 to 1 (session 29, before the own box was left out).
    */
  ///@{
  void
  setMaxSurroundedShare (float share)
  {
    max_surrounded_share_ = share;
  }
  float
  getMaxSurroundedShare () const
  {
    return max_surrounded_share_;
  }
  ///@}

  /** \brief Shortest edge of an object that may found a model by its size (metres, default
    * 0.03, >= 0): five times the default size tolerance, below which sizes agree by chance.
    */
  ///@{
  void
  setMinModelEdge (float edge)
  {
    min_model_edge_ = edge;
  }
  float
  getMinModelEdge () const
  {
    return min_model_edge_;
  }
  ///@}

  /** \brief Add the copies found by their size to the models, and the models found by size.
    * \param[in,out] models the frame's models; each keeps its instances and landmarks, in
    * order, and gains the instances found (after its own) and their keypoints as landmarks,
    * in its own frame (not centred again: centerModelFrame()); the new models
    * (setDiscoverModels()), centred on their landmarks, come after them. An object whose box
    * holds a keypoint of an instance is no copy (cut by its outline, its parts may be, if
    * their boxes hold none). Without a support plane, or
    * without a model of a measured size and without setDiscoverModels(), nothing changes.
    * \param[out] found how many instances were added, to old models and in new ones
    * \return false (with a PCL_ERROR, models unchanged, found 0) on missing or inconsistent
    * input, a parameter out of range, or an observation outside the keypoints
    */
  bool
  search (ObjectModels& models, std::size_t& found) const;

private:
  /** \brief What is wrong with the input, parameters or `models`; empty if nothing. */
  std::string
  inputProblem (const ObjectModels& models) const;

  SIFTDescriptorCloud::ConstPtr descriptors_;
  int min_keypoints_ = 2;
  bool discover_models_ = false;
  float max_surrounded_share_ = 1.0f;
  float min_model_edge_ = 0.03f;
};

} // namespace mid
