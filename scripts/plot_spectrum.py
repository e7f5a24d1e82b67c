#!/usr/bin/python3
"""Plot the spectrum tool's CSV files: per triad, each axis's one-sided PSD (log-log; the x axis's
confidence interval shaded, the same factors hold for every axis) with the identified model's PSD
dashed where the CSV has one (`spectrum --model`), and each axis's autocorrelation with the
white-noise band.

    scripts/plot_spectrum.py spectrum_psd.csv spectrum_autocorrelation.csv spectrum.png

The PNG is written beside the target and renamed into place (os.replace): never half a file.
"""
import sys

from plot_thermal import read_rows, save_figure  # it also selects the Agg backend

import matplotlib.pyplot as plt  # noqa: E402

TRIADS = {"gyro": "(rad/s)^2/Hz", "accelerometer": "(m/s^2)^2/Hz"}


def main(psd_path, autocorrelation_path, png_path):
    psd = read_rows(psd_path)
    acf = read_rows(autocorrelation_path)
    frequency = [float(row["frequency_hz"]) for row in psd]
    lag = [float(row["lag_s"]) for row in acf]
    band = float(acf[0]["white_band"])
    figure, panels = plt.subplots(2, 2, figsize=(13, 9))
    for column, (triad, unit) in enumerate(TRIADS.items()):
        top, bottom = panels[0][column], panels[1][column]
        for axis in "xyz":
            channel = f"{triad}_{axis}"
            key = next(name for name in psd[0] if name.startswith(channel + "_psd_") and name.endswith("_per_hz"))
            line, = top.loglog(frequency, [float(row[key]) for row in psd], lw=0.6, label=axis)
            model = next((name for name in psd[0] if name.startswith(channel + "_model_psd_")), None)
            if model is not None:
                # A model density of 0 (a ramp-only model, DC) has no place on a log axis.
                top.loglog(frequency, [float(row[model]) if float(row[model]) > 0 else float("nan") for row in psd],
                           lw=1.0, ls="--", color=line.get_color(), label=f"{axis}: model")
            if axis == "x":
                top.fill_between(frequency, [float(row[key + "_lower"]) for row in psd],
                                 [float(row[key + "_upper"]) for row in psd], color=line.get_color(), alpha=0.15,
                                 lw=0, label="x: interval")
                factors = (float(psd[0][key + "_lower"]) / float(psd[0][key]),
                           float(psd[0][key + "_upper"]) / float(psd[0][key]))
            bottom.plot(lag, [float(row[channel]) for row in acf], lw=0.6, label=axis)
        top.set_title(f"{triad}: Welch PSD, interval x{factors[0]:.2g} .. x{factors[1]:.2g} of the estimate")
        top.set_xlabel("frequency [Hz]")
        top.set_ylabel(f"one-sided PSD [{unit}]")
        top.grid(alpha=0.3, which="both")
        top.legend(fontsize=8)
        bottom.axhspan(-band, band, color="k", alpha=0.1, label="white-noise band")
        bottom.set_title(f"{triad}: autocorrelation")
        bottom.set_xlabel("lag [s]")
        bottom.set_ylabel("r(lag)")
        bottom.grid(alpha=0.3)
        bottom.legend(fontsize=8)
    save_figure(figure, png_path, 72)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
