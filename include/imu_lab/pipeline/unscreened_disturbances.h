// What the allan tool's screens before its engine (allan/impulse_screen.h for knocks and spikes,
// allan/level_shift_screen.h for steps in the level, both with allan's default options) find in a
// record that another tool analyses whole (bag_summary, spectrum). Those tools keep every sample,
// so a disturbance that allan leaves out is in their numbers: on the knocked ADIS16405 (unit 4),
// bag_summary's accelerometer y OADEV at 100 s is 5.2e-3 m/s^2 against allan's 3.0e-3 (3.2e-3
// with allan's impulse screen off, 4.5e-3 with its level-shift screen off: mostly the two tilts).
// The finder only looks; the note tells the user (doc/impulse_screen.md).
#pragma once

#include <string>

#include "imu_lab/allan/impulse_screen.h"
#include "imu_lab/allan/level_shift_screen.h"
#include "imu_lab/io/imu_records.h"

namespace imu_lab {
namespace pipeline {

struct UnscreenedDisturbances {
  allan::ImpulseScreenReport impulses;
  allan::LevelShiftReport level_shifts;
  bool any() const { return impulses.event_count + level_shifts.event_count > 0; }
};

class DisturbanceFinder {
 public:
  DisturbanceFinder();
  // One sample, in stamp order (a triad a message does not carry goes in as NaN, unscreened).
  void push(const io::ImuRecord& record);
  // End of the record: what both screens found.
  UnscreenedDisturbances finish();

 private:
  allan::ImpulseScreen impulses_;
  allan::LevelShiftScreen level_shifts_;
  allan::ScreenedSamples passed_, unshifted_;  // handed on and let go: only the reports matter
};

// Empty when nothing was found; otherwise a paragraph for the user starting with `tool`: how many
// knocks or spikes and level shifts allan's screens find, when the first and the largest happened
// (seconds from the first stamp), and that they are in `what` (e.g. "the Allan deviations below"),
// whereas allan leaves them out.
std::string unscreened_disturbance_note(const std::string& tool, const UnscreenedDisturbances& found,
                                        const std::string& what);

}  // namespace pipeline
}  // namespace imu_lab
