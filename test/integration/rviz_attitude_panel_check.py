#!/usr/bin/python3
"""rostest checker for rviz_attitude_panel.test: rviz with the shipped config/rviz/navigation.rviz
under a virtual X server (scripts/rviz_session.py) beside the live emulator and strapdown
navigator. The attitude panel loads without a plugin error and, once the navigator has aligned,
draws the solution's angles with the alignment's sigmas and the input health from /diagnostics; a
screenshot shows its text: dark table pixels and the OK colour of the health lines
(src/rviz/attitude_panel.cpp) over its white background, not a blank or one-colour area.

Parameter: ~screenshot (path to keep the PNG; "": none kept)."""

import os
import re
import shutil
import sys
import tempfile
import unittest

import rospkg
import rospy
import rostest

PACKAGE = rospkg.RosPack().get_path("imu_lab")
sys.path.insert(0, os.path.join(PACKAGE, "scripts"))
from rviz_session import ATTITUDE_PAINTED, capture, count_near, crop_pixels, plot_region  # noqa: E402

TEXT_RGB = (0, 0, 0)
OK_RGB = (0, 130, 0)  # src/rviz/attitude_panel.cpp, level_colour(OK)
# The waits are for events (a log line); this limit only ends a test that hangs.
EVENT_LIMIT_S = 150.0
COMPLETE = re.compile(r"^the attitude with the alignment's sigmas and (?P<statuses>\d+) health statuses$")


class RvizAttitudePanel(unittest.TestCase):
    def test_panel_draws_the_solution_the_sigmas_and_the_health(self):
        def complete(match):
            found = COMPLETE.match(match.group("what"))
            return found is not None and int(found.group("statuses")) >= 1

        with tempfile.TemporaryDirectory(prefix="imu_lab_rviz_test_") as work:
            png = os.path.join(work, "screen.png")
            painted, plugin_errors = capture(os.path.join(PACKAGE, "config", "rviz", "navigation.rviz"),
                                             lambda rviz: rviz.wait_for_line(ATTITUDE_PAINTED, complete, EVENT_LIMIT_S),
                                             png)
            self.assertEqual(plugin_errors, [], "rviz logged plugin errors")
            keep = rospy.get_param("~screenshot", "")
            if keep:
                shutil.copyfile(png, keep)
            region = plot_region(painted)
            width, height = region[2], region[3]
            self.assertGreater(width, 200)
            self.assertGreater(height, 120)
            crop_width, crop_height, pixels = crop_pixels(png, region, os.path.join(work, "panel.ppm"))
        self.assertEqual((crop_width, crop_height), (width, height), "the panel lies inside the screen")
        text = count_near(pixels, TEXT_RGB, 90)
        ok = count_near(pixels, OK_RGB, 40)
        white = count_near(pixels, (255, 255, 255), 0)
        rospy.loginfo("rviz_attitude_panel_check: %s; panel %dx%d: %d text, %d OK-health, %d white pixels",
                      painted.group("what"), width, height, text, ok, white)
        # Four table lines and the solution line of about 30 characters each leave several hundred
        # dark pixels; a health line some tens in its colour; a blank panel none.
        self.assertGreater(text, 300, "no table in the panel")
        self.assertGreater(ok, 30, "no input health line in the panel")
        self.assertGreater(white, width * height // 2, "the panel's white background is missing")


if __name__ == "__main__":
    rospy.init_node("rviz_attitude_panel_check")
    rostest.rosrun("imu_lab", "rviz_attitude_panel_check", RvizAttitudePanel, sys.argv)
