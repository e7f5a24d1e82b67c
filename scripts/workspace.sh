# Sourced by the other scripts: where the catkin workspace lives and how to build it.
# The workspace is made outside the sources (git-ignored .ws/ by default) with this
# repository linked into its src/.
IMU_LAB_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
IMU_LAB_WS=${IMU_LAB_WS:-$IMU_LAB_ROOT/.ws}

# Debian's python3 has the ROS modules; a pyenv python3 on PATH does not.
IMU_LAB_CATKIN_ARGS=(
  -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3
  -DCMAKE_BUILD_TYPE=Release -DCATKIN_ENABLE_TESTING=ON
)

imu_lab_build() {
  mkdir -p "$IMU_LAB_WS/src"
  ln -sfn "$IMU_LAB_ROOT" "$IMU_LAB_WS/src/imu_lab"
  (cd "$IMU_LAB_WS" && catkin_make -j"${IMU_LAB_JOBS:-2}" "${IMU_LAB_CATKIN_ARGS[@]}" "$@")
}

imu_lab_source() {
  # setup.bash reads unset variables; relax nounset while sourcing it.
  set +u
  # shellcheck disable=SC1091
  source "$IMU_LAB_WS/devel/setup.bash"
  set -u
}
