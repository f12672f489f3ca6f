#pragma once

#include <cstdint>
#include <random>

namespace mid {
namespace simulation {

/** \brief A seeded random source whose numbers are the same on every platform and standard
  * library: std::mt19937 (seeded through std::seed_seq, both fully specified by the standard)
  * with hand-written uniform and normal transforms (the std:: distributions are
  * implementation-defined).
  *
  * Independent streams of one seed (e.g. one per noise effect) are obtained with different
  * stream numbers, so that enabling one effect does not change the numbers another one draws.
  */
class DeterministicRandom
{
public:
  /** \brief Seed the generator.
    * \param[in] seed the seed
    * \param[in] stream the stream number: different streams of a seed are independent
    */
  explicit DeterministicRandom (std::uint32_t seed, std::uint32_t stream = 0);

  /** \brief The next raw 32-bit number. */
  std::uint32_t
  next ();

  /** \brief A uniform number in [0, 1) with 53 random bits. */
  double
  uniform ();

  /** \brief A uniform number in [low, high). */
  double
  uniform (double low, double high);

  /** \brief A uniform integer in [0, count); 0 if count <= 0. */
  int
  uniformInt (int count);

  /** \brief A standard normal number (Box-Muller, the second value of a pair is kept). */
  double
  normal ();

private:
  std::mt19937 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

} // namespace simulation
} // namespace mid
