#pragma once

// Layouts of the benchmark scenes: scattered objects (apart, or touching earlier ones) and
// regular rows. Used by benchmark_scene.cpp; not installed.

#include "table_layout.h"

#include <vector>

namespace mid {
namespace simulation {

/** An object to place: its footprint's half extents and height, and the direction (angle in
  * the table plane before the heading is applied) that should face the camera.
  */
struct LayoutItem
{
  Footprint shape;
  bool has_front = false;
  double front_angle = 0.0;
};

/** How scattered objects are placed. */
struct ScatterStyle
{
  /** Smallest gap between objects that are not put in contact, metres. */
  double gap = 0.04;
  /** Chance that an object is put against one placed before it (aligned with it, 0.5 mm
    * apart); when no such spot is free, it is placed apart. */
  double touch_probability = 0.0;
};

/** Place the items, largest first, at random free spots (heading uniform, or towards the
  * camera within +-30 deg for items with a front), some in contact as the style says; starts
  * over when one does not fit. layout[i] belongs to items[i]; false if no layout was found.
  */
bool
layoutScattered (const std::vector<LayoutItem>& items,
                 const PlacementView& view,
                 const ScatterStyle& style,
                 DeterministicRandom& random,
                 std::vector<Footprint>& layout);

/** One regular row: count copies of one item, equal gaps, one heading. */
struct RowSpec
{
  LayoutItem item;
  int count = 0;
  double gap = 0.01;
};

/** Place the rows (each at a random free spot, its items side by side perpendicular to their
  * front, or along a random footprint axis); layout holds the footprints row after row.
  * False if no layout was found.
  */
bool
layoutRows (const std::vector<RowSpec>& rows,
            const PlacementView& view,
            DeterministicRandom& random,
            std::vector<Footprint>& layout);

} // namespace simulation
} // namespace mid
