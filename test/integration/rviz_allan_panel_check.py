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
import sys
import tempfile
import unittest

import rospkg
import rospy
import rostest

PACKAGE = rospkg.RosPack().get_path("imu_lab")
sys.path.insert(0, os.path.join(PACKAGE, "scripts"))
from rviz_session import capture, count_near, crop_pixels, plot_region  # noqa: E402

# Colours of src/rviz/allan_plot_widget.cpp.
MEASURED_RGB = (20, 20, 20)
TOTAL_RGB = (200, 0, 0)
# The waits are for events (a log line, a message, a service); this limit only ends a test that hangs.
EVENT_LIMIT_S = 150.0


class RvizAllanPanel(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="imu_lab_rviz_test_")

    def tearDown(self):
        shutil.rmtree(self.work, ignore_errors=True)

    def test_panel_draws_the_live_curves_and_the_model(self):
        # allan_monitor identifies every identify_period_s on its own (its latched message may be
        # there before rviz is): the panel draws the live curve, and the model once a record is long
        # enough for the fit.
        png = os.path.join(self.work, "screen.png")
        fitted, plugin_errors = capture(os.path.join(PACKAGE, "config", "rviz", "characterise.rviz"),
                                        lambda rviz: rviz.wait_for_painted(want_model=True, limit_s=EVENT_LIMIT_S), png)
        self.assertIn("gyro x oadev", fitted.group("what"))
        self.assertGreater(int(fitted.group("points")), 3)
        self.assertGreaterEqual(int(fitted.group("series")), 2, "the total and at least one term")
        self.assertEqual(plugin_errors, [], "rviz logged plugin errors")
        keep = rospy.get_param("~screenshot", "")
        if keep:
            shutil.copyfile(png, keep)
            rospy.loginfo("rviz_allan_panel_check: screenshot %s", keep)

        x, y, width, height = plot_region(fitted)
        self.assertGreater(width, 200)
        self.assertGreater(height, 150)
        crop_width, crop_height, pixels = crop_pixels(png, (x, y, width, height), os.path.join(self.work, "plot.ppm"))
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
