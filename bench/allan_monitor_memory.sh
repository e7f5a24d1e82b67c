#!/usr/bin/env bash
# The long run as a node: the emulator (tactical_mems at rest, 1 kHz, no truth or increments) and
# allan_monitor as nodelets in one manager on a private roscore, so the samples pass as shared
# pointers (separate processes would spend ~42 us of CPU per sample in transport), faster than real
# time by REALTIME_FACTOR (default 50). The monitor's input queue holds 10 wall seconds of input
# (queue_size = 10 * 1000 * factor; the node's default 20000 holds 20 s at real time): on a shared
# machine the manager can stall for seconds, and faster-than-real time must not turn that into drops
# a real-time run would not have. Every simulated hour (every tenth of the run when it is shorter than
# 2 h) it prints the samples the monitor received, the gaps in their stamps (dropped samples), the
# engine state size from the monitor's diagnostics and the manager's resident set (VmRSS); then
# published against received, a verdict on the resident set, and the manager's wall and CPU time.
# The core version is bench/allan_emulated_memory. Not a test (24 h at the default factor takes
# 30-45 min of wall time): run by hand in a sourced workspace, at a low priority on a shared machine:
#   nice -n 10 bench/allan_monitor_memory.sh [hours=24] [realtime_factor=50]
set -euo pipefail
hours=${1:-24}
realtime_factor=${2:-50}
rate_hz=1000
source "$(dirname "$0")/private_roscore.sh" 12300
cat > "$ROS_HOME/params.yaml" <<EOF
allan_monitor: {report_dir: $ROS_HOME/allan_report, plot: false, identify: false,
                queue_size: $(echo "10 * $rate_hz * $realtime_factor / 1" | bc)}
imu_emulator: {profile: tactical_mems, scenario: static, rate_hz: $rate_hz, realtime_factor: $realtime_factor,
               duration_s: $(echo "$hours * 3600" | bc -l), publish_truth: false, publish_increments: false}
EOF
rosparam load "$ROS_HOME/params.yaml"

started=$(date +%s.%N)
rosrun nodelet nodelet manager __name:=allan_memory_manager > "$ROS_HOME/manager.log" 2>&1 & manager=$!
pids=("$manager" "${pids[@]}")
# The monitor first, so it has subscribed before the emulator's first sample.
rosrun nodelet nodelet load imu_lab/AllanMonitorNodelet allan_memory_manager __name:=allan_monitor \
  imu/raw:=/imu/raw > "$ROS_HOME/monitor_loader.log" 2>&1 & pids=($! "${pids[@]}")
until rosservice list 2>/dev/null | grep -q '^/allan_monitor/write_report$'; do
  kill -0 "$manager" 2>/dev/null || { echo "the manager died:" >&2; tail -n 5 "$ROS_HOME/manager.log" >&2; exit 1; }
  sleep 0.5
done
rosrun nodelet nodelet load imu_lab/ImuEmulatorNodelet allan_memory_manager __name:=imu_emulator \
  imu/raw:=/imu/raw > "$ROS_HOME/emulator_loader.log" 2>&1 & pids=($! "${pids[@]}")

# Reads /diagnostics (both nodelets report once a wall second) until the monitor has every sample
# or stops receiving; prints the table and the verdict.
/usr/bin/python3 - "$manager" "$hours" "$rate_hz" "$realtime_factor" "$started" "$(getconf CLK_TCK)" <<'PY'
import os, sys, time
import rospy
from diagnostic_msgs.msg import DiagnosticArray

manager_pid, hours, rate_hz, realtime_factor, started, clock_ticks_per_s = sys.argv[1], *map(float, sys.argv[2:])
expected_samples = round(hours * 3600 * rate_hz)
row_interval_h = 1.0 if hours >= 2 else hours / 10
row_samples = round(row_interval_h * 3600 * rate_hz)

def resident_megabytes():
    with open(f"/proc/{manager_pid}/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024 / 1e6

def cpu_seconds():
    with open(f"/proc/{manager_pid}/stat") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / clock_ticks_per_s  # utime + stime

latest = {"received": 0, "published": 0, "state_bytes": None, "gaps": 0}
rows = []
last_change = [time.time()]
first_sample_wall = [None]

def on_diagnostics(array):
    for status in array.status:
        values = {item.key: item.value for item in status.values}
        if status.name.endswith(": emulator"):
            latest["published"] = int(values.get("samples published", latest["published"]))
        elif status.name.endswith(": allan monitor") and "samples" in values:
            received = int(values["samples"])
            if received != latest["received"]:
                last_change[0] = time.time()
                if latest["received"] == 0:
                    first_sample_wall[0] = time.time()
            latest.update(received=received, state_bytes=int(values["engine state [bytes]"]), gaps=int(values["gaps"]))
            if received // row_samples > (rows[-1][1] // row_samples if rows else 0):  # one row per interval crossed
                row = (received / (3600 * rate_hz), received, latest["state_bytes"], resident_megabytes(),
                       latest["gaps"])
                rows.append(row)
                print(f"  {row[0]:7.2f} h {row[1]:12d} {row[4]:6d} {row[2]:14d} {row[3]:9.1f}", flush=True)

rospy.init_node("allan_memory_sampler", disable_signals=True)
print(f"emulator -> allan_monitor nodelets, tactical_mems at rest, {rate_hz:.0f} Hz, {hours:g} simulated h "
      f"({expected_samples} samples), realtime factor {realtime_factor:g}")
print("  simulated      samples   gaps  state [bytes]  RSS [MB]")
rospy.Subscriber("/diagnostics", DiagnosticArray, on_diagnostics, queue_size=100)
# Done when the monitor has every sample, or 30 s after the emulator's last one (the rest dropped);
# a manager that streams nothing for 300 s is reported as stalled.
while latest["received"] < expected_samples:
    if not os.path.exists(f"/proc/{manager_pid}"):
        sys.exit("the manager died: see manager.log in ROS_HOME")
    idle_s = time.time() - last_change[0]
    if (latest["published"] >= expected_samples and idle_s > 30) or idle_s > 300:
        break
    time.sleep(0.5)
if latest["received"] < expected_samples and latest["published"] < expected_samples:
    print(f"STALLED: nothing streamed for 300 s after {latest['published']} samples published")
wall_s, cpu_s = time.time() - started, cpu_seconds()
streaming_wall_s = last_change[0] - first_sample_wall[0] if first_sample_wall[0] else float("nan")
time.sleep(2)  # the emulator's last diagnostics
dropped = latest["published"] - latest["received"]
print(f"published {latest['published']}, received {latest['received']}: {dropped} dropped, "
      f"{latest['gaps']} gaps in the stamps")
if len(rows) >= 2:
    after_warm_up = [row[3] for row in rows[1:]]
    print(f"RSS {rows[0][3]:.1f} MB at {rows[0][0]:.2f} h, {rows[-1][3]:.1f} MB at {rows[-1][0]:.2f} h; "
          f"max growth after the first row {max(after_warm_up) - rows[0][3]:+.1f} MB; "
          f"engine state {min(r[2] for r in rows)}-{max(r[2] for r in rows)} bytes")
received = max(1, latest["received"])
print(f"manager: {wall_s:.0f} s wall, {streaming_wall_s:.0f} s of it streaming (achieved realtime factor "
      f"{received / rate_hz / streaming_wall_s:.1f}); {cpu_s:.0f} s CPU ({1e6 * cpu_s / received:.1f} us per sample)")
PY
