#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Lesson 2: the pole separation replayed event by event (Kuo & Yau sec. 3.2).

Runs the paper's method on the built-in star and walks through its labelling events: which pole
got which label, from which pole, by which rule (a convex seed, the pairing of a sample's two
poles, or the inscribed square of a labelled polar ball). Prints the first events of each rule and
the count per rule, and writes a strip of the separation at four moments, drawn by Sculpt's own renderer
(replay.png, or the path given).

    python3 replay_separation.py [OUTPUT.png]
"""
import collections
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import sculpt


def labels_after(events, pole_count, step):
    """The label of every pole once the first `step` events have happened."""
    labels = np.zeros(pole_count, dtype=np.uint8)  # 0: unlabelled
    done = events[:step]
    labels[done["pole"]] = done["label"]
    return labels


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else "replay.png"
    result = sculpt.reconstruct(sculpt.example("star"), method="paper")
    propagation = result.stages["propagation"]
    events = propagation.events
    pole_count = len(result.stages["poles"].radius)

    shown = collections.Counter()
    for k, event in enumerate(events):  # the first two events of each rule
        if shown[event["reason"]] == 2:
            continue
        shown[event["reason"]] += 1
        source = "a convex seed" if event["source"] < 0 else f"pole {event['source']}"
        print(f"event {k:3}: pole {event['pole']:4} {sculpt.LABELS[event['label']]:5} "
              f"from {source} ({sculpt.LABEL_REASONS[event['reason']]})")
    rules = collections.Counter(sculpt.LABEL_REASONS[r] for r in events["reason"])
    print(f"{len(events)} events: " + ", ".join(f"{n} by {rule}" for rule, n in rules.items()))
    print(f"{len(propagation.conflicts)} offers of the other label (conflicts)")
    # Replaying every event gives the final labels: the events are the whole story.
    assert np.array_equal(labels_after(events, pole_count, len(events)), propagation.labels)

    steps = [len(events) // 8, len(events) // 3, 2 * len(events) // 3, len(events)]
    fig, axes = plt.subplots(1, len(steps), figsize=(4 * len(steps), 4.4))
    for ax, step in zip(axes, steps):
        labels = labels_after(events, pole_count, step)
        ax.imshow(sculpt.render(result, stage="propagation", step=step, size=(400, 400),
                                legend=False))
        ax.set_title(f"after {step} events: {np.count_nonzero(labels == 1)} inner, "
                     f"{np.count_nonzero(labels == 2)} outer", fontsize=9)
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(output, dpi=100)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
