// The thesis' stationary test (section 5.1.3, Table 5.5) in the simulator: for each feature type
// and each view of sim/stationary_scene.hpp, captures with the neck still and with a small neck
// turn, consecutive captures matched by fusion/stationary_matching.hpp. Prints the table of
// docs/fusion-stationary.md. Not a Google Benchmark: one pass is the measurement.
//
//   stationary_table [FRAMES] [DATA_DIR]   (FRAMES default 20; DATA_DIR default TESSERA_DATA_DIR,
//                                           else ../shared/data beside the project)
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "table_data_dir.hpp"
#include "tessera/fusion/stationary_matching.hpp"
#include "tessera/io/tum_rgbd_sequence.hpp"
#include "tessera/render/simulated_rgbd_sequence.hpp"
#include "tessera/render/wall_textures.hpp"
#include "tessera/sim/stationary_scene.hpp"

int main(int argc, char** argv) {
  using namespace tessera;
  using namespace tessera::fusion;
  const int frames = argc > 1 ? std::atoi(argv[1]) : 20;
  if (frames < 2) {
    std::fprintf(stderr, "usage: stationary_table [FRAMES >= 2] [DATA_DIR]\n");
    return 2;
  }
  const std::filesystem::path data = bench::table_data_dir(argc > 2 ? argv[2] : nullptr) / "rgbd";
  // The photos of docs/fusion-stationary.md: a TUM fr1 desk frame as the desk, RTAB-Map's sample
  // images as the cabinet and the two posters.
  Result<std::vector<WallTexture>> photos = read_wall_textures({
      data / "tum_fr1_xyz_pairs/case_1/img_prev.png",
      data / "rtabmap_loop_samples/images/20.jpg",
      data / "rtabmap_loop_samples/images/5.jpg",
      data / "rtabmap_loop_samples/images/30.jpg",
  });
  if (!photos) {
    std::fprintf(stderr, "%s\n", photos.error().message.c_str());
    return 3;
  }
  Result<StationaryScene> scene = make_stationary_scene(std::move(photos).value());
  if (!scene) {
    std::fprintf(stderr, "%s\n", scene.error().message.c_str());
    return 3;
  }
  constexpr double kNeckTurnRad = 3.0 * std::numbers::pi / 180.0;
  std::printf("| features | view | neck | frames | pairs | accepted | mean t error (mm) | "
              "max t error (mm) | mean r error (deg) | max r error (deg) | rejections |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const FeatureType type : {FeatureType::kOrb, FeatureType::kSift, FeatureType::kAkaze}) {
    for (std::size_t v = 0; v < scene->views.size(); ++v) {
      const StationaryView& view = scene->views[v];
      for (const double turn : {0.0, kNeckTurnRad}) {
        StationaryCaptureOptions co;
        co.frames = frames;
        co.neck_turn_rad = turn;
        const std::vector<StationaryCapture> captures =
            capture_stationary_view(scene->camera, view, co, /*seed=*/100 + v);
        std::vector<PosedFrame> posed;
        for (const StationaryCapture& c : captures) {
          posed.push_back({c.frame, optical_frame_pose(c.frame.t_s, view.T_world_robot,
                                                       c.neck_pan_rad,
                                                       scene->camera.options().mount_height_m)
                                        .transform()});
        }
        StationaryMatchingOptions mo;
        mo.node.feature_type = type;
        const StationaryMatchingSummary s = match_consecutive_frames(posed, mo, /*seed=*/1);
        std::string reasons;
        for (const auto& [reason, n] : s.rejections) {
          reasons += (reasons.empty() ? "" : ", ") + reason + " " + std::to_string(n);
        }
        constexpr double kDeg = 180.0 / std::numbers::pi;
        const bool any = s.accepted > 0;
        std::printf("| %s | %s | %s | %d | %d | %d | %s | %s | %s | %s | %s |\n",
                    std::string(to_string(type)).c_str(), view.name.c_str(),
                    turn == 0.0 ? "still" : "3 deg turns", s.frames, s.pairs, s.accepted,
                    any ? std::to_string(1000.0 * s.mean_translation_error_m).substr(0, 5).c_str() : "-",
                    any ? std::to_string(1000.0 * s.max_translation_error_m).substr(0, 5).c_str() : "-",
                    any ? std::to_string(kDeg * s.mean_rotation_error_rad).substr(0, 5).c_str() : "-",
                    any ? std::to_string(kDeg * s.max_rotation_error_rad).substr(0, 5).c_str() : "-",
                    reasons.empty() ? "-" : reasons.c_str());
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
