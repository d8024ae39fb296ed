#!/usr/bin/python3
"""The bushing's drop-tower histories (issue 10, doc/verification/bushing.md): a figure
of drop_weight_force, bolt_axial_force, bolt_bending_moment,
inner_sleeve_slip and outer_sleeve_pull_out against time for one or more
runs, and the events that the reference study reports, measured from each
run's time_history.csv:

    /usr/bin/python3 doc/scripts/bushing_histories.py PNG LABEL=CSV...

- touch: the first row with a contact force between weight and plate
  (weight_plate_normal_force > 0);
- the peak of drop_weight_force, raw and filtered with SAE J211/1's
  channel frequency class CFC 180 (a phaseless 4-pole Butterworth: the
  2-pole filter of J211/1 Appendix C run forwards and backwards). A
  rigid block on a steel plate rings at tens of kHz: a force transducer
  and its filter see the CFC 180 curve, not the raw one;
- inner sleeve slides: the first time that inner_sleeve_slip has moved
  0.05 mm from its value at the hand-off (the sleeve against the brace;
  the study: sticking, then sliding from about 7 ms in test 2 and 3 ms in
  test 4);
- bolt bends: the first time that bolt_bending_moment exceeds a quarter
  of its largest value (the study: from about 8 ms);
- weight leaves: after the peak, the start of the last stretch with no
  contact force (the study: about 30 ms in test 2, 38 ms in test 4), or
  "not before the end" if the weight still presses at the last row.

The figure draws the CFC 180 force over the raw one. Needs matplotlib
(Debian: python3-matplotlib).
"""
import csv
import math
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

SLIDE_THRESHOLD = 0.05  # mm, inner_sleeve_slip from its hand-off value
BENDING_FRACTION = 0.25  # of the largest bending moment


def read(path):
    with open(path) as f:
        # (A run still writing may have an incomplete last row.)
        rows = [row for row in csv.DictReader(f)
                if None not in row.values() and "" not in row.values()]
    if not rows:
        sys.exit(path + ": no rows")
    return {key: [float(row[key]) for row in rows] for key in rows[0]}


def cfc_filter(values, dt_seconds, cfc=180.):
    """SAE J211/1 Appendix C: the 2-pole Butterworth of channel frequency
    class CFC, forwards then backwards (phaseless, 4 poles)."""
    wd = 2. * math.pi * cfc * 2.0775
    wa = math.sin(wd * dt_seconds / 2.) / math.cos(wd * dt_seconds / 2.)
    d = 1. + math.sqrt(2.) * wa + wa * wa
    a0 = wa * wa / d
    a1, a2 = 2. * a0, a0
    b1 = -2. * (wa * wa - 1.) / d
    b2 = (-1. + math.sqrt(2.) * wa - wa * wa) / d

    def one_pass(x):
        # The filter starts at rest at the first value: two samples of it
        # before the record. Starting from the record's first two samples
        # as outputs kicks the filter with their difference as a rate (a
        # weight touching between the first two rows: 105 kN at t = 0 for
        # a 95 kN peak, decaying over 3 ms).
        x = [x[0], x[0]] + list(x)
        y = [x[0], x[0]]
        for n in range(2, len(x)):
            y.append(a0 * x[n] + a1 * x[n - 1] + a2 * x[n - 2] +
                     b1 * y[n - 1] + b2 * y[n - 2])
        return y[2:]

    return one_pass(one_pass(values)[::-1])[::-1]


def events(h):
    t = h["time"]
    force = h["drop_weight_force"]
    contact = h["weight_plate_normal_force"]
    result = {}
    touch = next((i for i, f in enumerate(contact) if f > 0.), None)
    result["touch"] = t[touch] if touch is not None else None
    dt = (t[-1] - t[0]) / (len(t) - 1) * 1e-3  # s (uniform rows)
    filtered = cfc_filter(force, dt)
    peak = max(range(len(force)), key=lambda i: force[i])
    peak_f = max(range(len(filtered)), key=lambda i: filtered[i])
    result["peak"] = (force[peak], t[peak])
    result["peak_cfc180"] = (filtered[peak_f], t[peak_f])
    slip0 = h["inner_sleeve_slip"][0]
    result["slides"] = next(
        (t[i] for i, s in enumerate(h["inner_sleeve_slip"])
         if abs(s - slip0) > SLIDE_THRESHOLD), None)
    moment = h["bolt_bending_moment"]
    largest = max(moment)
    result["bends"] = next(
        (t[i] for i, m in enumerate(moment) if m > BENDING_FRACTION * largest),
        None)
    result["largest_moment"] = (largest, t[moment.index(largest)])
    last_contact = max((i for i, f in enumerate(contact) if f > 0.),
                       default=None)
    result["leaves"] = (t[last_contact + 1]
                        if last_contact is not None and
                        last_contact + 1 < len(t) else None)
    result["bolt_force"] = (min(h["bolt_axial_force"]),
                            max(h["bolt_axial_force"]))
    result["pull_out"] = (min(h["outer_sleeve_pull_out"]),
                          max(h["outer_sleeve_pull_out"]))
    result["end"] = t[-1]
    result["energy_error"] = max(abs(e) for e in h["energy_error"])
    return result, filtered


def show(value, unit="ms"):
    return "none" if value is None else "%.3g %s" % (value, unit)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    png = sys.argv[1]
    # LABEL=CSV: the label may hold "=" itself (e.g. "n = 2").
    runs = [arg.rsplit("=", 1) for arg in sys.argv[2:]]
    fig, axes = plt.subplots(5, 1, figsize=(8, 13), sharex=True)
    for label, path in runs:
        h = read(path)
        e, filtered = events(h)
        t = h["time"]
        line, = axes[0].plot(t, h["drop_weight_force"], lw=0.5, alpha=0.35)
        axes[0].plot(t, filtered, color=line.get_color(), lw=1.2,
                     label=label + " (CFC 180)")
        for ax, key in zip(axes[1:], ["bolt_axial_force",
                                       "bolt_bending_moment",
                                       "inner_sleeve_slip",
                                       "outer_sleeve_pull_out"]):
            ax.plot(t, h[key], color=line.get_color(), lw=1.0, label=label)
        print("%s (%s, to %.4g ms):" % (label, path, e["end"]))
        print("  weight touches the plate at %s" % show(e["touch"]))
        print("  drop_weight_force peak %.4g kN at %.4g ms raw, "
              "%.4g kN at %.4g ms CFC 180" % (e["peak"] + e["peak_cfc180"]))
        print("  inner sleeve slides (%.2g mm) from %s" %
              (SLIDE_THRESHOLD, show(e["slides"])))
        print("  bolt bends (moment above %g of its largest, %.4g kN mm at "
              "%.4g ms) from %s" % ((BENDING_FRACTION,) + e["largest_moment"] +
                                    (show(e["bends"]),)))
        print("  weight leaves the plate at %s" %
              (show(e["leaves"]) if e["leaves"] is not None else
               "not before the end"))
        print("  bolt_axial_force %.4g to %.4g kN; outer_sleeve_pull_out "
              "%.4g to %.4g mm" % (e["bolt_force"] + e["pull_out"]))
        # (The column energy_error is a fraction of the largest energy.)
        print("  largest energy error %.3g %% of the largest energy" %
              (100. * e["energy_error"]))
    labels = ["drop_weight_force (kN)", "bolt_axial_force (kN)",
              "bolt_bending_moment (kN mm)", "inner_sleeve_slip (mm)",
              "outer_sleeve_pull_out (mm)"]
    for ax, label in zip(axes, labels):
        ax.set_ylabel(label)
        ax.grid(True, lw=0.3)
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel("time (ms)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
