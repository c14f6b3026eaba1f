// Render speed of the simulated RGB-D camera (sim/rgbd_camera.hpp) at the Kinect v1's 640 x 480:
//  - BM_RenderPosterClose: facing a photo poster 1.2 m wide from 1 m (it fills most of the image,
//    every pixel trilinearly sampled: the worst case), depth noise on;
//  - BM_RenderOffice: the built-in office world at 5 cm with posters on 60 % of the wall faces
//    (RTAB-Map's photos when the data folder is there, else a synthetic texture), turning on the
//    spot, depth noise on;
//  - BM_RenderOfficeNoNoise: the same without depth noise (the cost of one Gaussian per pixel).
// The data folder is TESSERA_DATA_DIR, default ../shared/data beside the project.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <vector>

#include "tessera/render/wall_textures.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/rgbd_camera.hpp"
#include "tessera/io/data_dir.hpp"

namespace tessera {
namespace {

WallTexture synthetic_photo() {
  WallTexture t{512, 384, std::vector<std::uint8_t>(3 * 512 * 384), "synthetic"};
  for (std::size_t i = 0; i < t.rgb.size(); ++i) t.rgb[i] = static_cast<std::uint8_t>(i * 2654435761u >> 24);
  return t;
}

std::vector<WallTexture> textures() {
  const auto files = list_texture_images(data_dir() / "rgbd/rtabmap_loop_samples/images");
  if (files.ok()) {
    auto t = read_wall_textures(*files);
    if (t.ok()) return std::move(t).value();
  }
  return {synthetic_photo()};
}

World room() {
  const int w = 140, h = 90;
  std::vector<std::uint8_t> solid(static_cast<std::size_t>(w * h), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (x == 0 || y == 0 || x == w - 1 || y == h - 1) solid[static_cast<std::size_t>(y * w + x)] = 1;
    }
  }
  return World(GridGeometry({0.0, 0.0}, 0.05, w, h), solid, "room");
}

void BM_RenderPosterClose(benchmark::State& state) {
  const World world = room();
  const auto faces = find_wall_faces(world).faces;
  Poster p;
  p.face = nearest_wall_face(faces, {6.95, 2.25});
  p.width_m = 1.2;
  p.height_m = 0.9;
  p.center_m = 0.5 * faces[static_cast<std::size_t>(p.face)].length_m();
  p.bottom_m = 0.58;
  const RgbdCamera cam = RgbdCamera::create(world, {}, textures(), {p}).value();
  Rng rng(1);
  RgbdFrame frame;
  for (auto _ : state) {
    cam.render_into({5.95, 2.25, 0.0}, 0.0, 0.0, rng, frame);
    benchmark::DoNotOptimize(frame.rgb.data());
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                             benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RenderPosterClose)->Unit(benchmark::kMillisecond);

void render_office(benchmark::State& state, bool noise) {
  const World world = builtin_world("office", 0.05);
  const std::vector<WallTexture> tex = textures();
  const auto posters = place_posters(find_wall_faces(world).faces, tex, {}, 3);
  RgbdCameraOptions o;
  if (!noise) o.depth_noise_coefficient_1_per_m = 0.0;
  const RgbdCamera cam = RgbdCamera::create(world, o, tex, posters).value();
  // A free cell near the middle of the office.
  const GridGeometry& g = world.geometry();
  Vec2 at = g.center_of({g.width() / 2, g.height() / 2});
  for (int r = 0; r < g.width() && world.solid(g.cell_at_unchecked(at)); ++r) {
    at = g.center_of({g.width() / 2 + r, g.height() / 2});
  }
  Rng rng(1);
  RgbdFrame frame;
  double heading = 0.0;
  for (auto _ : state) {
    cam.render_into({at.x, at.y, heading}, 0.0, 0.0, rng, frame);
    heading += 0.1;
    benchmark::DoNotOptimize(frame.rgb.data());
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                             benchmark::Counter::kIsRate);
}

void BM_RenderOffice(benchmark::State& state) { render_office(state, true); }
void BM_RenderOfficeNoNoise(benchmark::State& state) { render_office(state, false); }
BENCHMARK(BM_RenderOffice)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderOfficeNoNoise)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tessera

BENCHMARK_MAIN();
