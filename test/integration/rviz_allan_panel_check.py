#!/usr/bin/python3
"""rostest checker for rviz_allan_panel.test: rviz with the shipped config/rviz/characterise.rviz
under a virtual X server (scripts/rviz_session.py) beside the live emulator and allan_monitor.
The Allan panel loads without a plugin error and draws the live curve with the fitted model once
allan_monitor's periodic identification (identify_period_s) has published one; a screenshot shows
the curves in the panel's plot: pixels of the measured curve's and the fitted total's colours
(src/rviz/allan_plot_widget.cpp) over its white background, not a blank or one-colour area.

Parameter: ~screenshot (path to keep the PNG; "": none kept)."""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import rospkg
import rospy
import rostest

PACKAGE = rospkg.RosPack().get_path("imu_lab")
sys.path.insert(0, os.path.join(PACKAGE, "scripts"))
from rviz_session import RvizSession, plot_region  # noqa: E402

# Colours of src/rviz/allan_plot_widget.cpp.
MEASURED_RGB = (20, 20, 20)
TOTAL_RGB = (200, 0, 0)
# The waits are for events (a log line, a message, a service); this limit only ends a test that hangs.
EVENT_LIMIT_S = 150.0


def read_ppm(path):
    """Width, height and the RGB bytes of a binary PPM (P6, maxval 255, no comments: ImageMagick's)."""
    with open(path, "rb") as handle:
        data = handle.read()
    magic, width, height, maxval, pixels = data.split(maxsplit=4)
    assert magic == b"P6" and maxval == b"255", (magic, maxval)
    return int(width), int(height), pixels[:3 * int(width) * int(height)]


def count_near(pixels, rgb, tolerance):
    count = 0
    for i in range(0, len(pixels), 3):
        if (abs(pixels[i] - rgb[0]) <= tolerance and abs(pixels[i + 1] - rgb[1]) <= tolerance
                and abs(pixels[i + 2] - rgb[2]) <= tolerance):
            count += 1
    return count


class RvizAllanPanel(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="imu_lab_rviz_test_")

    def tearDown(self):
        shutil.rmtree(self.work, ignore_errors=True)

    def test_panel_draws_the_live_curves_and_the_model(self):
        with RvizSession(os.path.join(PACKAGE, "config", "rviz", "characterise.rviz")) as rviz:
            # allan_monitor identifies every identify_period_s on its own (its latched message may
            # be there before rviz is): the panel draws the live curve, and the model once a record
            # is long enough for the fit.
            fitted = rviz.wait_for_painted(want_model=True, limit_s=EVENT_LIMIT_S)
            self.assertIn("gyro x oadev", fitted.group("what"))
            self.assertGreater(int(fitted.group("points")), 3)
            self.assertGreaterEqual(int(fitted.group("series")), 2, "the total and at least one term")

            png = os.path.join(self.work, "screen.png")
            rviz.screenshot(png)
            self.assertEqual(rviz.plugin_errors(), [], "rviz logged plugin errors")
        keep = rospy.get_param("~screenshot", "")
        if keep:
            shutil.copyfile(png, keep)
            rospy.loginfo("rviz_allan_panel_check: screenshot %s", keep)

        x, y, width, height = plot_region(fitted)
        self.assertGreater(width, 200)
        self.assertGreater(height, 150)
        region = os.path.join(self.work, "plot.ppm")
        subprocess.run(["convert", png, "-crop", "%dx%d+%d+%d" % (width, height, x, y), "+repage", region], check=True)
        crop_width, crop_height, pixels = read_ppm(region)
        self.assertEqual((crop_width, crop_height), (width, height), "the plot lies inside the screen")
        measured = count_near(pixels, MEASURED_RGB, 30)
        total = count_near(pixels, TOTAL_RGB, 40)
        white = count_near(pixels, (255, 255, 255), 0)
        rospy.loginfo("rviz_allan_panel_check: plot %dx%d: %d measured-curve, %d fitted-total, %d white pixels",
                      width, height, measured, total, white)
        # A curve drawn across the plot covers at least half its width in pixels; a blank plot none.
        self.assertGreater(measured, width // 2, "no measured curve in the panel")
        self.assertGreater(total, width // 2, "no fitted total in the panel")
        self.assertGreater(white, width * height // 4, "the plot's white background is missing")


if __name__ == "__main__":
    rospy.init_node("rviz_allan_panel_check")
    rostest.rosrun("imu_lab", "rviz_allan_panel_check", RvizAllanPanel, sys.argv)
