#!/usr/bin/python3
"""What a calibration buys a strapdown system at rest, computed: the first-order error model of a
stationary navigator on the rotating Earth, driven by the terms the calibration removes and bounded
by the terms it cannot remove.

    scripts/navigation_budget.py FOLDER --profile NAME [--plot PNG] [--title TEXT] [--check]

FOLDER holds what scripts/demo leaves for one IMU at rest, each run navigated without alignment
from the truth (a self-alignment would absorb the biases and hide what the calibration does):
  raw_trajectory.csv, raw_trajectory_errors.csv   navigate on the raw run
  corrected_trajectory_errors.csv                 the same run after `correct --calibration`
  calibration.yaml                                fit_calibration on a run of the same power-up
  new_turn_on_trajectory_errors.csv (optional)    another power-up (seed), corrected the same way
Writes FOLDER/budget.yaml (the figures report_index.py quotes), prints a summary and, with --plot,
draws the runs, the computed response and the bound. With --check it exits 1 unless
  (a) raw minus corrected (horizontal position, attitude) is the model's response to the removed
      terms, raw output - K^-1 (raw output - b - G f), within the model's own first-order error;
  (b) the corrected errors stay inside the BOUND_SIGMAS bound of what the calibration cannot
      remove: its uncertainty as its file states it, the bias instability's wander, rate random
      walk, an unfitted g-sensitivity, white noise and angle quantization;
  (c) another power-up's errors minus these stay inside the bound of what differs between power-ups
      by the profile alone: turn-on bias, the bias instability's state, random walk and noise.

The model (ENU, small errors; psi is the small rotation with q_estimated = exp(psi) q_true, the
navigate tool's attitude error, and the velocity and position errors are components compared as
the tool compares them): with Earth rate W = (0, Wc, Ws) = W (0, cos L, sin L), radii M
(meridian) and N (prime vertical), gravity g and its height gradient, the held vertical channel's
gains k1, k2 (nav/vertical_channel.h), and constant gyro and accelerometer errors nu, b (ENU):
  d(dr_E)/dt = dv_E    d(dr_N)/dt = dv_N    d(dh)/dt = dv_U + k1 dh
  d(dv_E)/dt =  g psi_N + 2 Ws dv_N - 2 Wc dv_U + b_E
  d(dv_N)/dt = -g psi_E - 2 Ws dv_E + b_N
  d(dv_U)/dt = (dg/dh + k2) dh + 2 Wc dv_E + b_U        (dg/dh > 0: gravity falls with height)
  d(psi_E)/dt = nu_E + dv_N / M - Wc psi_U + Ws psi_N
  d(psi_N)/dt = nu_N - dv_E / N - Ws psi_E + Ws dr_N / M
  d(psi_U)/dt = nu_U - dv_E tan L / N + Wc psi_E - Wc dr_N / M
i.e. psi' = nu - d(omega_in) - omega_in x psi (the frame-rate error of the velocity and position
errors, and the Earth's turning), dv' = psi x f - 2 W x dv + b. The held channel's steady vertical
velocity (it absorbs the loop's k1 dh) reaches the east channel through the Coriolis term: metres
in an hour for a 50 micro-g vertical bias. Without Earth rate the horizontal part is two Schuler
channels: b / w0^2 (1 - cos w0 t), R nu (t - sin(w0 t) / w0) (Fomichev 2022; the bounds the nav tests
use). Responses to constant inputs and the covariance of white inputs come exactly from matrix
exponentials (Van Loan).
"""
import argparse
import csv
import math
import os
import sys

import numpy as np
import yaml
from scipy.linalg import expm

# WGS-84 (the navigator's default Earth, nav/earth_model.h).
SEMI_MAJOR_AXIS_M = 6378137.0
FLATTENING = 1.0 / 298.257223563
ECCENTRICITY_SQUARED = FLATTENING * (2.0 - FLATTENING)
EARTH_RATE_RAD_S = 7.292115e-5
EQUATORIAL_GRAVITY_M_S2 = 9.7803253359
SOMIGLIANA_K = 0.00193185265241
GRAVITY_RATIO_M = 0.00344978650684
# The held vertical channel's default loop (nav/vertical_channel.h): a double root at -1/30 s.
HELD_K1_PER_S = -2.0 / 30.0
HELD_K2_PER_S2 = -1.0 / 900.0 - 2.0 * EQUATORIAL_GRAVITY_M_S2 / SEMI_MAJOR_AXIS_M
# Flicker noise's Allan floor is 0.664 B; two averages a record apart differ by sqrt(2) of that:
# the bias a calibration measured and the one a later run sees differ by about 0.94 B (1 sigma).
BIAS_INSTABILITY_WANDER = math.sqrt(2.0) * 0.664
# Each run is checked at every output sample, four errors at a time: a per-sample 4-sigma bound
# would be crossed somewhere by the early, noise-dominated samples in about one run of ten;
# Bonferroni over ~100 effectively independent samples at 99.7 % family-wise gives ~4 sigma.
BOUND_SIGMAS = 4.0
# The model is first order: what it leaves out is of the order of the largest relative error (tilt
# and heading in rad, position error over the Earth's radius) times the response. Below that, the
# navigator's own error without sensor errors (test_navigate_ideal.cpp: under 5 cm; 0.1 arcsec).
EXPLANATION_FLOOR_M = 0.05
EXPLANATION_FLOOR_RAD = 0.1 / 206264.80624709636
ARCSEC_PER_RAD = 206264.80624709636


def normal_gravity(latitude, height):
    s2 = math.sin(latitude) ** 2
    g0 = EQUATORIAL_GRAVITY_M_S2 * (1.0 + SOMIGLIANA_K * s2) / math.sqrt(1.0 - ECCENTRICITY_SQUARED * s2)
    a, f = SEMI_MAJOR_AXIS_M, FLATTENING
    return g0 * (1.0 - 2.0 / a * (1.0 + f + GRAVITY_RATIO_M - 2.0 * f * s2) * height + 3.0 * height ** 2 / a ** 2)


class StaticErrorModel:
    """x = [dr_E, dr_N, dh, dv_E, dv_N, dv_U, psi_E, psi_N, psi_U],
    u = [nu_E, nu_N, nu_U, b_E, b_N, b_U]; the held vertical channel with the navigator's default
    gains (nav/vertical_channel.h)."""

    def __init__(self, latitude, height):
        s2 = math.sin(latitude) ** 2
        prime = SEMI_MAJOR_AXIS_M / math.sqrt(1.0 - ECCENTRICITY_SQUARED * s2) + height
        meridian = SEMI_MAJOR_AXIS_M * (1.0 - ECCENTRICITY_SQUARED) / (1.0 - ECCENTRICITY_SQUARED * s2) ** 1.5 + height
        g = normal_gravity(latitude, height)
        # Normal gravity's decrease with height (the free-air term of nav/earth_model.h).
        gravity_gradient = 2.0 * normal_gravity(latitude, 0.0) / SEMI_MAJOR_AXIS_M * (
            1.0 + FLATTENING + GRAVITY_RATIO_M - 2.0 * FLATTENING * s2)
        wc, ws = EARTH_RATE_RAD_S * math.cos(latitude), EARTH_RATE_RAD_S * math.sin(latitude)
        a = np.zeros((9, 9))
        a[0, 3] = a[1, 4] = 1.0
        a[2, 5], a[2, 2] = 1.0, HELD_K1_PER_S
        a[3, 7], a[3, 4], a[3, 5] = g, 2.0 * ws, -2.0 * wc
        a[4, 6], a[4, 3] = -g, -2.0 * ws
        a[5, 2], a[5, 3] = gravity_gradient + HELD_K2_PER_S2, 2.0 * wc
        a[6, 4], a[6, 8], a[6, 7] = 1.0 / meridian, -wc, ws
        a[7, 3], a[7, 6], a[7, 1] = -1.0 / prime, -ws, ws / meridian
        a[8, 3], a[8, 6], a[8, 1] = -math.tan(latitude) / prime, wc, -wc / meridian
        b = np.zeros((9, 6))
        b[6, 0] = b[7, 1] = b[8, 2] = 1.0
        b[3, 3] = b[4, 4] = b[5, 5] = 1.0
        self.a, self.b, self.gravity, self.earth_rate_enu = a, b, g, np.array([0.0, wc, ws])

    def sensitivity(self, t):
        """9x6: the state at t per unit constant input."""
        n, m = self.b.shape
        augmented = np.zeros((n + m, n + m))
        augmented[:n, :n], augmented[:n, n:] = self.a, self.b
        return expm(augmented * t)[:n, n:]

    def white_noise_covariances(self, times, input_psd):
        """9x9 state covariances at the (increasing) times from white inputs with these two-sided
        PSDs, stepped between the times (Van Loan over each step: over a whole hour the exponential
        of -A would grow as e^(t / 15 s) through the vertical loop and cancel catastrophically)."""
        n = self.a.shape[0]
        q = self.b @ np.diag(input_psd) @ self.b.T
        covariance, previous, result, steps = np.zeros((n, n)), 0.0, [], {}
        for t in times:
            dt = round(t - previous, 9)
            if dt not in steps:
                m = np.zeros((2 * n, 2 * n))
                m[:n, :n], m[:n, n:], m[n:, n:] = -self.a, q, self.a.T
                f = expm(m * dt)
                steps[dt] = (f[n:, n:].T, f[n:, n:].T @ f[:n, n:])
            transition, driven = steps[dt]
            covariance = transition @ covariance @ transition.T + driven
            result.append(covariance)
            previous = t
        return result


def quaternion_matrix(w, x, y, z):
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def read_rows(path):
    with open(path, newline="") as handle:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]


def profile_terms(profile_path, triad, unit):
    """Per-axis terms a calibration cannot remove, from the profile: white noise density, bias
    instability (coefficient, cutoff, longest correlation), rate random walk, run-to-run (turn-on)
    sigma, g-sensitivity matrix."""
    with open(profile_path) as handle:
        t = yaml.safe_load(handle)[triad]
    noise = t.get("noise", {})
    per_axis = lambda value: np.broadcast_to(np.asarray(value, dtype=float), (3,)).copy()
    instability = noise.get("bias_instability", {})
    return {
        "white": per_axis(noise.get("white_rate", {}).get(f"density_{unit}_per_sqrt_hz", 0.0)),
        "instability": per_axis(instability.get(f"coefficient_{unit}", 0.0)),
        "instability_cutoff_hz": float(instability.get("cutoff_frequency_hz", 1.0)),
        "instability_longest_s": float(instability.get("valid_tau_range_s", [1.0, 1.0])[1]),
        "random_walk": per_axis(noise.get("random_walk", {}).get(f"density_{unit}_per_sqrt_s", 0.0)),
        "turn_on": per_axis(t.get(f"bias_turn_on_sigma_{unit}", 0.0)),
        "g_sensitivity": np.array(t.get("g_sensitivity_rad_s_per_m_s2", np.zeros((3, 3))), dtype=float),
        # The angle's quantization: pulses with carry keep the emitted angle within one pulse of the
        # true one; the white-angle model adds a white angle error of sigma q per sample.
        "pulse_weight": float(t.get("quantization", {}).get("pulse_weight_rad", 0.0)),
        "white_angle": float(np.max(per_axis(t.get("quantization", {}).get("q_rad", 0.0)))),
    }


def flicker_spread(terms):
    """Per-axis 1-sigma of the bias instability's own state: the emulator's Markov bank starts
    stationary, so another power-up starts elsewhere. The two-sided PSD B^2 / (2 pi f) between
    1 / (2 pi tau_max) and the cutoff f0 integrates to (B^2 / pi) ln(2 pi f0 tau_max)."""
    spread = math.log(2.0 * math.pi * terms["instability_cutoff_hz"] * terms["instability_longest_s"]) / math.pi
    return terms["instability"] * math.sqrt(max(spread, 0.0))


def removed_terms(calibration, truth_rate, truth_force):
    """Raw minus corrected (body axes) for this input: output - K^-1 (output - b - G f), the
    correction calibration_corrector applies (accelerometers first)."""
    accel, gyro = calibration["accelerometer"], calibration["gyro"]
    accel_k = np.array(accel["scale_misalignment"])
    gyro_k = np.array(gyro["scale_misalignment"])
    g_sensitivity = np.array(gyro.get("g_sensitivity_rad_s_per_m_s2", np.zeros((3, 3))))
    corrected_force = np.linalg.solve(accel_k, truth_force - np.array(accel["bias_m_s2"]))
    corrected_rate = np.linalg.solve(gyro_k, truth_rate - np.array(gyro["bias_rad_s"]) - g_sensitivity @ corrected_force)
    return truth_rate - corrected_rate, truth_force - corrected_force


def calibration_residual_sigma(calibration, triad, unit, terms, input_body, force_body, duration_s):
    """Per-axis 1-sigma of the constant error left after a calibration of the same power-up: its
    own bias and K uncertainty (the file's sigmas), the bias instability's wander between its
    rests and the run (flicker's Allan floor 0.664 B, times sqrt(2) for two averages), the rate
    random walk over the run, and the g-sensitivity when the calibration did not fit it."""
    values = calibration[triad]
    variance = np.array(values[f"bias_sigma_{unit}"]) ** 2
    variance += (np.array(values["scale_misalignment_sigma"]) ** 2) @ (input_body ** 2)
    variance += (BIAS_INSTABILITY_WANDER * terms["instability"]) ** 2 + terms["random_walk"] ** 2 * duration_s
    if triad == "gyro" and not values.get("g_sensitivity_estimated", False):
        variance += (terms["g_sensitivity"] @ force_body) ** 2
    return np.sqrt(variance)


def power_up_difference_sigma(terms, duration_s):
    """Per-axis 1-sigma of the difference between two power-ups' constant errors, the same
    calibration removed from both (its error, the g-sensitivity and the temperature cancel): twice
    the variance of the turn-on bias, of the bias instability's state and of the random walk."""
    return np.sqrt(2.0 * (terms["turn_on"] ** 2 + flicker_spread(terms) ** 2 + terms["random_walk"] ** 2 * duration_s))


class Run:
    """Errors over a run: horizontal position (E, N) and attitude (E tilt, N tilt, heading)."""

    def __init__(self, times, position, attitude):
        self.times, self.position, self.attitude = times, position, attitude

    @staticmethod
    def read(path):
        """A navigate error CSV."""
        rows = read_rows(path)
        return Run(np.array([r["time_since_alignment_s"] for r in rows]),
                   np.array([[r["east_error_m"], r["north_error_m"]] for r in rows]),
                   np.array([[r[f"attitude_error_{a}_rad"] for a in ("east", "north", "up")] for r in rows]))


def bounds(model, times, c_body_to_enu, gyro_sigma, accel_sigma, gyro, accel, runs=1):
    """BOUND_SIGMAS x the RMS horizontal position error (both axes together) and each attitude
    component's, at each time: constant unknown per-axis errors of these sigmas in the body axes,
    and the white noise of `runs` independent runs (the largest axis's density on every ENU axis);
    the attitude's also the gyro angle quantization of each run (a pulse, or BOUND_SIGMAS q)."""
    gyro_white, accel_white = gyro["white"], accel["white"]
    quantization = runs * gyro["pulse_weight"] + BOUND_SIGMAS * math.sqrt(runs) * gyro["white_angle"]
    input_cov = np.zeros((6, 6))
    input_cov[:3, :3] = c_body_to_enu @ np.diag(gyro_sigma ** 2) @ c_body_to_enu.T
    input_cov[3:, 3:] = c_body_to_enu @ np.diag(accel_sigma ** 2) @ c_body_to_enu.T
    psd = runs * np.array([gyro_white.max() ** 2] * 3 + [accel_white.max() ** 2] * 3)
    position, attitude = [], []
    for t, white in zip(times, model.white_noise_covariances(times, psd)):
        s = model.sensitivity(t)
        covariance = s @ input_cov @ s.T + white
        position.append(BOUND_SIGMAS * math.sqrt(np.trace(covariance[:2, :2])))
        attitude.append(BOUND_SIGMAS * np.sqrt(np.diag(covariance)[6:]) + quantization)
    return np.array(position), np.array(attitude)


def inside(run, position_bound, attitude_bound):
    n = len(run.times)
    position_fraction = np.linalg.norm(run.position, axis=1) / np.maximum(position_bound[:n], 1e-12)
    attitude_fraction = np.abs(run.attitude) / np.maximum(attitude_bound[:n], 1e-15)
    worst = float(max(position_fraction.max(), attitude_fraction.max()))
    return {"final_position_m": float(np.linalg.norm(run.position[-1])),
            "max_position_m": float(np.linalg.norm(run.position, axis=1).max()),
            "final_attitude_arcsec": (run.attitude[-1] * ARCSEC_PER_RAD).tolist(),
            "max_attitude_arcsec": (np.abs(run.attitude).max(axis=0) * ARCSEC_PER_RAD).tolist(),
            "position_bound_final_m": float(position_bound[n - 1]),
            "attitude_bound_final_arcsec": (attitude_bound[n - 1] * ARCSEC_PER_RAD).tolist(),
            "worst_fraction_of_bound": worst, "inside": worst <= 1.0}


def budget(folder, profile_path):
    raw = Run.read(os.path.join(folder, "raw_trajectory_errors.csv"))
    corrected = Run.read(os.path.join(folder, "corrected_trajectory_errors.csv"))
    start = read_rows(os.path.join(folder, "raw_trajectory.csv"))[0]
    with open(os.path.join(folder, "calibration.yaml")) as handle:
        calibration = yaml.safe_load(handle)
    if len(raw.times) != len(corrected.times) or not np.array_equal(raw.times, corrected.times):
        raise SystemExit("navigation_budget: the raw and corrected error CSVs are not at the same times")
    latitude, height = start["latitude_rad"], start["height_m"]
    c = quaternion_matrix(start["qw"], start["qx"], start["qy"], start["qz"])  # the truth's, at the start
    model = StaticErrorModel(latitude, height)
    truth_rate = c.T @ model.earth_rate_enu
    truth_force = c.T @ np.array([0.0, 0.0, model.gravity])
    times, duration = raw.times, float(raw.times[-1])

    # (a) raw - corrected = the model's response to the removed terms.
    removed_rate, removed_force = removed_terms(calibration, truth_rate, truth_force)
    u = np.concatenate([c @ removed_rate, c @ removed_force])
    predicted = np.array([model.sensitivity(t) @ u for t in times])
    position_mismatch = np.linalg.norm(raw.position - corrected.position - predicted[:, :2], axis=1)
    attitude_mismatch = np.abs(raw.attitude - corrected.attitude - predicted[:, 6:]).max(axis=1)
    relative = np.abs(raw.attitude).max() + np.linalg.norm(raw.position, axis=1).max() / SEMI_MAJOR_AXIS_M
    position_tolerance = relative * np.linalg.norm(predicted[:, :2], axis=1).max() + EXPLANATION_FLOOR_M
    attitude_tolerance = relative * np.abs(predicted[:, 6:]).max() + EXPLANATION_FLOOR_RAD
    explained = bool(position_mismatch.max() <= position_tolerance and attitude_mismatch.max() <= attitude_tolerance)

    # (b) the corrected errors inside the bound of what the calibration cannot remove.
    gyro, accel = profile_terms(profile_path, "gyro", "rad_s"), profile_terms(profile_path, "accelerometer", "m_s2")
    gyro_sigma = calibration_residual_sigma(calibration, "gyro", "rad_s", gyro, truth_rate, truth_force, duration)
    accel_sigma = calibration_residual_sigma(calibration, "accelerometer", "m_s2", accel, truth_force, truth_force,
                                             duration)
    position_bound, attitude_bound = bounds(model, times, c, gyro_sigma, accel_sigma, gyro, accel)
    result = {
        "duration_s": duration,
        "latitude_deg": math.degrees(latitude),
        "raw": inside(raw, np.full(len(times), np.inf), np.full((len(times), 3), np.inf)),
        "removed_terms": {
            "gyro_enu_rad_s": (c @ removed_rate).tolist(),
            "accel_enu_m_s2": (c @ removed_force).tolist(),
            "predicted_final_position_m": float(np.linalg.norm(predicted[-1, :2])),
            "predicted_final_attitude_arcsec": (predicted[-1, 6:] * ARCSEC_PER_RAD).tolist(),
            "measured_final_position_m": float(np.linalg.norm(raw.position[-1] - corrected.position[-1])),
            "measured_final_attitude_arcsec": ((raw.attitude[-1] - corrected.attitude[-1]) * ARCSEC_PER_RAD).tolist(),
            "worst_position_mismatch_m": float(position_mismatch.max()),
            "position_tolerance_m": float(position_tolerance),
            "worst_attitude_mismatch_arcsec": float(attitude_mismatch.max() * ARCSEC_PER_RAD),
            "attitude_tolerance_arcsec": float(attitude_tolerance * ARCSEC_PER_RAD),
            "largest_relative_error": float(relative),
            "explained": explained,
        },
        "corrected": inside(corrected, position_bound, attitude_bound),
        "residual_sigma": {"gyro_rad_s": gyro_sigma.tolist(), "accel_m_s2": accel_sigma.tolist(),
                           "of_which_calibration_gyro_bias_rad_s": calibration["gyro"]["bias_sigma_rad_s"],
                           "of_which_calibration_accel_bias_m_s2": calibration["accelerometer"]["bias_sigma_m_s2"]},
    }
    curves = {"times": times, "raw": raw, "corrected": corrected, "predicted": predicted}
    new_path = os.path.join(folder, "new_turn_on_trajectory_errors.csv")
    if os.path.exists(new_path):
        # Another power-up corrected by the same calibration: its error minus the same-power-up
        # run's is what differs between power-ups, bounded by the profile alone.
        new = Run.read(new_path)
        n = len(new.times)
        if not np.array_equal(new.times, times[:n]):
            raise SystemExit("navigation_budget: the other power-up's error CSV is not at the same times")
        difference = Run(new.times, new.position - corrected.position[:n], new.attitude - corrected.attitude[:n])
        difference_bounds = bounds(model, new.times, c, power_up_difference_sigma(gyro, duration),
                                   power_up_difference_sigma(accel, duration), gyro, accel, runs=2)
        result["new_turn_on"] = inside(new, np.full(n, np.inf), np.full((n, 3), np.inf))
        result["power_up_difference"] = inside(difference, *difference_bounds)
        result["power_up_difference"]["sigma"] = {
            "gyro_rad_s": power_up_difference_sigma(gyro, duration).tolist(),
            "accel_m_s2": power_up_difference_sigma(accel, duration).tolist()}
        curves.update(new_turn_on=new)
    return result, curves


def plot(curves, png_path, title):
    """Horizontal position, heading and tilt errors of each run; beside them raw minus corrected as
    measured (dashed) and as the model makes it of the removed terms (dotted)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = curves["times"] / 60.0
    figure, (position, heading, tilt) = plt.subplots(3, 1, sharex=True, figsize=(8, 9))
    runs = [("raw", "raw", "C3"), ("corrected", "corrected, same power-up", "C0")]
    if "new_turn_on" in curves:
        runs.append(("new_turn_on", "corrected, another power-up", "C2"))
    for key, label, colour in runs:
        run = curves[key]
        minutes = run.times / 60.0
        position.plot(minutes, np.linalg.norm(run.position, axis=1), colour, label=label)
        heading.plot(minutes, run.attitude[:, 2] * ARCSEC_PER_RAD, colour, label=label)
        tilt.plot(minutes, np.linalg.norm(run.attitude[:, :2], axis=1) * ARCSEC_PER_RAD, colour, label=label)
    raw, corrected, predicted = curves["raw"], curves["corrected"], curves["predicted"]
    measured = Run(raw.times, raw.position - corrected.position, raw.attitude - corrected.attitude)
    for run, style, label in ((measured, "k--", "raw − corrected"),
                              (Run(curves["times"], predicted[:, :2], predicted[:, 6:]), "y:",
                               "computed: the removed terms alone")):
        position.plot(t, np.linalg.norm(run.position, axis=1), style, label=label)
        heading.plot(t, run.attitude[:, 2] * ARCSEC_PER_RAD, style, label=label)
        tilt.plot(t, np.linalg.norm(run.attitude[:, :2], axis=1) * ARCSEC_PER_RAD, style, label=label)
    position.set_ylabel("horizontal position error [m]")
    heading.set_ylabel("heading error [arcsec]")
    tilt.set_ylabel("tilt error [arcsec]")
    tilt.set_xlabel("time since the start [min]")
    for axes in (position, heading, tilt):
        axes.grid(True, alpha=0.3)
    position.legend(fontsize=8)
    figure.suptitle(title)
    figure.tight_layout()
    temporary = png_path + ".tmp.png"
    figure.savefig(temporary, dpi=100)
    os.replace(temporary, png_path)


def summary(result):
    r, b = result["removed_terms"], result
    arcsec = lambda values: " ".join(f"{v:.1f}" for v in values)
    lines = [
        f"navigation_budget: {b['duration_s']:.0f} s at rest at {b['latitude_deg']:.2f} deg, started from the truth",
        f"  raw: horizontal {b['raw']['final_position_m']:.2f} m at the end (max {b['raw']['max_position_m']:.2f}), "
        f"attitude E/N/U {arcsec(b['raw']['final_attitude_arcsec'])} arcsec",
        f"  removed terms (ENU): gyro {np.array(r['gyro_enu_rad_s'])} rad/s, accel {np.array(r['accel_enu_m_s2'])} m/s^2;"
        f" computed effect {r['predicted_final_position_m']:.2f} m, attitude {arcsec(r['predicted_final_attitude_arcsec'])}"
        f" arcsec; raw minus corrected {r['measured_final_position_m']:.2f} m, {arcsec(r['measured_final_attitude_arcsec'])}"
        f" arcsec; worst mismatch {r['worst_position_mismatch_m']:.3g} m (tolerance {r['position_tolerance_m']:.3g}),"
        f" {r['worst_attitude_mismatch_arcsec']:.3g} arcsec (tolerance {r['attitude_tolerance_arcsec']:.3g}): "
        f"{'explained' if r['explained'] else 'NOT EXPLAINED'}",
    ]
    for key, label in (("corrected", "corrected, same power-up"),
                       ("power_up_difference", "another power-up minus the same power-up (both corrected)")):
        if key not in result:
            continue
        c = result[key]
        if key == "power_up_difference":
            n = result["new_turn_on"]
            lines.append(f"  corrected, another power-up: horizontal {n['final_position_m']:.2f} m (max "
                         f"{n['max_position_m']:.2f}), attitude E/N/U {arcsec(n['final_attitude_arcsec'])} arcsec")
        lines.append(f"  {label}: horizontal {c['final_position_m']:.2f} m (max {c['max_position_m']:.2f}; 4-sigma bound "
                     f"{c['position_bound_final_m']:.2f} at the end), attitude E/N/U {arcsec(c['final_attitude_arcsec'])}"
                     f" arcsec (bound {arcsec(c['attitude_bound_final_arcsec'])}): "
                     f"{'inside' if c['inside'] else 'OUTSIDE'} the bound (worst fraction {c['worst_fraction_of_bound']:.2f})")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--profile", required=True, help="the sensor profile's name (config/sensors) or YAML path")
    parser.add_argument("--plot", help="also plot the runs, the computed effect and the bound into this PNG")
    parser.add_argument("--title", default="Navigation at rest from the truth: raw, corrected, computed")
    parser.add_argument("--check", action="store_true", help="exit 1 unless explained and inside the bounds")
    args = parser.parse_args()
    profile = args.profile
    if not os.path.exists(profile):
        profile = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "config", "sensors", profile + ".yaml")
    result, curves = budget(args.folder, profile)
    target = os.path.join(args.folder, "budget.yaml")
    with open(target + ".tmp", "w") as handle:
        yaml.safe_dump(result, handle, sort_keys=False)
    os.replace(target + ".tmp", target)
    if args.plot:
        plot(curves, args.plot, args.title)
    print(summary(result))
    if args.check:
        ok = result["removed_terms"]["explained"] and result["corrected"]["inside"]
        ok = ok and result.get("power_up_difference", {}).get("inside", True)
        sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
