#!/usr/bin/python3
"""rostest checker for launch/characterise.launch run the way a user runs it (characterise_launch.test):
roslaunch started by this checker, fed an emulated bag, ended as a user ends it.

- Live: the launch on this test's master with `rosbag play` feeding the topic; the report service
  answers `rosservice call` from a shell (the command-line tool needs std_srvs' Python class, which
  scripts/setup installs); then SIGINT to roslaunch, as Ctrl-C in its terminal, while a periodic
  identification runs (identify_period_s is 1 ms, so one is always under way once the first has
  published): the node abandons it, writes its report and exits within roslaunch's SIGINT timeout
  (no "escalating to SIGTERM"); the report is complete (every file, no staging folder left) and
  covers at least the samples the node's engine held before the interrupt.
- Bag mode: `bag:= start:= duration:= rviz:=false` on roslaunch's own master (as from a terminal):
  the replay of the given part ends, the node writes its report of every sample of that part and
  the launch ends by itself with status 0 and no "REQUIRED process has died" banner.
The waits are for events (a service, a message, a process's end); the limits only end a test that
hangs."""

import os
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import shutil
import unittest

import rosbag
import rospy
import rostest
import yaml
from diagnostic_msgs.msg import DiagnosticArray

# The package's own message classes are not imported: under `catkin_make run_tests` in a fresh
# workspace the environment is the one cached when cmake first ran, before the Python messages
# existed. The waits take any message; the sample count comes from /diagnostics.

EVENT_LIMIT_S = 240.0
BAG_DURATION_S = 1800.0
RATE_HZ = 100.0
PART_START_S = 100.0
PART_DURATION_S = 600.0
REPORT_FILES = (
    ["%s.csv" % name for name in ("adev", "oadev", "mdev", "ohdev", "hdev", "tdev", "totdev", "akdev", "hkdev")]
    + ["allan_summary.yaml", "noise.yaml", "kalibr_imu.yaml", "kalibr_imu_chain.yaml", "allan.png"]
    + ["noise_partial_%s_%s.csv" % (sensor, axis) for sensor in ("gyro", "accel") for axis in "xyz"])


class Launch:
    """roslaunch in a session of its own (as a terminal's foreground job), its output collected."""

    def __init__(self, arguments, environment=None):
        self.lines = []
        self.process = subprocess.Popen(["roslaunch"] + arguments, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        text=True, start_new_session=True, env=environment)
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        for line in self.process.stdout:
            self.lines.append(line)

    def interrupt(self):
        self.process.send_signal(signal.SIGINT)

    def wait(self):
        try:
            status = self.process.wait(timeout=EVENT_LIMIT_S)
        except subprocess.TimeoutExpired:
            os.killpg(self.process.pid, signal.SIGKILL)
            raise AssertionError("roslaunch did not end:\n" + self.output())
        self.reader.join(timeout=10.0)
        return status

    def output(self):
        return "".join(self.lines)

    def stop(self):
        if self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGKILL)
            self.process.wait()


def engine_samples():
    """The samples allan_monitor's engine holds, from its next diagnostics report."""
    while True:
        array = rospy.wait_for_message("/diagnostics", DiagnosticArray, timeout=EVENT_LIMIT_S)
        for status in array.status:
            for pair in status.values:
                if pair.key.startswith("engine samples"):
                    return int(pair.value)


def free_port():
    with socket.socket() as probe:
        probe.bind(("localhost", 0))
        return probe.getsockname()[1]


class CharacteriseLaunch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="imu_lab_characterise_launch_")
        cls.bag = os.path.join(cls.work, "static.bag")
        subprocess.run(["rosrun", "imu_lab", "emulate", "--duration-s", str(BAG_DURATION_S), "--rate-hz",
                        str(RATE_HZ), "--no-truth", "--no-increments", "-o", cls.bag], check=True,
                       stdout=subprocess.DEVNULL)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)

    def assert_complete_report(self, directory, output):
        entries = os.listdir(directory)
        missing = [name for name in REPORT_FILES if name not in entries]
        self.assertEqual(missing, [], "report files missing from %s:\n%s" % (directory, output))
        left = [name for name in entries if name.startswith(".") or ".tmp" in name]
        self.assertEqual(left, [], "temporaries left in %s" % directory)
        triads = yaml.safe_load(open(os.path.join(directory, "noise.yaml")))["triads"]
        for sensor in ("gyro", "accel"):
            self.assertEqual(sorted(triads[sensor]["axes"]), [sensor + "_" + axis for axis in "xyz"])
        return yaml.safe_load(open(os.path.join(directory, "allan_summary.yaml")))

    def assert_clean_end(self, output):
        for banner in ("escalating to SIGTERM", "escalating to SIGKILL", "REQUIRED process", "has died"):
            self.assertNotIn(banner, output, "roslaunch's output:\n" + output)

    def test_live_report_service_then_ctrl_c_during_an_identification(self):
        report = os.path.join(self.work, "live_report")
        launch = Launch(["imu_lab", "characterise.launch", "rviz:=false", "report_dir:=" + report,
                         "publish_period_s:=0.2", "identify_period_s:=0.001"])
        player = None
        try:
            rospy.wait_for_service("/allan_monitor/write_report", timeout=EVENT_LIMIT_S)
            player = subprocess.Popen(["rosbag", "play", "--quiet", "--rate=20", self.bag],
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            rospy.wait_for_message("/allan/gyro", rospy.AnyMsg, timeout=EVENT_LIMIT_S)

            # The documented service, from a shell.
            call = subprocess.run(["rosservice", "call", "/allan_monitor/write_report"], capture_output=True,
                                  text=True, timeout=EVENT_LIMIT_S)
            self.assertEqual(call.returncode, 0, call.stdout + call.stderr)
            self.assertIn("success: True", call.stdout)
            self.assert_complete_report(report, launch.output())

            # A periodic identification has finished; with a 1 ms period the next one is running.
            rospy.wait_for_message("/allan/noise", rospy.AnyMsg, timeout=EVENT_LIMIT_S)
            counted = engine_samples()
            launch.interrupt()
            self.assertEqual(launch.wait(), 0, launch.output())
        finally:
            launch.stop()
            if player is not None:
                player.kill()
                player.wait()
        output = launch.output()
        self.assert_clean_end(output)
        self.assertIn("periodic identification in progress was abandoned", output)
        summary = self.assert_complete_report(report, output)
        self.assertGreaterEqual(summary["samples"], counted)

    def test_bag_part_replayed_then_the_launch_ends_by_itself(self):
        report = os.path.join(self.work, "bag_report")
        port = free_port()
        environment = dict(os.environ, ROS_MASTER_URI="http://localhost:%d" % port)
        launch = Launch(["-p", str(port), "imu_lab", "characterise.launch", "rviz:=false", "bag:=" + self.bag,
                         "rate:=100", "start:=%g" % PART_START_S, "duration:=%g" % PART_DURATION_S,
                         "report_dir:=" + report], environment)
        try:
            status = launch.wait()
        finally:
            launch.stop()
        output = launch.output()
        self.assertEqual(status, 0, output)
        self.assert_clean_end(output)
        self.assertIn("the replay ended", output)
        summary = self.assert_complete_report(report, output)
        # rosbag play's part: from the first message's time + start to that + duration, both included.
        with rosbag.Bag(self.bag) as bag:
            first = bag.get_start_time()
            expected = sum(1 for _, _, t in bag.read_messages(topics=["/imu/raw"], raw=True)
                           if first + PART_START_S <= t.to_sec() <= first + PART_START_S + PART_DURATION_S)
        self.assertEqual(summary["samples"], expected)


if __name__ == "__main__":
    rospy.init_node("characterise_launch_check")
    rostest.rosrun("imu_lab", "characterise_launch_check", CharacteriseLaunch, sys.argv)
