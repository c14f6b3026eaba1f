#include "tessera/fusion/stationary_matching.hpp"

#include <algorithm>
#include <vector>

#include "tessera/core/assert.hpp"

namespace tessera::fusion {

StationaryMatchingSummary match_consecutive_frames(std::span<const PosedFrame> frames,
                                                   const StationaryMatchingOptions& options,
                                                   std::uint64_t seed) {
  TESSERA_ASSERT(!validate(options.node));
  TESSERA_ASSERT(!validate(options.matcher));
  StationaryMatchingSummary s;
  s.frames = static_cast<int>(frames.size());
  s.pairs = std::max(0, s.frames - 1);
  std::vector<NodeCreation> nodes;
  nodes.reserve(frames.size());
  for (const PosedFrame& f : frames) nodes.push_back(create_image_node(f.frame, {}, options.node));

  const Rng base(seed);
  double sum_t = 0.0, sum_r = 0.0;
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const NodeCreation& prev = nodes[k - 1];
    const NodeCreation& curr = nodes[k];
    if (!prev.ok() || !curr.ok()) {
      ++s.rejections[std::string(to_string(!prev.ok() ? prev.check : curr.check))];
      continue;
    }
    Rng rng = base.fork(k);
    const MatchResult r = match_nodes(prev.node, curr.node, options.matcher, rng);
    if (!r.accepted) {
      ++s.rejections[std::string(to_string(r.reason))];
      continue;
    }
    ++s.acceptances[std::string(to_string(r.reason))];
    ++s.accepted;
    const Eigen::Isometry3d truth =
        frames[k - 1].T_world_camera.inverse() * frames[k].T_world_camera;
    const Eigen::Isometry3d error = truth.inverse() * r.T_prev_curr;
    const double t = error.translation().norm();
    const double a = Eigen::AngleAxisd(error.linear()).angle();
    sum_t += t;
    sum_r += a;
    s.max_translation_error_m = std::max(s.max_translation_error_m, t);
    s.max_rotation_error_rad = std::max(s.max_rotation_error_rad, a);
  }
  if (s.accepted > 0) {
    s.mean_translation_error_m = sum_t / s.accepted;
    s.mean_rotation_error_rad = sum_r / s.accepted;
  }
  return s;
}

}  // namespace tessera::fusion
