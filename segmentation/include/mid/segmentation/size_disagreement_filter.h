#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>

#include <string>

namespace mid {

/** \brief Removes the models whose copies, each standing alone on the support plane and so
  * measured whole, agree on no size: the same print on different products, not one object
  * seen several times (not in the paper).
  *
  * Products of one maker share a font, a logo, lines of small text; a few matches between
  * such prints on three different boxes can pass every check of the triplets, the clusters
  * and the look, and the frame, in which nothing repeats, gets a model. The depth tells: one
  * product repeated occupies boxes of one size. But a copy in a pile is measured joined with
  * a neighbour or partly hidden, and its box is then of another size, so disagreement alone
  * proves nothing. This step only trusts boxes of copies that stand alone. For each model:
  *
  * 1. the surfaces of all instances of all models grow at once from their keypoints, and a box
  *    is fitted to each (measureInstanceBoxes());
  * 2. the model takes part when it has at least `min_copies` instances, each standing alone:
  *    at most `max_surrounded_share` of the pixels around its surface hold something else
  *    than the plane and its own box (nothing leans on it, nothing lies beside it, nothing
  *    hides it); an instance without a surface (no observations) does not stand alone;
  * 3. it is removed when no two of its boxes agree in size (the size tolerances) and at least
  *    two of them differ on every edge (SizeAgreement::differOnEveryEdge()): boxes of
  *    different products, not one box measured a little off.
  *
  * On the benchmark (four datasets, 440 frames) the rule holds for two models, both in frames
  * in which nothing repeats, and for no true one; with two copies and a 10 % bound, true pairs
  * of copies measured joined in piles qualify too (doc/model_building.md, session 43). The
  * sizes agree by the tolerances of ModelSizeMeasurement; its setMinAgreeing() plays no part
  * here (a value below 1 is still refused). Frames without a support plane are left as they
  * are. Deterministic (the plane's hypotheses are drawn with a fixed seed).
  */
class SizeDisagreementFilter : public ModelSizeMeasurement
{
public:
  /** \brief Largest share of the pixels around a copy's surface (within a few pixels of it)
    * that may hold something else than the plane and its own box, for the copy to count as
    * standing alone (default 0.05, in [0, 1]).
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

  /** \brief Fewest instances of a model that this step may judge (default 3, >= 2). */
  ///@{
  void
  setMinCopies (int copies)
  {
    min_copies_ = copies;
  }
  int
  getMinCopies () const
  {
    return min_copies_;
  }
  ///@}

  /** \brief Remove the models whose copies stand alone and agree on no size.
    * \param[in,out] models the models (their instances' keypoints index the input keypoints);
    * the remaining models keep their order
    * \param[out] removed the number of models removed
    * \return false (with a PCL_ERROR naming the problem, the models untouched, removed 0) if
    * an input or a parameter is unusable
    */
  bool
  filter (ObjectModels& models, std::size_t& removed) const;

private:
  /** \brief What is wrong with the input or the parameters; empty if nothing. */
  std::string
  inputProblem (const ObjectModels& models) const;

  float max_surrounded_share_ = 0.05f; ///< see setMaxSurroundedShare()
  int min_copies_ = 3;                 ///< see setMinCopies()
};

} // namespace mid
