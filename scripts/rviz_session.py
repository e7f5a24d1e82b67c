"""rviz with a config under its own virtual X server (Xvfb), for the rviz test and the pictures:
start it, read its log, wait for a panel to paint, take a screenshot (ImageMagick `import`).
Needs a ROS master (ROS_MASTER_URI) and rviz, xvfb, imagemagick (scripts/setup).

The panels (src/rviz/) log each new picture they paint with its place on the screen: "imu_lab allan
panel: painted gyro x oadev with the fitted model (12 points, 5 model curves) at screen 10 60 size
640 420", "imu_lab attitude panel: painted the attitude with the alignment's sigmas and 2 health
statuses at screen 10 60 size 420 260"; waiting for that line waits for the picture itself."""

import os
import queue
import re
import subprocess
import threading

PAINTED = re.compile(r"imu_lab allan panel: painted (?P<what>.*) \((?P<points>\d+) points, (?P<series>\d+) model curves\) "
                     r"at screen (?P<x>-?\d+) (?P<y>-?\d+) size (?P<w>\d+) (?P<h>\d+)")
ATTITUDE_PAINTED = re.compile(r"imu_lab attitude panel: painted (?P<what>.*) at screen (?P<x>-?\d+) (?P<y>-?\d+) "
                              r"size (?P<w>\d+) (?P<h>\d+)")
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
        """The Allan panel's first 'painted' line with (want_model) or without the fitted model.
        limit_s only ends a session that hangs: the wait is for rviz's log line."""
        return self.wait_for_line(PAINTED, lambda match: (int(match.group("series")) > 0) == want_model, limit_s)

    def wait_for_line(self, pattern, accept, limit_s):
        """The first match of pattern in rviz's log that accept(match) takes; limit_s as above."""
        while True:
            try:
                line = self.lines.get(timeout=limit_s)
            except queue.Empty:
                raise RvizSessionError("rviz logged nothing for %.0f s; its last lines:\n%s" %
                                       (limit_s, "\n".join(self.log[-20:])))
            if line is None:
                raise RvizSessionError("rviz ended; its last lines:\n" + "\n".join(self.log[-40:]))
            self.log.append(line)
            match = pattern.search(line)
            if match and accept(match):
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


def capture(config, wait, png, screen="1280x800x24"):
    """rviz with config until wait(session) returns (a panel's 'painted' match), then a screenshot
    to png. Returns that match and the plugin errors rviz logged."""
    with RvizSession(config, screen) as rviz:
        painted = wait(rviz)
        rviz.screenshot(png)
        return painted, rviz.plugin_errors()


def read_ppm(path):
    """Width, height and the RGB bytes of a binary PPM (P6, maxval 255, no comments: ImageMagick's)."""
    with open(path, "rb") as handle:
        data = handle.read()
    magic, width, height, maxval, pixels = data.split(maxsplit=4)
    assert magic == b"P6" and maxval == b"255", (magic, maxval)
    return int(width), int(height), pixels[:3 * int(width) * int(height)]


def count_near(pixels, rgb, tolerance):
    """Pixels of RGB bytes within tolerance of rgb in every channel."""
    count = 0
    for i in range(0, len(pixels), 3):
        if (abs(pixels[i] - rgb[0]) <= tolerance and abs(pixels[i + 1] - rgb[1]) <= tolerance
                and abs(pixels[i + 2] - rgb[2]) <= tolerance):
            count += 1
    return count


def crop_pixels(png, region, work_ppm):
    """Width, height and RGB bytes of region (x, y, width, height) of a screenshot."""
    x, y, width, height = region
    subprocess.run(["convert", png, "-crop", "%dx%d+%d+%d" % (width, height, x, y), "+repage", work_ppm], check=True)
    return read_ppm(work_ppm)


def plot_region(painted):
    """x, y, width, height of the plot from a 'painted' match."""
    return tuple(int(painted.group(key)) for key in ("x", "y", "w", "h"))
