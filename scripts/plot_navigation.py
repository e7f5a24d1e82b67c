#!/usr/bin/python3
"""Plot the navigate tool's error CSV: horizontal position, height and attitude error against time.

    scripts/plot_navigation.py trajectory_errors.csv errors.png

The PNG is written beside the target and renamed into place (os.replace): never half a file.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ARCSEC_PER_RAD = 180.0 / 3.141592653589793 * 3600.0


def read_columns(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        sys.exit(f"plot_navigation: {path} has no rows")
    return {name: [float(row[name]) for row in rows] for name in rows[0]}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    errors_path, png_path = sys.argv[1:]
    c = read_columns(errors_path)
    t = c["time_since_alignment_s"]
    figure, (position, height, attitude) = plt.subplots(3, 1, sharex=True, figsize=(8, 8))
    position.plot(t, c["horizontal_position_error_m"], label="horizontal")
    position.plot(t, c["east_error_m"], label="east", alpha=0.6)
    position.plot(t, c["north_error_m"], label="north", alpha=0.6)
    position.set_ylabel("position error [m]")
    position.legend()
    height.plot(t, c["height_error_m"])
    height.set_ylabel("height error [m]")
    for axis, label in (("east", "east tilt"), ("north", "north tilt"), ("up", "heading")):
        attitude.plot(t, [v * ARCSEC_PER_RAD for v in c[f"attitude_error_{axis}_rad"]], label=label)
    attitude.set_ylabel("attitude error [arcsec]")
    attitude.set_xlabel("time since alignment [s]")
    attitude.legend()
    for axes in (position, height, attitude):
        axes.grid(True, alpha=0.3)
    figure.suptitle(f"Strapdown navigation error against the truth\n{os.path.basename(errors_path)}")
    figure.tight_layout()
    temporary = png_path + ".tmp.png"
    figure.savefig(temporary, dpi=100)
    os.replace(temporary, png_path)


if __name__ == "__main__":
    main()
