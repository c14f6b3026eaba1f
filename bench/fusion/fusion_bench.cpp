// Image-node speed at 640 x 480 on the real TUM fr1/xyz case_1 frames (issue 5: "benchmarks report
// frames per second for node creation and matching at 640 x 480 for each feature type"):
//   BM_NodeCreation/<type>: grey conversion, keypoints + descriptors, back-projection (one frame)
//   BM_NodeMatching/<type>: descriptor matching, ratio + mutual test, 3D-3D RANSAC, checks
// The counter `fps` is frames (node creations or node pairs matched) per second of wall time.
// Argument 0 = ORB, 1 = SIFT, 2 = AKAZE. OpenCV may use a second thread inside detection.
// The data folder is TESSERA_DATA_DIR, default ../shared/data beside the project.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tessera/core/rng.hpp"
#include "tessera/fusion/image_node.hpp"
#include "tessera/fusion/node_matcher.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"
#include "tessera/io/data_dir.hpp"

namespace tessera {
namespace {

/// case_1, read once; nullptr, with the benchmark skipped and the reason given, when the data is
/// missing.
const RgbdPair* case_1_or_skip(benchmark::State& state) {
  static const Result<RgbdPair> pair =
      read_rgbd_pair_folder(data_dir() / "rgbd/tum_fr1_xyz_pairs/case_1");
  if (!pair) {
    state.SkipWithError(pair.error().message.c_str());
    return nullptr;
  }
  return &pair.value();
}

fusion::FeatureType type_of(const benchmark::State& state) {
  switch (state.range(0)) {
    case 1:
      return fusion::FeatureType::kSift;
    case 2:
      return fusion::FeatureType::kAkaze;
    default:
      return fusion::FeatureType::kOrb;
  }
}

/// Node options for the feature type of argument 0, named in the benchmark's label.
fusion::ImageNodeOptions node_options(benchmark::State& state) {
  fusion::ImageNodeOptions o;
  o.feature_type = type_of(state);
  state.SetLabel(std::string(fusion::to_string(o.feature_type)));
  return o;
}

void BM_NodeCreation(benchmark::State& state) {
  const RgbdPair* pair = case_1_or_skip(state);
  if (pair == nullptr) return;
  const fusion::ImageNodeOptions o = node_options(state);
  int features = 0;
  for (auto _ : state) {
    const fusion::NodeCreation c = fusion::create_image_node(pair->prev, {}, o);
    features = c.features;
    benchmark::DoNotOptimize(c.node.features.data());
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["features"] = features;
}
BENCHMARK(BM_NodeCreation)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_NodeMatching(benchmark::State& state) {
  const RgbdPair* pair = case_1_or_skip(state);
  if (pair == nullptr) return;
  const fusion::ImageNodeOptions o = node_options(state);
  const fusion::NodeCreation prev = fusion::create_image_node(pair->prev, {}, o);
  const fusion::NodeCreation curr = fusion::create_image_node(pair->curr, {}, o);
  if (!prev.ok() || !curr.ok()) {
    state.SkipWithError("case_1 frames did not become nodes");
    return;
  }
  const fusion::NodeMatcherOptions mo;
  int inliers = 0;
  for (auto _ : state) {
    Rng rng(1);
    const fusion::MatchResult r = fusion::match_nodes(prev.node, curr.node, mo, rng);
    inliers = r.inliers;
    benchmark::DoNotOptimize(r.T_prev_curr.data());
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["inliers"] = inliers;
}
BENCHMARK(BM_NodeMatching)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace tessera

BENCHMARK_MAIN();
