#!/usr/bin/python3
"""Plot a lot of units: per axis, each unit's overlapping Allan deviation (its allan output's
oadev.csv) and the lot's typical model (lot_model.csv, written by lot_report).

    scripts/plot_lot.py lot_model.csv lot_allan.png NAME=ALLAN_DIR [NAME=ALLAN_DIR ...]

Gyros in deg/h, accelerometers in micro-g. The PNG is written beside the target and renamed into
place (os.replace): never half a file.
"""
import os
import sys

from plot_thermal import UNITS, read_rows, save_figure  # it also selects the Agg backend

import matplotlib.pyplot as plt  # noqa: E402

CHANNELS = ["gyro_x", "gyro_y", "gyro_z", "accel_x", "accel_y", "accel_z"]
UNIT_KEYS = ["rad_s"] * 3 + ["m_s2"] * 3


def column(rows, name):
    """(tau, value) pairs of the rows where the column has a value."""
    pairs = [(float(row["tau_s"]), float(row[name])) for row in rows if row.get(name)]
    return [p[0] for p in pairs], [p[1] for p in pairs]


def main(model_path, png_path, units):
    model = read_rows(model_path)
    curves = [(name, read_rows(os.path.join(directory, "oadev.csv"))) for name, directory in units]
    figure, axes = plt.subplots(2, 3, figsize=(12, 6.5), squeeze=False)
    for index, channel in enumerate(CHANNELS):
        axis = axes[index // 3][index % 3]
        scale, unit = UNITS[UNIT_KEYS[index]]
        for name, rows in curves:
            taus, values = column(rows, f"{channel}_dev_{UNIT_KEYS[index]}")
            axis.loglog(taus, [v * scale for v in values], lw=1, alpha=0.8, label=name)
        taus, values = column(model, f"{channel}_typical_dev_{UNIT_KEYS[index]}")
        if taus:
            axis.loglog(taus, [v * scale for v in values], "k--", lw=1.5, label="typical model")
        axis.set_title(channel)
        axis.set_xlabel("tau [s]")
        axis.set_ylabel(f"Allan deviation [{unit}]")
        axis.grid(which="both", alpha=0.3)
        if index == 0:
            axis.legend(fontsize=7)
    save_figure(figure, png_path, 70)


if __name__ == "__main__":
    if len(sys.argv) < 4 or any("=" not in argument for argument in sys.argv[3:]):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], [tuple(argument.split("=", 1)) for argument in sys.argv[3:]])
