// SPDX-License-Identifier: GPL-3.0-or-later
// Stage 4 of the robust method: the poles labelled inner or outer by confidence, not by arrival.
//
// Why: the paper's breadth-first separation (section 3.1.1) keeps the first label a pole is
// offered. On real input some samples have both poles on one side (sharp CAD edges, sparse
// fingers, nearly touching strands); one such wrong offer early is spread by the cube and pairing
// rules to hundreds of poles. Amenta, Choi and Kolluri's power crust (2001, section 5) labels
// instead in order of confidence, with a priority queue; we do the same with their evidence:
//
//   same side:  two polar balls through one sample s that meet deeply. The weight is the cosine
//               of the angle between their radii at s, cos(p s q), which is also the cosine of
//               the balls' intersection angle: 1 for tangent balls, 0 at right angles.
//   opposite:   the two poles of one sample, when they are roughly antipodal (the pair filter:
//               cos(p+ s p-) <= -0.7); weight -cos(p+ s p-). A sample whose poles are not
//               antipodal (at a sharp edge, in a thin part) says nothing about sides.
//   seeds:      the convex poles (their cells touch the box) are outer, with weight 1.
//
// Every pole keeps the strongest evidence for each side it was offered. The queue pops the pole
// whose evidence is most one-sided, the largest |outer - inner|; it is labelled by the stronger
// side and offers its label to its neighbours. A pole is "contradicted" (recorded as a conflict)
// when it was labelled despite strong evidence for the other side (at least strong_evidence), or
// when such evidence, at least as strong as its own, arrives after it was labelled.
#pragma once

#include <algorithm>
#include <cmath>
#include <queue>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <vector>

#include "../../core/prefetch.hpp"
#include "../../core/seeds.hpp"
#include "../../core/stage_clock.hpp"

namespace sculpt {

// Below this cosine the two poles of a sample count as antipodal (robust.md: -0.5 ... -0.9
// behave alike).
constexpr double antipodal_pair_cosine = -0.7;

// Evidence this strong for the side a pole did not get makes the pole "contradicted".
constexpr float strong_evidence = 0.5f;

// The evidence between poles: for each pole, its neighbours with a weight and whether the
// evidence says "same side" or "opposite sides". Compressed rows.
struct Pole_evidence {
  // 8 bytes: the labelling reads the links of each pole it pops, in no order the memory likes.
  struct Link {
    int key;  // 2 pole + 1 if the evidence says "opposite sides"
    float weight;
    int pole() const { return key >> 1; }
    bool opposite() const { return key & 1; }
  };
  std::vector<int> offsets;
  std::vector<Link> links;
};

// Links pole p to the poles of the samples on its ball (the vertices of its Delaunay cell): both
// balls pass through that sample, so the angle between them there is the evidence.
template <int D>
Pole_evidence pole_evidence(const Reconstruction<D>& result) {
  const auto& stage = result.poles;
  const int n = static_cast<int>(stage.positive_pole.size());
  const int pole_count = static_cast<int>(stage.poles.size());
  // Each piece of evidence, found twice (cheap: a cosine): once to count the links of every
  // pole, once to file them in compressed rows, both directions. Keeping the list between the
  // two would cost more memory than the links themselves. What a sample lends to the evidence
  // (its position, its poles and their centres) is gathered in one record per sample: the poles
  // name their samples in no useful order, and one record is one or two cache lines where the
  // scattered arrays were five (bunny00 subdivided: the evidence 0.20 -> 0.13 s).
  struct Sample_poles {
    Point<D> sample;
    Point<D> center[2];  // of p+ and p-
    int pole[2];         // p+ and p- (-1: none)
  };
  std::vector<Sample_poles> around(n);
  for (int s = 0; s < n; ++s) {
    around[s].sample = result.sites[s];
    around[s].pole[0] = stage.positive_pole[s];
    around[s].pole[1] = stage.negative_pole[s];
    for (int j = 0; j < 2; ++j) {
      if (around[s].pole[j] >= 0) around[s].center[j] = stage.poles[around[s].pole[j]].center;
    }
  }
  const auto for_each_evidence = [&](auto&& use) {
    for (int p = 0; p < pole_count; ++p) {
      if (p + 1 < pole_count) {  // the next pole's records, while this one's are read
        for (int s : stage.poles[p + 1].sites) {
          if (s < n) prefetch(&around[s]);
        }
      }
      const Point<D>& p_center = stage.poles[p].center;
      for (int s : stage.poles[p].sites) {
        if (s >= n) continue;  // a box corner
        const Sample_poles& at = around[s];
        for (int j = 0; j < 2; ++j) {
          const int q = at.pole[j];
          if (q < 0 || q == p) continue;
          double dot = 0, a2 = 0, b2 = 0;
          for (int k = 0; k < D; ++k) {
            const double a = p_center[k] - at.sample[k];
            const double b = at.center[j][k] - at.sample[k];
            dot += a * b;
            a2 += a * a;
            b2 += b * b;
          }
          if (a2 <= 0 || b2 <= 0) continue;
          const double cosine = dot / std::sqrt(a2 * b2);
          const int plus = at.pole[0], minus = at.pole[1];
          const bool pair = (p == plus && q == minus) || (p == minus && q == plus);
          if (pair && cosine <= antipodal_pair_cosine) {
            use(p, q, float(-cosine), true);
          } else if (!pair && cosine > 0) {
            use(p, q, float(cosine), false);
          }
        }
      }
    }
  };
  Pole_evidence evidence;
  auto& offsets = evidence.offsets;
  offsets.assign(pole_count + 1, 0);
  for_each_evidence([&](int p, int q, float, bool) {
    ++offsets[p + 1];
    ++offsets[q + 1];
  });
  for (int p = 0; p < pole_count; ++p) offsets[p + 1] += offsets[p];
  using Link = Pole_evidence::Link;
  std::vector<Link> links(offsets.back());
  {
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for_each_evidence([&](int p, int q, float weight, bool opposite) {
      links[fill[p]++] = {2 * q + opposite, weight};
      links[fill[q]++] = {2 * p + opposite, weight};
    });
  }
  // Per pole, one link per (neighbour, kind), with the strongest weight, in that order.
  const auto before = [](const Link& a, const Link& b) {
    return a.key != b.key ? a.key < b.key : a.weight > b.weight;
  };
  const auto same = [](const Link& a, const Link& b) { return a.key == b.key; };
  std::size_t kept = 0;
  for (int p = 0; p < pole_count; ++p) {
    const auto first = links.begin() + offsets[p], last = links.begin() + offsets[p + 1];
    std::sort(first, last, before);
    offsets[p] = static_cast<int>(kept);  // rows only shrink: compacting in place is safe
    for (auto link = first; link != last; ++link) {
      if (link != first && same(*(link - 1), *link)) continue;
      links[kept++] = *link;
    }
  }
  offsets[pole_count] = static_cast<int>(kept);
  links.resize(kept);
  links.shrink_to_fit();
  evidence.links = std::move(links);
  return evidence;
}

template <int D>
class Confidence_labelling {
 public:
  Confidence_labelling(Reconstruction<D>& result, const Pole_evidence& evidence,
                       const Stage_clock& clock)
      : stage_(result.propagation),
        evidence_(evidence),
        clock_(clock),
        pole_count_(static_cast<int>(result.poles.poles.size())),
        offers_(static_cast<std::size_t>(pole_count_)) {
    stage_.labels.assign(pole_count_, Label::unlabelled);
  }

  void run(const Seeds_stage& seeds) {
    for (int seed : seeds.outer_seeds) {
      offers_[seed].side[side(Label::outer)] = {1.0f, -1, Label_reason::convex_seed};
      queue_.push({seed_priority, seed});
    }
    std::size_t popped = 0;
    while (!queue_.empty()) {
      const auto [priority, pole] = queue_.top();
      queue_.pop();
      if (stage_.labels[pole] != Label::unlabelled) continue;
      if (priority != seed_priority && priority != confidence(pole)) {
        continue;  // a stale entry: the pole has been offered stronger evidence since
      }
      // The pole most likely popped next: its label, offers and row of evidence, asked for
      // while this one is labelled (the poles are popped in no order the memory likes).
      // A 1M-point random torus: the stage 1.44-1.50 -> 1.26-1.27 s.
      if (!queue_.empty()) {
        const int next = queue_.top().pole;
        prefetch(&stage_.labels[next]);
        prefetch(&offers_[next]);
        prefetch(evidence_.links.data() + evidence_.offsets[next]);
      }
      label(pole);
      if (++popped % 65536 == 0) clock_.report(double(popped) / double(pole_count_));
    }
    for (Label label : stage_.labels) stage_.unlabelled += label == Label::unlabelled;
  }

 private:
  struct Offer {
    float weight = 0;
    int source = -1;
    Label_reason reason = Label_reason::pairing;
  };
  struct Offers {
    Offer side[2];  // strongest evidence for inner (0) and outer (1)
  };
  struct Entry {
    float priority;
    int pole;
    bool operator<(const Entry& other) const { return priority < other.priority; }
  };

  static constexpr float seed_priority = 2;  // seeds first: evidence weighs at most 1

  static int side(Label label) { return label == Label::outer ? 1 : 0; }
  static Label label_of_side(int s) { return s == 1 ? Label::outer : Label::inner; }

  float confidence(int pole) const {
    return std::abs(offers_[pole].side[1].weight - offers_[pole].side[0].weight);
  }

  void label(int pole) {
    const Offers& offers = offers_[pole];
    const int winner = offers.side[1].weight >= offers.side[0].weight ? 1 : 0;
    const Label label = label_of_side(winner);
    const Offer& why = offers.side[winner];
    stage_.labels[pole] = label;
    stage_.events.push_back({pole, label, why.source, why.reason, why.weight});
    const Offer& against = offers.side[1 - winner];
    if (against.weight >= strong_evidence) {
      stage_.conflicts.push_back({pole, label_of_side(1 - winner), against.source, against.reason,
                                  against.weight, long(stage_.events.size())});
    }

    // The neighbours' labels and offers lie anywhere in memory: asked for together first.
    for (int i = evidence_.offsets[pole]; i < evidence_.offsets[pole + 1]; ++i) {
      const int other = evidence_.links[i].pole();
      prefetch(&stage_.labels[other]);
      prefetch(&offers_[other]);
    }
    for (int i = evidence_.offsets[pole]; i < evidence_.offsets[pole + 1]; ++i) {
      const auto& link = evidence_.links[i];
      const int other = link.pole();
      const Label offered = link.opposite() ? opposite(label) : label;
      const Label_reason reason =
          link.opposite() ? Label_reason::pairing : Label_reason::ball_overlap;
      const Label current = stage_.labels[other];
      if (current == Label::unlabelled) {
        Offer& offer = offers_[other].side[side(offered)];
        if (link.weight > offer.weight) {
          offer = {link.weight, pole, reason};
          queue_.push({confidence(other), other});
        }
      } else if (current != offered && link.weight >= strong_evidence &&
                 link.weight >= offers_[other].side[side(current)].weight) {
        stage_.conflicts.push_back(
            {other, offered, pole, reason, link.weight, long(stage_.events.size())});
      }
    }
  }

  Propagation_stage& stage_;
  const Pole_evidence& evidence_;
  const Stage_clock& clock_;
  int pole_count_;
  std::vector<Offers> offers_;
  std::priority_queue<Entry> queue_;
};

// Stage 4 of the robust method and of the power crust: every pole labelled, seeds first.
template <int D>
void label_poles_by_confidence(Reconstruction<D>& result, const Stage_clock& clock) {
  const Pole_evidence evidence = pole_evidence(result);
  Confidence_labelling<D>(result, evidence, clock).run(result.seeds);
}

}  // namespace sculpt
