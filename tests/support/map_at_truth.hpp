#pragma once
// A simulated run's map as a perfect session would have frozen it: every scan at its true pose.
// Header-only: a test that includes it links tessera::slam and tessera::sim.
#include <vector>

#include "tessera/sim/laser_run.hpp"
#include "tessera/slam/localizer.hpp"

namespace tessera::support {

/// A run's scans at its true poses, at 0.05 m, each scan turned into points as `points` says.
inline slam::ProbabilityGrid map_at_truth(
    const SimulatedLaserRun& run,
    const slam::ScanPointsOptions& points = slam::LocalizerOptions{}.points) {
  std::vector<const StampedScan*> scans;
  std::vector<Pose2> poses;
  for (std::size_t i = 0; i < run.log.scans.size(); ++i) {
    scans.push_back(&run.log.scans[i]);
    poses.push_back(run.truth[i].pose);
  }
  return slam::frozen_map(scans, poses, points, slam::RangeInsertOptions{}, 0.05);
}

}  // namespace tessera::support
