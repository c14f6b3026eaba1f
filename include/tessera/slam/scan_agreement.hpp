#pragma once
// Whether two consecutive scans see the same place: the localizer's test for a jump of the scans
// (a kidnapped robot) that the map alone may not show. Right after a kidnapping the tracker
// searches only around the old pose, and in a building of look-alike rooms and corridors it can
// find a pose there where the new scan fits the map passably (on Freiburg 079, 0.5-0.7 of the way
// from free space to wall) and follow it for many seconds. Two consecutive scans of a robot that
// was not moved, placed at their tracked poses, agree on nearly all the returns they share (on
// the Intel raw log at least 66 % over 2,464 pairs, on Freiburg 079 at least 58 % of 2,186 bar
// two where the log's odometry glitched); the first scan after a kidnapping agreed with the last
// before it on 1-24 % (20 kidnappings on the two logs; docs/decisions/0042).

#include "tessera/core/pose2.hpp"
#include "tessera/slam/scan_points.hpp"

namespace tessera::slam {

/// How a later scan's returns compare with an earlier scan's beams.
struct ScanAgreement {
  /// Returns of the later scan on a bearing (from the earlier scan's sensor) within one beam of
  /// an earlier return: those the two scans can be compared on.
  int compared = 0;
  /// Of those, the returns within agreement_m + agreement_share * range of such an earlier
  /// return's range: the same surface, seen again.
  int agreeing = 0;

  /// agreeing / compared; 1 when nothing could be compared (no evidence of a jump).
  [[nodiscard]] double share() const {
    return compared == 0 ? 1.0 : static_cast<double>(agreeing) / static_cast<double>(compared);
  }
};

/// How far a return may lie from the earlier scan's range on its bearing and still be the same
/// surface: the two poses' error (a few centimetres once tracked) plus a share of the range for
/// the angular error and for a surface seen at a grazing angle from a slightly different place.
struct ScanAgreementOptions {
  double agreement_m = 0.1;
  double agreement_share = 0.05;
};

/// Compares `later` with `earlier` (both in their robot frames, as scan_to_points gives them),
/// the later robot at T_earlier_later in the earlier robot's frame. `beam_rad`: the earlier
/// scan's angular increment (its beams' spacing). Returns beyond the earlier scan's field of view,
/// or on a bearing where it had no return, are not compared. Cost: O((n + m) log n) for n earlier
/// and m later returns.
[[nodiscard]] ScanAgreement scan_agreement(const ScanPoints& earlier, const ScanPoints& later,
                                           const Pose2& T_earlier_later, double beam_rad,
                                           const ScanAgreementOptions& options = {});

}  // namespace tessera::slam
