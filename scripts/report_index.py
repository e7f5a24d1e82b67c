#!/usr/bin/python3
"""Write REPORT/index.md: the demo's figures and key numbers on one page.

    scripts/report_index.py REPORT [--profile NAME]

Reads what scripts/demo left in REPORT: noise/ (allan: noise.yaml, kalibr_imu.yaml, allan.png;
spectrum/spectrum.png; attitude_error_budget: attitude_error_budget.txt and .png),
thermal/ (fit_thermal: thermal.yaml, thermal.png, fit_thermal.txt), calibration/
(fit_calibration: calibration.yaml, calibration_report.txt, fit_calibration.txt; the warnings in
the tools' logs are listed), repeatability/ (repeatability: repeatability.yaml, repeatability.png),
navigation/rlg/ and navigation/mems/ (navigate raw, corrected and on another power-up;
scripts/navigation_budget.py: budget.yaml, budget.png), rviz.png, rviz_allan.png or rviz_skipped.txt. A missing part is named in the index, not skipped silently.
Written beside the target and renamed into place.
"""
import argparse
import csv
import math
import os
import sys

import yaml

ARCSEC_PER_RAD = 180.0 / math.pi * 3600.0
DEG_H_PER_RAD_S = 180.0 / math.pi * 3600.0
MICRO_G_PER_M_S2 = 1e6 / 9.80665

# Noise terms shown per triad: (term, symbol, field unit key, unit as printed).
NOISE_TERMS = {
    "gyro": [("white_rate", "N", "deg_per_sqrt_h", "deg/√h"), ("bias_instability", "B", "deg_h", "deg/h"),
             ("random_walk", "K", "deg_h_per_sqrt_h", "deg/h/√h")],
    "accel": [("white_rate", "N", "m_s_per_sqrt_h", "m/s/√h"), ("bias_instability", "B", "micro_g", "µg"),
              ("random_walk", "K", "m_s_per_h_per_sqrt_h", "m/s/h/√h")],
}


def load_yaml(path):
    with open(path) as handle:
        return yaml.safe_load(handle)


def missing(what, path):
    return [f"*Not produced: {what} (`{os.path.basename(path)}` missing; see the demo's output above it).*", ""]


def figure(report, relative_path, alt, caption):
    if os.path.exists(os.path.join(report, relative_path)):
        return [caption, "", f"![{alt}]({relative_path})", ""]
    return [f"*No figure: `{relative_path}` missing.*", ""]


def profile_description(profile):
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "config", "sensors", profile + ".yaml")
    if not os.path.exists(path):
        return None
    return load_yaml(path).get("description")


def term_cell(terms, term, symbol, unit_key):
    values = terms.get(term)
    if values is None:
        return "–"
    key = f"{symbol}_{unit_key}"
    if values.get("status") == "present" and key in values:
        sigma = values.get(key + "_sigma")
        return f"{values[key]:.3g} ± {sigma:.2g}" if sigma is not None else f"{values[key]:.3g}"
    bound = next((v for k, v in values.items() if k.startswith(key + "_upper_")), None)
    return f"< {bound:.3g}" if bound is not None else "–"


def white_equivalent_cell(fit, unit_key):
    """noise.yaml's white-equivalent N: the fitted N plus the Markov terms the curve cannot tell
    from white noise (kalibr_imu.yaml's density)."""
    value = fit.get("white_equivalent", {}).get(f"N_{unit_key}")
    return f"{value:.3g}" if value is not None else "–"


def noise_section(report, profile):
    folder = os.path.join(report, "noise")
    lines = ["## Noise: Allan deviation and the identified noise model", ""]
    lines += figure(report, "noise/allan.png", "Allan deviation",
                    "One hour at rest, 200 Hz. Overlapping Allan deviation with 68 % bounds, the fitted total "
                    "(solid) and each identified term (dashed).")
    noise_path = os.path.join(folder, "noise.yaml")
    if not os.path.exists(noise_path):
        return lines + missing("noise identification", noise_path)
    noise = load_yaml(noise_path)
    for triad, terms in NOISE_TERMS.items():
        axes = noise.get("triads", {}).get(triad, {}).get("axes", {})
        if not axes:
            lines += [f"*No {triad} identification in noise.yaml.*", ""]
            continue
        white_unit_key, white_unit = terms[0][2], terms[0][3]
        header = "| axis | " + " | ".join(f"{symbol} [{unit}]" for _, symbol, _, unit in terms)
        header += f" | white-equivalent N [{white_unit}] |"
        lines += [header, "|---" * (len(terms) + 2) + "|"]
        for axis, fit in axes.items():
            cells = [term_cell(fit.get("terms", {}), term, symbol, key) for term, symbol, key, _ in terms]
            cells.append(white_equivalent_cell(fit, white_unit_key))
            lines.append(f"| {axis} | " + " | ".join(cells) + " |")
        lines.append("")
    lines += ["Value ± 1 sigma where the fit finds the term; `< x`: absent, 95 % upper bound. Every term "
              "(a Markov term can take part of the white noise: the white-equivalent N adds back, in power, "
              "each Markov term with T_c below twice tau0, as kalibr_imu.yaml does), SI values and warnings: "
              "[noise/noise.yaml](noise/noise.yaml).", ""]
    truth = profile_description(profile)
    if truth:
        lines += [f"The emulated profile's own figures, for comparison: {truth}.", ""]
    kalibr_path = os.path.join(folder, "kalibr_imu.yaml")
    if os.path.exists(kalibr_path):
        kalibr = load_yaml(kalibr_path)
        lines += ["Kalibr ([noise/kalibr_imu.yaml](noise/kalibr_imu.yaml), continuous time):", ""]
        for key, unit in [("gyroscope_noise_density", "rad/s/√Hz"), ("gyroscope_random_walk", "rad/s²/√Hz"),
                          ("accelerometer_noise_density", "m/s²/√Hz"), ("accelerometer_random_walk", "m/s³/√Hz")]:
            if key in kalibr:
                bound = " (upper bound)" if kalibr.get(key + "_is_upper_bound") else ""
                lines.append(f"- `{key}`: {kalibr[key]:.3g} {unit}{bound}")
        lines.append("")
    return lines


def spectrum_and_attitude_section(report):
    lines = ["## The same noise as spectra, and as attitude error", ""]
    lines += figure(report, "noise/spectrum/spectrum.png", "PSD with the identified model",
                    "The hour at rest as power spectral densities (Welch, with each bin's interval) and the "
                    "identified model's PSD drawn over them (doc/spectrum.md).")
    lines += figure(report, "noise/attitude_error_budget.png", "attitude error, strapdown vs platform",
                    "The identified gyro model, with the profile's run-to-run bias (1 deg/h, which no Allan curve shows), "
                    "turned into attitude error on the rate_table scenario: the "
                    "strapdown system's gyros turn with the table and average part of their errors, a platform's "
                    "stay on the ENU axes (doc/attitude_error_budget.md).")
    summary = os.path.join(report, "noise", "attitude_error_budget.txt")
    if not os.path.exists(summary):
        return lines + missing("attitude error budget", summary)
    with open(summary) as handle:
        text = handle.read().strip().splitlines()
    lines += ["```", *text, "```", ""]
    return lines


def thermal_section(report):
    folder = os.path.join(report, "thermal")
    path = os.path.join(folder, "thermal.yaml")
    lines = ["## Temperature: thermal model", ""]
    lines += figure(report, "thermal/thermal.png", "Thermal fit",
                    "Six positions through −20, +20 and +60 °C soaks. Bias against temperature per axis "
                    "(window means), the fitted curve and the residuals.")
    if not os.path.exists(path):
        return lines + missing("thermal model", path)
    model = load_yaml(path)
    validity = model.get("validity", {})
    lines += [f"Reference {model.get('reference_temperature_c')} °C; valid over "
              f"{validity.get('temperature_min_c', float('nan')):.1f} … {validity.get('temperature_max_c', float('nan')):.1f} °C; "
              f"rate term: {model.get('uses_temperature_rate')}.", "",
              "| axis | bias order | bias polynomial (per °C, °C², …) | fitted bias change peak to peak | residual RMS |",
              "|---|---|---|---|---|"]
    for axis in model.get("fit", {}).get("axes", []):
        triad, name = axis.get("triad"), axis.get("axis")
        unit = "rad_s" if triad == "gyro" else "m_s2"
        terms = model.get(triad, {}).get(name, {})
        polynomial = terms.get(f"bias_polynomial_{unit}", [])
        scale, shown_unit = (DEG_H_PER_RAD_S, "deg/h") if triad == "gyro" else (MICRO_G_PER_M_S2, "µg")
        coefficients = ", ".join(f"{c * scale:.3g}" for c in polynomial)
        lines.append(f"| {triad} {name} | {axis.get('bias_order')} | {coefficients} {shown_unit} | "
                     f"{axis.get('fitted_delta_bias_peak_to_peak', float('nan')) * scale:.3g} {shown_unit} | "
                     f"{axis.get('residual_rms', float('nan')) * scale:.3g} {shown_unit} |")
    lines += ["", "Model file (for the `thermal_compensator` node): [thermal/thermal.yaml](thermal/thermal.yaml).", ""]
    return lines + tool_warnings(report, "thermal/fit_thermal.txt")


def tool_warnings(report, log):
    """The warnings a tool printed into its log (REPORT/log), as a list under the section, so that
    the index never shows a fit's numbers without what the tool said against them."""
    path = os.path.join(report, log)
    if not os.path.exists(path):
        return []
    with open(path, errors="replace") as handle:
        warnings = [line.strip() for line in handle if ": warning: " in line]
    if not warnings:
        return []
    return [f"Warnings in [{log}]({log}):", ""] + [f"- {w.split(': warning: ', 1)[1]}" for w in warnings] + [""]


def calibration_section(report):
    folder = os.path.join(report, "calibration")
    path = os.path.join(folder, "calibration.yaml")
    lines = ["## Calibration: the thesis's 12-position scheme", ""]
    if not os.path.exists(path):
        return lines + missing("calibration", path)
    calibration = load_yaml(path)
    lines += ["| triad | bias | scale-factor error [ppm] | misalignment [arcsec] |", "|---|---|---|---|"]
    for triad in ("accelerometer", "gyro"):
        values = calibration.get(triad, {})
        unit_si = "rad_s" if triad == "gyro" else "m_s2"
        scale, unit = (DEG_H_PER_RAD_S, "deg/h") if triad == "gyro" else (MICRO_G_PER_M_S2, "µg")
        bias = values.get(f"bias_{unit_si}", [])
        sigma = values.get(f"bias_sigma_{unit_si}", [float("nan")] * len(bias))
        bias_text = ", ".join(f"{b * scale:.4g} ± {s * scale:.2g}" for b, s in zip(bias, sigma)) + f" {unit}"
        ppm = ", ".join(f"{v:.1f}" for v in values.get("scale_factor_error_ppm", []))
        # K's off-diagonal terms: row = sensor axis, column = input axis.
        matrix = values.get("misalignment_arcsec", [])
        misalignment = ", ".join(f"{'xyz'[i]}{'xyz'[j]} {v:.1f}" for i, row in enumerate(matrix)
                                 for j, v in enumerate(row) if i != j)
        lines.append(f"| {triad} | {bias_text} | {ppm} | {misalignment} |")
    lines += ["", "Each parameter's sigma, the residuals per rest and move, Kalibr's form: "
              "[calibration/calibration.yaml](calibration/calibration.yaml), "
              "[calibration/calibration_report.txt](calibration/calibration_report.txt), "
              "[calibration/calibration_kalibr_imu_chain.yaml](calibration/calibration_kalibr_imu_chain.yaml).", ""]
    return lines + tool_warnings(report, "calibration/fit_calibration.txt")


def repeatability_section(report, profile):
    folder = os.path.join(report, "repeatability")
    path = os.path.join(folder, "repeatability.yaml")
    lines = ["## Repeatability: five switch-ons", ""]
    if not os.path.exists(path):
        return lines + missing("repeatability", path)
    table = load_yaml(path)
    path_profile = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "config", "sensors", profile + ".yaml")
    sensors = load_yaml(path_profile)
    lines += [f"{len(table['runs'])} emulated switch-ons of {table['runs'][0]['duration_s']:.0f} s at rest "
              "(one seed each: the emulator draws the turn-on bias per seed). The run-to-run sigma (n - 1) "
              f"with its {100 * table['confidence']:.0f} % chi-squared interval estimates the turn-on sigma "
              "combined with the uncertainty of one run's mean (doc/repeatability.md).", "",
              "| channel | mean output at rest (bias, Earth rate, gravity) | run-to-run sigma [interval] | rms uncertainty of a run's mean | "
              "profile's turn-on sigma |", "|---|---|---|---|---|"]
    for channel, values in table["channels"].items():
        gyro = channel.startswith("gyro")
        scale, unit = (DEG_H_PER_RAD_S, "deg/h") if gyro else (MICRO_G_PER_M_S2, "µg")
        triad = sensors["gyro" if gyro else "accelerometer"]
        turn_on = triad.get("bias_turn_on_sigma_rad_s" if gyro else "bias_turn_on_sigma_m_s2", float("nan"))
        if isinstance(turn_on, list):  # one number or [x, y, z] (config/sensors)
            turn_on = turn_on["xyz".index(channel[-1])]
        spread = values["run_to_run_bias"]
        lines.append(f"| {channel} | {spread['mean'] * scale:.4g} {unit} | {spread['standard_deviation'] * scale:.3g} "
                     f"[{spread['lower'] * scale:.3g}, {spread['upper'] * scale:.3g}] {unit} | "
                     f"{values['rms_mean_uncertainty'] * scale:.3g} {unit} | {turn_on * scale:.3g} {unit} |")
    lines.append("")
    lines += figure(report, "repeatability/repeatability.png", "run biases",
                    "Per channel, each run's bias with its in-run 1-sigma uncertainty, the mean and the "
                    "run-to-run band ([repeatability/repeatability.csv](repeatability/repeatability.csv)).")
    return lines


def arcsec_triple(values):
    return " / ".join(f"{v:.1f}" for v in values)


def budget_table(budget, what):
    """The runs' final errors beside what navigation_budget.py computed for them."""
    removed, raw, corrected = budget["removed_terms"], budget["raw"], budget["corrected"]
    verdict = lambda ok, yes, no: f"**{yes if ok else no}**"
    lines = [f"| after {budget['duration_s'] / 60.0:.0f} min | horizontal position [m] | "
             "attitude: east tilt / north tilt / heading [arcsec] | computed |",
             "|---|---|---|---|",
             f"| raw | {raw['final_position_m']:.1f} | {arcsec_triple(raw['final_attitude_arcsec'])} | |",
             f"| corrected, same power-up | {corrected['final_position_m']:.1f} | "
             f"{arcsec_triple(corrected['final_attitude_arcsec'])} | 4-sigma bound of what the calibration cannot "
             f"remove: {corrected['position_bound_final_m']:.0f} m, {arcsec_triple(corrected['attitude_bound_final_arcsec'])} "
             f"arcsec: {verdict(corrected['inside'], 'inside', 'OUTSIDE')} (at worst {corrected['worst_fraction_of_bound']:.2f} "
             "of it over the run) |",
             f"| raw − corrected | {removed['measured_final_position_m']:.1f} | "
             f"{arcsec_triple(removed['measured_final_attitude_arcsec'])} | the removed terms alone: "
             f"{removed['predicted_final_position_m']:.1f} m, {arcsec_triple(removed['predicted_final_attitude_arcsec'])} "
             f"arcsec; worst mismatch over the run {removed['worst_position_mismatch_m']:.2g} m "
             f"(tolerance {removed['position_tolerance_m']:.2g}), {removed['worst_attitude_mismatch_arcsec']:.2g} arcsec "
             f"(tolerance {removed['attitude_tolerance_arcsec']:.2g}): {verdict(removed['explained'], 'explained', 'NOT explained')} |"]
    if "power_up_difference" in budget:
        new, difference = budget["new_turn_on"], budget["power_up_difference"]
        lines += [f"| corrected, another power-up | {new['final_position_m']:.1f} | {arcsec_triple(new['final_attitude_arcsec'])} | |",
                  f"| another − same power-up | {difference['final_position_m']:.1f} | "
                  f"{arcsec_triple(difference['final_attitude_arcsec'])} | 4-sigma bound from the profile's turn-on bias, bias "
                  f"instability and noise: {difference['position_bound_final_m']:.0f} m, "
                  f"{arcsec_triple(difference['attitude_bound_final_arcsec'])} arcsec: "
                  f"{verdict(difference['inside'], 'inside', 'OUTSIDE')} (at worst {difference['worst_fraction_of_bound']:.2f}) |"]
    gyro = ", ".join(f"{v * DEG_H_PER_RAD_S:.3g}" for v in removed["gyro_enu_rad_s"])
    accel = ", ".join(f"{v * MICRO_G_PER_M_S2:.3g}" for v in removed["accel_enu_m_s2"])
    residual = budget["residual_sigma"]
    left = ", ".join(f"{v * DEG_H_PER_RAD_S:.2g}" for v in residual["gyro_rad_s"])
    stated = ", ".join(f"{v * DEG_H_PER_RAD_S:.2g}" for v in residual["of_which_calibration_gyro_bias_rad_s"])
    lines += ["", f"What the calibration removes at this attitude (raw − corrected, ENU): gyro {gyro} deg/h, "
              f"accelerometer {accel} µg. {what} The corrected run's bound takes 1 sigma of {left} deg/h per gyro "
              f"axis for what is left, of which the calibration file's own bias sigma is {stated} deg/h.", ""]
    return lines


def navigation_part(report, folder, title, caption, what):
    lines = [f"### {title}", ""]
    lines += figure(report, f"navigation/{folder}/budget.png", title, caption)
    path = os.path.join(report, "navigation", folder, "budget.yaml")
    if not os.path.exists(path):
        return lines + missing(f"the {folder} navigation budget", path)
    lines += budget_table(load_yaml(path), what)
    runs = ", ".join(f"[{name}](navigation/{folder}/{name}_trajectory_errors.csv)"
                     for name in ("raw", "corrected", "new_turn_on"))
    lines += [f"Error CSVs: {runs}; the computation: [navigation/{folder}/budget.yaml](navigation/{folder}/budget.yaml).", ""]
    return lines


def navigation_section(report):
    lines = ["## Navigation: what the calibration buys", "",
             "At rest at the calibration's site and temperature, each run starts without alignment from the truth's "
             "state at its first sample (attitude, velocity, position): a static alignment would fold the constant "
             "biases into the initial attitude and hide what a calibration does. Each IMU is calibrated on the "
             "thesis's 12 positions in a run of the same power-up (the same seed: the same turn-on bias and the "
             "same in-run noise, the calibration's best case), the run is navigated raw and corrected, and the same "
             "calibration corrects another power-up. `scripts/navigation_budget.py` computes the explanation with "
             "the first-order error model of a navigator at rest on the rotating Earth (Schuler and Foucault "
             "coupling, the held vertical channel): the raw error minus the corrected one must be the model's "
             "response to the terms the calibration removes; the corrected error must stay inside the 4-sigma bound "
             "of what it cannot remove (its own uncertainty as its file states it, the bias instability's wander, "
             "rate random walk, white noise, quantization, an unfitted g-sensitivity); and another power-up's error "
             "minus this one's inside the bound of what differs between power-ups by the profile (turn-on bias, the "
             "bias instability's state, noise).", ""]
    lines += navigation_part(
        report, "rlg", "Navigation-grade IMU (rlg_navigation): an hour at rest, 20 Hz",
        "Horizontal position, heading and tilt errors against the truth of the three runs; dashed: raw − corrected "
        "as measured, dotted: as the model makes it of the removed terms alone (the two coincide).",
        "The accelerometer terms give Schuler-bounded errors (b / w0² (1 − cos w0 t) horizontally, b / g in tilt); "
        "the gyro terms a position error that grows (R ν (t − sin(w0 t) / w0)) and a heading that drifts (ν_U t). "
        "At this grade the calibration's gyro bias is as uncertain as the bias itself, so the corrected run keeps a "
        "few hundred metres; another power-up brings a new turn-on bias and bias-instability state, more than the "
        "calibration took out. fit_calibration's gyro white-noise estimate (block means of 0.5 s) is about ten times "
        "the profile's 2.9e-7 rad/s/√Hz because at that length the 1-arcsec pulse quantization looks white; over a "
        "whole rest it averages as 1/T, not 1/√T, so the stated bias sigma, and the bound built on it, are loose.")
    lines += navigation_part(
        report, "mems", "MEMS IMU (tactical_mems): ten minutes at rest, 100 Hz",
        "The same for the tactical MEMS profile. Its free-inertial position is kilometres within minutes; what a "
        "MEMS navigator delivers is its attitude (the node's `attitude_only`).",
        "Tilts follow the horizontal gyro terms, held by the Schuler loop (ν sin(w0 t) / w0), plus the "
        "accelerometers' b / g; the heading drifts with the up gyro's term (ν_U t).")
    return lines


def rviz_section(report):
    lines = ["## rviz", ""]
    if os.path.exists(os.path.join(report, "rviz.png")):
        lines += figure(report, "rviz.png", "rviz",
                        "The navigator live in rviz (emulated navigation-grade IMU at rest, aligned for "
                        "60 s: body axes, odometry arrow along body x, path).")
    if os.path.exists(os.path.join(report, "rviz_allan.png")):
        lines += figure(report, "rviz_allan.png", "rviz Allan deviation panel",
                        "The Allan deviation panel during a live emulated recording (launch/characterise.launch, "
                        "tactical_mems at rest, 100 Hz, 20x real time): the gyro's x axis with its band, the model "
                        "allan_monitor identified after 20 min of record, and per term how much longer the "
                        "record must run for its amplitude to be known to 10 %.")
    reason_path = os.path.join(report, "rviz_skipped.txt")
    if os.path.exists(reason_path):
        lines += [f"*rviz pictures missing: {open(reason_path).read().strip()}.*", ""]
    elif len(lines) == 2:
        lines += ["*No rviz pictures.*", ""]
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("report")
    parser.add_argument("--profile", default="tactical_mems")
    args = parser.parse_args()
    if not os.path.isdir(args.report):
        sys.exit(f"report_index: {args.report} is not a folder")
    lines = [f"# imu_lab report: emulated `{args.profile}`", "",
             "Made by `scripts/demo`: each section is one tool on its own emulated test; the numbers are "
             "read from the files beside this page.", ""]
    lines += noise_section(args.report, args.profile)
    lines += spectrum_and_attitude_section(args.report)
    for section in (thermal_section, calibration_section):
        lines += section(args.report)
    lines += repeatability_section(args.report, args.profile)
    for section in (navigation_section, rviz_section):
        lines += section(args.report)
    target = os.path.join(args.report, "index.md")
    temporary = target + ".tmp"
    with open(temporary, "w") as handle:
        handle.write("\n".join(lines))
    os.replace(temporary, target)
    print(f"report_index: wrote {target}")


if __name__ == "__main__":
    main()
