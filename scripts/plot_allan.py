#!/usr/bin/python3
"""Plots the stability CSV written by imu_lab's `allan` tool: log-log deviation against tau,
gyro and accelerometer panels, chi-squared confidence bands, and slope guides. Where the noise
identification wrote noise_partial_<channel>.csv, the fitted total (solid) and each term's
partial curve (the channel's colour, the term family's line style or marker, drawn where it
carries 10 % of the AVAR) are drawn over the measured points, and a measured point the fitted
total misses by a factor 3 or more is named on the plot with the factor and whether it lies in
the point's 95 % band (the longest taus have a few degrees of freedom: a wide band).

usage: plot_allan.py REPORT_DIR [--statistic oadev] [--out REPORT_DIR/allan.png (or .svg)]
"""
import argparse
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.fonttype"] = "none"  # an .svg keeps its text as text
import matplotlib.lines  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def read_curves(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        raise ValueError(f"{path}: no rows")
    channels = [name[: -len("_dev_" + name.split("_dev_")[1])] for name in rows[0] if "_dev_" in name]
    curves = {}
    for channel in channels:
        unit = next(name.split("_dev_")[1] for name in rows[0] if name.startswith(channel + "_dev_"))
        taus, dev, lo, hi = [], [], [], []
        for row in rows:
            value = row[f"{channel}_dev_{unit}"]
            if value == "":
                continue
            taus.append(float(row["tau_s"]))
            dev.append(float(value))
            lo.append(float(row[f"{channel}_lo_{unit}"]))
            hi.append(float(row[f"{channel}_hi_{unit}"]))
        curves[channel] = (unit, taus, dev, lo, hi)
    return curves


def read_partial_curves(report_dir, channel):
    """{"tau": [...], "total": [...], "terms": {term: [...]}} from noise_partial_<channel>.csv, or None."""
    path = os.path.join(report_dir, f"noise_partial_{channel}.csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        return None
    columns = list(rows[0])
    total_column = next(name for name in columns if name.startswith("fit_total_dev_"))
    unit = total_column[len("fit_total_dev_"):]
    term_columns = [name for name in columns[3:] if name.endswith("_dev_" + unit)]
    band_low, band_high = f"band95_low_{unit}", f"band95_high_{unit}"
    has_band = band_low in columns and band_high in columns
    return {
        "tau": [float(row["tau_s"]) for row in rows],
        "measured": [float(row[f"measured_dev_{unit}"]) for row in rows],
        "total": [float(row[total_column]) for row in rows],
        "terms": {name[: -len("_dev_" + unit)]: [float(row[name]) for row in rows] for name in term_columns},
        "band": ([float(row[band_low]) for row in rows], [float(row[band_high]) for row in rows]) if has_band
        else None,
    }


# A partial curve is drawn only where it reaches this fraction of the fitted total in deviation,
# 10 % of the AVAR: the curves say which term carries the total where, and a term below a tenth
# of it carries nothing there (drawn, the small ones crowd the panel and squeeze the data into
# its top).
PARTIAL_FLOOR = math.sqrt(0.1)
# One look per term family (markov_1 and markov_2 are both Markov noise): the five IEEE Std 952
# terms as line styles, the others as thin lines with a marker, so that no two families look
# alike; the colour is the channel's.
FAMILY_STYLES = {
    "white_rate": {"linestyle": "--"},
    "bias_instability": {"linestyle": ":"},
    "random_walk": {"linestyle": "-."},
    "white_angle": {"linestyle": (0, (8, 3))},
    "rate_ramp": {"linestyle": (0, (6, 2, 1, 2, 1, 2))},
    "markov": {"linestyle": "-", "marker": "v"},
    "sinusoid": {"linestyle": "-", "marker": "^"},
    "resonance": {"linestyle": "-", "marker": "s"},
    "output_quantization": {"linestyle": "-", "marker": "x"},
}
OTHER_STYLE = {"linestyle": "-", "marker": "d"}  # the zero-at-DC families
# A measured point the fitted total misses by this factor or more is named on the plot.
MISS_FACTOR = 3.0


def term_family(term):
    """"markov_1" -> "markov": the numbered terms of one kind share a look."""
    return re.sub(r"_\d+$", "", term)


def family_style(family):
    style = dict(FAMILY_STYLES.get(family, OTHER_STYLE))
    if "marker" in style:
        style.update(markersize=3, markevery=2, linewidth=0.6)
    else:
        style.update(linewidth=0.9)
    return style


def draw_fit(axis, channel, fit, color, families):
    """The fitted total (solid) and the terms' partial curves where they carry 10 % of the AVAR,
    in the channel's colour and each family's look (families: the set drawn, extended here)."""
    axis.loglog(fit["tau"], fit["total"], color=color, linewidth=1.2)
    for term, devs in fit["terms"].items():
        shown = [d if d >= PARTIAL_FLOOR * total else float("nan") for d, total in zip(devs, fit["total"])]
        if all(d != d for d in shown):
            continue
        family = term_family(term)
        families.add(family)
        axis.loglog(fit["tau"], shown, color=color, gid=f"partial:{channel}:{term}", **family_style(family))


def note_misses(axis, channel, fit, color):
    """Names the measured point the fitted total misses most, when by MISS_FACTOR or more: the
    factor and whether the point's 95 % band holds the total (at the longest taus it is wide)."""
    worst = None
    for i, (measured, total) in enumerate(zip(fit["measured"], fit["total"])):
        if not (measured > 0 and total > 0):
            continue
        factor = max(total / measured, measured / total)
        if factor >= MISS_FACTOR and (worst is None or factor > worst[1]):
            worst = (i, factor)
    if worst is None:
        return
    i, factor = worst
    tau, measured, total = fit["tau"][i], fit["measured"][i], fit["total"][i]
    side = "above" if total > measured else "below"
    inside = fit["band"] is not None and fit["band"][0][i] <= total <= fit["band"][1][i]
    where = "inside its 95 % band (few degrees of freedom)" if inside else "outside its 95 % band"
    axis.plot([tau], [measured], marker="o", markersize=7, markerfacecolor="none", markeredgecolor=color,
              linestyle="none", gid=f"miss:{channel}")
    axis.annotate(f"{channel}: fit {factor:.0f}x {side} this point at {tau:.4g} s,\n{where}", (tau, measured),
                  xytext=(-10, -16), textcoords="offset points", ha="right", va="top", fontsize=6.5, color=color,
                  bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.8, "pad": 1})


def slope_guides(axis, taus, devs):
    """Grey lines of slope -1, -1/2, 0, +1/2, +1 through the curve's middle point (the panel's
    limits are the data's: the guides never widen them)."""
    if len(taus) < 3:
        return
    middle = len(taus) // 2
    tau_ref, dev_ref = taus[middle], devs[middle]
    span = [taus[0], taus[-1]]
    for slope, label in ((-1.0, "-1"), (-0.5, "-1/2"), (0.0, "0"), (0.5, "+1/2"), (1.0, "+1")):
        axis.plot(span, [dev_ref * (t / tau_ref) ** slope for t in span], color="0.75", linewidth=0.7,
                  linestyle="--", zorder=0, scalex=False, scaley=False)
        axis.annotate(label, (span[-1], dev_ref * (span[-1] / tau_ref) ** slope), fontsize=7, color="0.5",
                      annotation_clip=True)


def data_limits(curves, members):
    """The panel's deviation range: the measured curves with their upper bounds, and below the
    smallest measured deviation a quarter of it (a lone low point at a few EDF, with its far lower
    bound, would otherwise stretch the panel)."""
    low = min(min(v for v in curves[c][2] if v > 0) for c in members)
    high = max(max(curves[c][4] + curves[c][2]) for c in members)
    return low / 4.0, high * 1.5


def plot(report_dir, statistic, out_path):
    path = os.path.join(report_dir, f"{statistic}.csv")
    curves = read_curves(path)
    sensors = [s for s in ("gyro", "accel") if any(c.startswith(s) for c in curves)] or ["all"]
    figure, axes = plt.subplots(1, len(sensors), figsize=(6.5 * len(sensors), 5.6), squeeze=False)
    for axis, sensor in zip(axes[0], sensors):
        members = [c for c in curves if sensor == "all" or c.startswith(sensor)]
        unit = curves[members[0]][0].replace("_", "/").replace("s2", "s^2")
        families = set()
        channel_handles = []
        for channel in members:
            _, taus, dev, lo, hi = curves[channel]
            fit = read_partial_curves(report_dir, channel)
            # With a fit, the measurement is points and the fitted total the solid line.
            line, = axis.loglog(taus, dev, marker=".", linestyle="none" if fit else "-",
                                label=channel + (": measured, fitted total" if fit else ""))
            channel_handles.append(line)
            axis.fill_between(taus, lo, hi, color=line.get_color(), alpha=0.2, linewidth=0)
            if fit:
                draw_fit(axis, channel, fit, line.get_color(), families)
                note_misses(axis, channel, fit, line.get_color())
        axis.set_ylim(*data_limits(curves, members))
        _, taus, dev, _, _ = curves[members[0]]
        slope_guides(axis, taus, dev)
        axis.set_xlabel("tau [s]")
        axis.set_ylabel(f"{statistic.upper()} [{unit}]")
        axis.set_title(f"{sensor}: {statistic} with 68.3 % chi-squared bounds")
        axis.grid(True, which="both", alpha=0.3)
        # Colour names the channel, line style the term: each is named once.
        channels = axis.legend(handles=channel_handles, fontsize=7, loc="lower left")
        if families:
            axis.add_artist(channels)
            ordered = [f for f in FAMILY_STYLES if f in families] + sorted(families - FAMILY_STYLES.keys())
            term_handles = [matplotlib.lines.Line2D([], [], color="0.3", label=family, **family_style(family))
                            for family in ordered]
            axis.legend(handles=term_handles, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12),
                        ncol=4, title="partial curves (where >= 10 % of the AVAR)", title_fontsize=7, frameon=False)
    figure.tight_layout()
    root, extension = os.path.splitext(out_path)
    staged = root + ".tmp" + (extension or ".png")  # the extension picks the format
    figure.savefig(staged, dpi=110)
    os.replace(staged, out_path)  # atomic: a reader never sees half a picture


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("report_dir")
    parser.add_argument("--statistic", default="oadev")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    out = args.out or os.path.join(args.report_dir, "allan.png")
    try:
        plot(args.report_dir, args.statistic, out)
    except (OSError, ValueError, KeyError) as error:
        print(f"plot_allan: {error}", file=sys.stderr)
        return 1
    return 0  # quiet: the caller (allan, allan_monitor) names the files it wrote


if __name__ == "__main__":
    sys.exit(main())
