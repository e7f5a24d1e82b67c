#!/usr/bin/python3
"""Plots the stability CSV written by imu_lab's `allan` tool: log-log deviation against tau,
gyro and accelerometer panels, chi-squared confidence bands, and slope guides. Where the noise
identification wrote noise_partial_<channel>.csv, the fitted total (solid) and each term's
partial curve (the channel's colour, the term's line style, drawn where it carries 1 % of the
AVAR) are drawn over the measured points.

usage: plot_allan.py REPORT_DIR [--statistic oadev] [--out REPORT_DIR/allan.png]
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
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
    return {
        "tau": [float(row["tau_s"]) for row in rows],
        "total": [float(row[total_column]) for row in rows],
        "terms": {name[: -len("_dev_" + unit)]: [float(row[name]) for row in rows] for name in term_columns},
    }


# A partial curve is drawn only where it reaches this fraction of the fitted total in deviation,
# 1 % of the AVAR: a smaller share moves the total by under 0.5 %, inside the band's +-1 % floor
# (doc/identification.md, "The 95 % band"), and drawing it would squeeze the data into the top.
PARTIAL_FLOOR = 0.1
# Line styles of the terms, one per term name in order of first appearance on a panel; the colour
# is the channel's.
TERM_STYLES = ("--", "-.", ":", (0, (5, 2, 1, 2)), (0, (1, 1)), (0, (3, 1, 1, 1, 1, 1)), (0, (8, 2)),
               (0, (2, 2, 6, 2)))


def draw_fit(axis, fit, color, term_styles):
    """The fitted total (solid) and the terms' partial curves where they matter, in the channel's
    colour and each term's style (term_styles: term -> style, extended here)."""
    axis.loglog(fit["tau"], fit["total"], color=color, linewidth=1.2)
    for term, devs in fit["terms"].items():
        shown = [d if d >= PARTIAL_FLOOR * total else float("nan") for d, total in zip(devs, fit["total"])]
        if all(d != d for d in shown):
            continue
        style = term_styles.setdefault(term, TERM_STYLES[len(term_styles) % len(TERM_STYLES)])
        axis.loglog(fit["tau"], shown, color=color, linewidth=0.8, linestyle=style)


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
        term_styles = {}
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
                draw_fit(axis, fit, line.get_color(), term_styles)
        axis.set_ylim(*data_limits(curves, members))
        _, taus, dev, _, _ = curves[members[0]]
        slope_guides(axis, taus, dev)
        axis.set_xlabel("tau [s]")
        axis.set_ylabel(f"{statistic.upper()} [{unit}]")
        axis.set_title(f"{sensor}: {statistic} with 68.3 % chi-squared bounds")
        axis.grid(True, which="both", alpha=0.3)
        # Colour names the channel, line style the term: each is named once.
        channels = axis.legend(handles=channel_handles, fontsize=7, loc="lower left")
        if term_styles:
            axis.add_artist(channels)
            term_handles = [matplotlib.lines.Line2D([], [], color="0.3", linewidth=0.8, linestyle=style, label=term)
                            for term, style in term_styles.items()]
            axis.legend(handles=term_handles, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12),
                        ncol=4, title="partial curves (where >= 1 % of the AVAR)", title_fontsize=7, frameon=False)
    figure.tight_layout()
    figure.savefig(out_path + ".tmp.png", dpi=110)
    os.replace(out_path + ".tmp.png", out_path)  # atomic: a reader never sees half a picture


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
    print(f"plot_allan: wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
