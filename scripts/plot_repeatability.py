#!/usr/bin/python3
"""Plot the repeatability CSV: per channel, each run's bias with its in-run uncertainty (1 sigma
error bar, the uncertainty of the run's mean), the mean over the runs and the mean +/- the
run-to-run sigma.

    scripts/plot_repeatability.py repeatability.csv repeatability.png

Gyros in deg/h, accelerometers in micro-g. The PNG is written beside the target and renamed into
place (os.replace): never half a file.
"""
import sys

from plot_thermal import UNITS, read_rows, save_figure  # it also selects the Agg backend

import matplotlib.pyplot as plt  # noqa: E402

CHANNELS = ["gyro_x", "gyro_y", "gyro_z", "accel_x", "accel_y", "accel_z"]


def main(csv_path, png_path):
    rows = read_rows(csv_path)
    figure, axes = plt.subplots(2, 3, figsize=(13, 7), squeeze=False)
    for index, channel in enumerate(CHANNELS):
        axis = axes[index // 3][index % 3]
        mine = [row for row in rows if row["channel"] == channel]
        scale, unit = UNITS[mine[0]["unit"]]
        runs = [row for row in mine if row["run"] not in ("mean", "spread")]
        mean = float(next(row for row in mine if row["run"] == "mean")["bias"]) * scale
        sigma = float(next(row for row in mine if row["run"] == "spread")["bias"]) * scale
        numbers = list(range(1, len(runs) + 1))
        axis.errorbar(numbers, [float(row["bias"]) * scale for row in runs],
                      yerr=[float(row["mean_uncertainty"]) * scale for row in runs], fmt="o", capsize=3,
                      label="run bias +/- in-run 1 sigma")
        axis.axhline(mean, color="k", lw=1, label="mean")
        axis.axhspan(mean - sigma, mean + sigma, color="k", alpha=0.1, label="+/- run-to-run sigma")
        axis.set_title(f"{channel}: sigma {sigma:.3g} {unit}")
        axis.set_xlabel("run")
        axis.set_ylabel(f"bias [{unit}]")
        axis.grid(alpha=0.3)
        axis.ticklabel_format(axis="y", useOffset=False)
        if index == 0:
            axis.legend(fontsize=7)
    save_figure(figure, png_path, 90)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
