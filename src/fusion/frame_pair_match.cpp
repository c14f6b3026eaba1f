#include "tessera/fusion/frame_pair_match.hpp"

#include <string>

namespace tessera::fusion {
namespace {

bool too_few_features(NodeCheck check) {
  return check == NodeCheck::kTooFewFeatures || check == NodeCheck::kTooFewFeaturesWithDepth;
}

bool too_few_features(MatchReason reason) {
  switch (reason) {
    case MatchReason::kTooFewMatches:
    case MatchReason::kTooFewInliers:
    case MatchReason::kLowInlierRatio:
    case MatchReason::kInliersConcentrated:
    case MatchReason::kInliersDegenerate:
      return true;
    default:
      return false;
  }
}

}  // namespace

std::string_view to_string(PairMethod method) {
  switch (method) {
    case PairMethod::kAuto:
      return "auto";
    case PairMethod::kFeatures:
      return "features";
    case PairMethod::kDepthIcp:
      return "depth-icp";
  }
  return "unknown";
}

Result<PairMethod> parse_pair_method(std::string_view name) {
  for (const PairMethod m : {PairMethod::kAuto, PairMethod::kFeatures, PairMethod::kDepthIcp}) {
    if (name == to_string(m)) return m;
  }
  return usage_error("unknown pair method '" + std::string(name) +
                     "': expected auto, features or depth-icp");
}

bool features_too_few(const FramePairMatch& m) {
  if (!m.prev || !m.curr) return false;
  if (!m.prev->ok() || !m.curr->ok()) {
    // Both frames must have the depth the ICP needs: a failed check is "too few features" or ok.
    const bool prev_usable = m.prev->ok() || too_few_features(m.prev->check);
    const bool curr_usable = m.curr->ok() || too_few_features(m.curr->check);
    return prev_usable && curr_usable;
  }
  return m.features && !m.features->accepted && too_few_features(m.features->reason);
}

FramePairMatch match_frame_pair(const RgbdFrame& prev, const RgbdFrame& curr,
                                const FramePairOptions& options, Rng& rng) {
  FramePairMatch out;
  if (options.method != PairMethod::kDepthIcp) {
    out.prev = create_image_node(prev, {}, options.node);
    out.curr = create_image_node(curr, {}, options.node);
    if (out.prev->ok() && out.curr->ok()) {
      out.features = match_nodes(out.prev->node, out.curr->node, options.matcher, rng);
      out.accepted = out.features->accepted;
      out.T_prev_curr = out.features->T_prev_curr;
    }
  }
  const bool try_depth = options.method == PairMethod::kDepthIcp ||
                         (options.method == PairMethod::kAuto && features_too_few(out));
  if (try_depth) {
    out.depth = align_depth(prev, curr, options.icp);
    out.accepted = out.depth->accepted;
    out.T_prev_curr = out.depth->T_prev_curr;
  }
  return out;
}

}  // namespace tessera::fusion
