# Sourced by the ROS benches: a roscore of their own on a random port above PORT_BASE (so a bench
# never talks to another master on the machine), ROS_HOME in a fresh folder unless given, and an
# exit trap that sends SIGINT to everything the bench appended to `pids` (the master last).
#   source "$(dirname "$0")/private_roscore.sh" PORT_BASE
port=$(($1 + RANDOM % 400))
export ROS_MASTER_URI=http://localhost:$port
export ROS_HOME=${ROS_HOME:-$(mktemp -d)}
pids=()
cleanup() { for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done; wait 2>/dev/null || true; }
trap cleanup EXIT

roscore -p "$port" > /dev/null 2>&1 & pids+=($!)
until rosparam list > /dev/null 2>&1; do sleep 0.5; done
