// SPDX-License-Identifier: GPL-3.0-or-later
// Stages 3 and 4: the pole separation of section 3.1.1 (the paper's Fig. 5).
//
//   seeds:   (core/seeds.hpp) convex poles are outer; the poles paired with them are inner.
//   spread:  breadth first, a labelled pole p gives
//              - its own label to every pole strictly inside the inscribed cube of its polar ball
//                (half side r / sqrt(D)): the cube lies inside the ball, and a polar ball holds
//                no pole of the other side;
//              - the opposite label to the poles paired with it (the two poles of one sample lie
//                on opposite sides of the surface).
//   An offer of the other label to a pole already labelled is a conflict: it is counted and
//   recorded, and the first label stays. Without conflicts the result does not depend on order.
#pragma once

#include <cmath>
#include <deque>
#include <string>
#include <vector>

#include "../../core/seeds.hpp"
#include "../../core/stage_clock.hpp"
#include "pole_tree.hpp"

namespace sculpt {

template <int D>
class Pole_separation {
 public:
  Pole_separation(Reconstruction<D>& result, const Stage_clock& clock)
      : poles_(result.poles), stage_(result.propagation), clock_(clock), tree_(poles_.poles) {
    stage_.labels.assign(poles_.poles.size(), Label::unlabelled);
  }

  void run(const Seeds_stage& seeds) {
    // The paper initialises both seed sets before propagating: first the outer seeds, then
    // the inner seeds, their partners.
    for (int seed : seeds.outer_seeds) offer(seed, Label::outer, -1, Label_reason::convex_seed);
    for (int seed : seeds.outer_seeds) offer_to_partners(seed);
    for (std::size_t next = 0; next < stage_.events.size(); ++next) {
      const Labelling_event event = stage_.events[next];
      offer_to_cube(event.pole);
      if (event.reason != Label_reason::convex_seed) offer_to_partners(event.pole);
      if (next % 65536 == 0) clock_.report(double(next) / double(poles_.poles.size()));
    }
    for (Label label : stage_.labels) stage_.unlabelled += label == Label::unlabelled;
  }

 private:
  void offer(int pole, Label label, int source, Label_reason reason) {
    Label& current = stage_.labels[pole];
    if (current == label) return;
    if (current == Label::unlabelled) {
      current = label;
      tree_.relabel(pole, Label::unlabelled, label);
      stage_.events.push_back({pole, label, source, reason});
    } else {
      stage_.conflicts.push_back({pole, label, source, reason, 1.0f, long(stage_.events.size())});
    }
  }

  void offer_to_cube(int pole) {
    const Label label = stage_.labels[pole];
    const double half_side = poles_.poles[pole].radius / std::sqrt(double(D));
    tree_.for_each_other_label_in_cube(poles_.poles[pole].center, half_side, label, [&](int other) {
      offer(other, label, pole, Label_reason::inscribed_cube);
    });
  }

  void offer_to_partners(int pole) {
    const Label label = opposite(stage_.labels[pole]);
    for (int partner : poles_.partners_of(pole)) offer(partner, label, pole, Label_reason::pairing);
  }

  const Poles_stage<D>& poles_;
  Propagation_stage& stage_;
  const Stage_clock& clock_;
  Pole_tree<D> tree_;
};

template <int D>
void propagate_labels(Reconstruction<D>& result, const Stage_clock& clock) {
  Pole_separation<D>(result, clock).run(result.seeds);
}

}  // namespace sculpt
