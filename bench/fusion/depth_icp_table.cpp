// Motion from depth alone (fusion/depth_icp.hpp, issue 18 item 10): for each view of
// sim/blank_room.hpp, PAIRS pairs with a random planar motion (up to 5 cm each way and 3 degrees)
// rendered with the Kinect v1's depth noise, with and without its disparity quantisation, and with
// motions up to 30 cm and 15 degrees, beyond what the ICP converges from; and the
// real TUM fr1/xyz pairs. Prints the tables of docs/fusion-depth-icp.md: how many pairs are
// accepted, the largest error of an accepted estimate against the truth, how many accepted
// estimates are wrong (over 2 cm or 1 degree), the condition numbers and the time per pair. Not a
// Google Benchmark: one pass is the measurement.
//
//   depth_icp_table [PAIRS] [DATA_DIR]   (PAIRS default 20; DATA_DIR default TESSERA_DATA_DIR,
//                                         else ../shared/data beside the project)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "table_data_dir.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/fusion/depth_icp.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"
#include "tessera/render/simulated_rgbd_sequence.hpp"
#include "tessera/sim/blank_room.hpp"

namespace {

using namespace tessera;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

struct Error {
  double t_m = 0.0;
  double r_deg = 0.0;
};

Error error_of(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& truth) {
  const Eigen::Isometry3d d = truth.inverse() * estimate;
  return {d.translation().norm(), Eigen::AngleAxisd(d.linear()).angle() * kRadToDeg};
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Motions up to max_m each way and max_deg.
void simulated_rows(const BlankRoom& room, const char* noise, double max_m, double max_deg,
                    int pairs) {
  const fusion::DepthIcpOptions options;
  for (std::size_t v = 0; v < room.views.size(); ++v) {
    const BlankView& view = room.views[v];
    int accepted = 0, wrong = 0;
    double max_t = 0.0, max_r = 0.0, seconds = 0.0;
    double min_cond = std::numeric_limits<double>::infinity(), max_cond = 0.0;
    for (int k = 0; k < pairs; ++k) {
      Rng rng = Rng(1000 + v).fork(static_cast<std::uint64_t>(k));
      const Pose2 motion{rng.uniform(-max_m, max_m), rng.uniform(-max_m, max_m),
                         rng.uniform(-max_deg, max_deg) / kRadToDeg};
      const Pose2 next = view.T_world_robot * motion;
      const RgbdFrame prev = room.camera.render(view.T_world_robot, 0.0, 0.0, rng);
      const RgbdFrame curr = room.camera.render(next, 0.0, 1.0, rng);
      const double h = room.camera.options().mount_height_m;
      const Eigen::Isometry3d truth =
          optical_frame_pose(0.0, view.T_world_robot, 0.0, h).transform().inverse() *
          optical_frame_pose(1.0, next, 0.0, h).transform();
      const auto t0 = std::chrono::steady_clock::now();
      const fusion::DepthIcpResult r = fusion::align_depth(prev, curr, options);
      seconds += seconds_since(t0);
      min_cond = std::min(min_cond, r.condition_number);
      max_cond = std::max(max_cond, r.condition_number);
      if (!r.accepted) continue;
      ++accepted;
      const Error e = error_of(r.T_prev_curr, truth);
      max_t = std::max(max_t, e.t_m);
      max_r = std::max(max_r, e.r_deg);
      if (e.t_m > 0.02 || e.r_deg > 1.0) ++wrong;
    }
    std::printf(
        "| %s | %s | %.0f cm, %.0f deg | %s | %d | %d | %d | %.1f | %.2f | %.0f to %.0f | %.0f |\n",
        view.name.c_str(), noise, 100.0 * max_m, max_deg, view.solvable ? "yes" : "no", pairs,
        accepted, wrong, 1000.0 * max_t, max_r, min_cond, max_cond, 1000.0 * seconds / pairs);
  }
}

void real_rows(const std::filesystem::path& data) {
  const fusion::DepthIcpOptions options;
  for (const char* name : {"case_1", "case_2"}) {
    const Result<RgbdPair> pair = read_rgbd_pair_folder(data / "rgbd/tum_fr1_xyz_pairs" / name);
    if (!pair) {
      std::fprintf(stderr, "%s\n", pair.error().message.c_str());
      std::exit(3);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const fusion::DepthIcpResult r = fusion::align_depth(pair->prev, pair->curr, options);
    const double ms = 1000.0 * seconds_since(t0);
    const Error e = error_of(r.T_prev_curr, pair->T_prev_curr_truth());
    const Error motion = error_of(Eigen::Isometry3d::Identity(), pair->T_prev_curr_truth());
    std::printf("| %s | %.1f mm, %.2f deg | %s | %.1f | %.2f | %.0f | %.0f%% | %.1f | %.0f |\n",
                name, 1000.0 * motion.t_m, motion.r_deg,
                std::string(fusion::to_string(r.reason)).c_str(), 1000.0 * e.t_m, e.r_deg,
                r.condition_number, 100.0 * r.overlap, 1000.0 * r.rmse_m, ms);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int pairs = argc > 1 ? std::atoi(argv[1]) : 20;
  if (pairs < 1) {
    std::fprintf(stderr, "usage: depth_icp_table [PAIRS >= 1] [DATA_DIR]\n");
    return 2;
  }
  const std::filesystem::path data = bench::table_data_dir(argc > 2 ? argv[2] : nullptr);
  std::printf(
      "| view | depth noise | motion up to | solvable | pairs | accepted | wrong | "
      "max t error (mm) | max r error (deg) | condition number | ms per pair |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  RgbdCameraOptions camera;
  for (const bool quantised : {false, true}) {
    camera.inverse_depth_step_1_per_m = quantised ? 2.8e-3 : 0.0;
    const Result<BlankRoom> room = make_blank_room(camera);
    if (!room) {
      std::fprintf(stderr, "%s\n", room.error().message.c_str());
      return 3;
    }
    const char* noise = quantised ? "k z^2, quantised" : "k z^2";
    simulated_rows(*room, noise, 0.05, 3.0, pairs);
    // Beyond the ICP's reach from identity: whatever it accepts must still be right.
    if (quantised) simulated_rows(*room, noise, 0.3, 15.0, pairs);
  }
  std::printf(
      "\n| TUM fr1/xyz pair | true motion | depth ICP | t error (mm) | r error (deg) | "
      "condition number | overlap | residual (mm) | ms |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  real_rows(data);
  return 0;
}
