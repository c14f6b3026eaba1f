// Appearance-based recall on RTAB-Map's loop-closure set (issue 5, item 7): for each feature type,
// the hypotheses of fusion/appearance_recall.hpp over images 1..84 in order, recall at 100%
// precision (fusion/loop_recall.hpp) against samples_GT.bmp, and the time per image. Prints the
// table of docs/fusion-recall.md. Not a Google Benchmark: one pass is the measurement.
//
//   loop_recall [DATA_DIR]   (default: TESSERA_DATA_DIR, else ../shared/data beside the project)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "table_data_dir.hpp"
#include "tessera/fusion/appearance_recall.hpp"
#include "tessera/fusion/loop_recall.hpp"
#include "tessera/io/loop_closure_set.hpp"

int main(int argc, char** argv) {
  using namespace tessera;
  using namespace tessera::fusion;
  const std::filesystem::path set =
      bench::table_data_dir(argc > 1 ? argv[1] : nullptr) / "rgbd/rtabmap_loop_samples";
  constexpr int kImages = 84;
  Result<LoopGroundTruth> gt = read_loop_ground_truth(set / "samples_GT.bmp", kImages);
  if (!gt) {
    std::fprintf(stderr, "%s\n", gt.error().message.c_str());
    return 3;
  }
  Result<std::vector<GrayImage>> images = read_loop_closure_images(set / "images", kImages);
  if (!images) {
    std::fprintf(stderr, "%s\n", images.error().message.c_str());
    return 3;
  }
  const int positives = gt->queries_with_loop();
  std::printf("RTAB-Map loop set: %d images, %d queries with a true loop, short-term memory %d\n",
              kImages, positives, AppearanceOptions{}.short_term_memory);
  std::printf("| features | recall at 100%% precision | found / 44 | threshold (inliers) | "
              "hypotheses | correct hypotheses | best wrong score | describe ms/image | "
              "score ms/image |\n");
  for (const FeatureType type : {FeatureType::kOrb, FeatureType::kSift, FeatureType::kAkaze}) {
    AppearanceOptions o;
    o.feature_type = type;
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    std::vector<ImageDescription> described;
    for (const GrayImage& g : *images) {
      described.push_back(describe_image({g.width, g.height, g.pixels}, o));
    }
    const auto t1 = Clock::now();
    const std::vector<LoopHypothesis> hyps = best_loop_hypotheses(described, o);
    const auto t2 = Clock::now();
    std::vector<ScoredHypothesis> scored;
    int correct = 0;
    int best_wrong = 0;
    for (const LoopHypothesis& h : hyps) {
      if (h.candidate < 0) continue;
      const bool ok = gt->is_loop(h.query, h.candidate);
      scored.push_back({static_cast<double>(h.score), ok});
      correct += ok ? 1 : 0;
      if (!ok) best_wrong = std::max(best_wrong, h.score);
    }
    const RecallAtFullPrecision r = recall_at_full_precision(scored, positives);
    const double describe_ms =
        std::chrono::duration<double, std::milli>(t1 - t0).count() / kImages;
    const double score_ms = std::chrono::duration<double, std::milli>(t2 - t1).count() / kImages;
    std::printf("| %s | %.1f%% | %d | %.0f | %zu | %d | %d | %.1f | %.1f |\n",
                std::string(to_string(type)).c_str(), 100.0 * r.recall, r.found, r.threshold,
                scored.size(), correct, best_wrong, describe_ms, score_ms);
    for (const LoopHypothesis& h : hyps) {
      if (h.candidate < 0) continue;
      std::fprintf(stderr, "%s query %2d -> %2d score %3d matches %3d %s\n",
                   std::string(to_string(type)).c_str(), h.query + 1, h.candidate + 1, h.score,
                   h.matches,
                   gt->is_loop(h.query, h.candidate) ? "loop"
                   : gt->has_loop(h.query)           ? "WRONG (query has a loop)"
                                                     : "wrong (no loop)");
    }
  }
  return 0;
}
