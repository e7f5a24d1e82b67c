#!/usr/bin/python3
"""Plot the fit_thermal residual CSV: per axis, the observed bias deviation of each averaging
window against temperature, the fitted polynomial, and the residuals below it.

    scripts/plot_thermal.py model_residuals.csv thermal.png

Gyros in deg/h, accelerometers in micro-g. The PNG is written beside the target and renamed into
place (os.replace): never half a file.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DEG_H_PER_RAD_S = 180.0 / 3.141592653589793 * 3600.0
MICRO_G_PER_M_S2 = 1e6 / 9.80665
UNITS = {"rad_s": (DEG_H_PER_RAD_S, "deg/h"), "m_s2": (MICRO_G_PER_M_S2, "micro-g")}


def read_rows(path):
    """The rows of a CSV file as dicts; exits naming the running script and the file if it has none."""
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        sys.exit(f"{os.path.basename(sys.argv[0])}: {path} has no rows")
    return rows


def save_figure(figure, png_path, dpi):
    """Lays the figure out and writes it beside the target, then renames it into place."""
    figure.tight_layout()
    temporary = png_path + ".tmp.png"
    figure.savefig(temporary, dpi=dpi)
    os.replace(temporary, png_path)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    csv_path, png_path = sys.argv[1:]
    rows = read_rows(csv_path)
    channels = [(triad, axis) for triad in ("gyro", "accelerometer") for axis in ("x", "y", "z")]
    figure, panels = plt.subplots(4, 3, figsize=(13, 11), gridspec_kw={"height_ratios": [3, 1, 3, 1]})
    for index, (triad, axis) in enumerate(channels):
        mine = [r for r in rows if r["triad"] == triad and r["axis"] == axis]
        if not mine:
            continue
        scale, unit = UNITS[mine[0]["unit"]]
        top = panels[2 * (index // 3)][index % 3]
        bottom = panels[2 * (index // 3) + 1][index % 3]
        temperature = [float(r["temperature_c"]) for r in mine]
        top.scatter(temperature, [scale * float(r["observed_delta_bias"]) for r in mine], s=6, alpha=0.6,
                    c=[int(r["orientation"]) for r in mine], cmap="tab10", label="window means")
        curve = sorted(zip(temperature, (scale * float(r["fitted_delta_bias"]) for r in mine)))
        top.plot([t for t, _ in curve], [b for _, b in curve], color="black", label="fitted polynomial")
        top.set_title(f"{triad} {axis}")
        top.set_ylabel(f"delta bias [{unit}]")
        top.legend(fontsize=7)
        bottom.scatter(temperature, [scale * float(r["residual"]) for r in mine], s=4, color="tab:red")
        bottom.axhline(0.0, color="black", linewidth=0.5)
        bottom.set_ylabel(f"residual [{unit}]")
        bottom.set_xlabel("temperature [degC]")
    figure.suptitle("Bias against temperature (colour: orientation)")
    save_figure(figure, png_path, 90)


if __name__ == "__main__":
    main()
