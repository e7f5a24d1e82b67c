#!/usr/bin/python3
"""Plot attitude_error_budget's CSV: the 1-sigma attitude error per ENU axis over time, strapdown
(solid) against platform (dashed), log-log, in degrees.

    scripts/plot_attitude_error_budget.py attitude_error_budget.csv attitude_error_budget.png [title]

The PNG is written beside the target and renamed into place (os.replace): never half a file.
"""
import math
import sys

from plot_thermal import read_rows, save_figure  # it also selects the Agg backend

import matplotlib.pyplot as plt  # noqa: E402

AXES = {"east": "tab:blue", "north": "tab:orange", "up": "tab:green"}


def main(csv_path, png_path, title):
    rows = [row for row in read_rows(csv_path) if float(row["time_s"]) > 0.0]
    time = [float(row["time_s"]) for row in rows]
    figure, panel = plt.subplots(figsize=(9, 6))
    for axis, colour in AXES.items():
        for system, style in (("strapdown", "-"), ("platform", "--")):
            sigma = [math.degrees(float(row[f"{system}_{axis}_rad"])) for row in rows]
            panel.loglog(time, sigma, style, color=colour, label=f"{system} {axis}")
    panel.set_xlabel("time [s]")
    panel.set_ylabel("attitude error, 1 sigma [deg]")
    panel.set_title(title)
    panel.grid(True, which="both", alpha=0.3)
    panel.legend()
    save_figure(figure, png_path, 100)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) == 4 else "attitude error budget")
