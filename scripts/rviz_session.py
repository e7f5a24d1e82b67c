"""rviz with a config under its own virtual X server (Xvfb), for the rviz test and the pictures:
start it, read its log, wait for the Allan panel to paint, take a screenshot (ImageMagick
`import`). Needs a ROS master (ROS_MASTER_URI) and rviz, xvfb, imagemagick (scripts/setup).

The Allan panel (src/rviz/allan_panel.cpp) logs each new picture it paints with the plot's place
on the screen: "imu_lab allan panel: painted gyro x oadev with the fitted model (12 points, 5 model
curves) at screen 10 60 size 640 420"; waiting for that line waits for the picture itself."""

import os
import queue
import re
import subprocess
import threading

PAINTED = re.compile(r"imu_lab allan panel: painted (?P<what>.*) \((?P<points>\d+) points, (?P<series>\d+) model curves\) "
                     r"at screen (?P<x>-?\d+) (?P<y>-?\d+) size (?P<w>\d+) (?P<h>\d+)")
# What rviz logs when a plugin cannot be created or a config entry names an unknown class.
PLUGIN_ERROR = re.compile(r"PluginlibFactory|failed to load|could not load|The plugin for class", re.IGNORECASE)


class RvizSessionError(RuntimeError):
    pass


class RvizSession:
    def __init__(self, config, screen="1280x800x24"):
        self.config = config
        self.screen = screen
        self.processes = []
        self.lines = queue.Queue()
        self.log = []
        self.display = None

    def __enter__(self):
        self.start()
        return self

    def __exit__(self, *exc):
        self.close()

    def start(self):
        # -displayfd: Xvfb picks a free display and writes its number once it accepts clients.
        read_end, write_end = os.pipe()
        xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", self.screen, "-nolisten", "tcp"],
                                pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.processes.append(xvfb)
        os.close(write_end)
        with os.fdopen(read_end) as display_pipe:
            number = display_pipe.readline().strip()
        if not number.isdigit():
            raise RvizSessionError("Xvfb did not start (is xvfb installed?)")
        self.display = ":" + number
        # Mesa's software renderer: no GPU behind Xvfb.
        # Its log lines as they come: rosconsole leaves stdout block-buffered in a pipe.
        environment = dict(os.environ, DISPLAY=self.display, LIBGL_ALWAYS_SOFTWARE="1",
                           ROSCONSOLE_STDOUT_LINE_BUFFERED="1")
        rviz = subprocess.Popen(["stdbuf", "-oL", "rosrun", "rviz", "rviz", "-d", self.config, "__name:=rviz_" + number],
                                env=environment, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, bufsize=1)
        self.processes.append(rviz)

        def forward():
            for line in rviz.stdout:
                self.lines.put(line.rstrip("\n"))
            self.lines.put(None)

        threading.Thread(target=forward, daemon=True).start()

    def wait_for_painted(self, want_model, limit_s):
        """The panel's first 'painted' line with (want_model) or without the fitted model. limit_s
        only ends a session that hangs: the wait is for rviz's log line."""
        while True:
            try:
                line = self.lines.get(timeout=limit_s)
            except queue.Empty:
                raise RvizSessionError("rviz logged nothing for %.0f s; its last lines:\n%s" %
                                       (limit_s, "\n".join(self.log[-20:])))
            if line is None:
                raise RvizSessionError("rviz ended; its last lines:\n" + "\n".join(self.log[-40:]))
            self.log.append(line)
            match = PAINTED.search(line)
            if match and (int(match.group("series")) > 0) == want_model:
                return match

    def plugin_errors(self):
        return [line for line in self.log if PLUGIN_ERROR.search(line) or "[ERROR]" in line]

    def screenshot(self, path):
        # What the panel painted is on the X server already: Xvfb has no compositor.
        subprocess.run(["import", "-display", self.display, "-window", "root", path], check=True)

    def close(self):
        for process in reversed(self.processes):
            if process.poll() is None:
                process.terminate()
                try:
                    process.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    process.kill()
                    process.wait()
        self.processes = []


def plot_region(painted):
    """x, y, width, height of the plot from a 'painted' match."""
    return tuple(int(painted.group(key)) for key in ("x", "y", "w", "h"))
