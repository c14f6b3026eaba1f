# The fuzz targets: tessera_fuzz_harness(<format> SEEDS <glob> ...) per line; fuzz/<format>_fuzz.cpp
# holds the target, fuzz/dict/<format>.dict its libFuzzer dictionary (optional). Seed globs are
# relative to the source folder ("tests/fixtures/...") or, with "data:", to the real-data folder
# (TESSERA_DATA_DIR, default ../shared/data); scripts/fuzz.sh copies at most 12 files per glob into
# the corpus when it starts: fixtures whole, real files' first 4 KB. fuzz/CMakeLists.txt builds one libFuzzer
# executable per line, tests/fuzz/CMakeLists.txt one regression test over all of them.
tessera_fuzz_harness(houseexpo SEEDS "data:maps/houseexpo/json/*.json")
tessera_fuzz_harness(map_yaml SEEDS "data:maps/ros_map_server/*/*.yaml" "data:maps/explore_bench/*.yaml")
tessera_fuzz_harness(image SEEDS "tests/fixtures/io/ros/*.png" "data:maps/houseexpo/png/*.png"
  "data:rgbd/rtabmap_loop_samples/*.bmp")
tessera_fuzz_harness(pgm SEEDS "tests/fixtures/io/stage/*.pgm" "data:maps/explore_bench/*.pgm")
tessera_fuzz_harness(movingai SEEDS "tests/fixtures/io/movingai/*.map" "data:maps/movingai/*.map")
tessera_fuzz_harness(stage_world SEEDS "tests/fixtures/io/stage/*.world" "data:maps/stage_bitmaps/*.world"
  "data:maps/ros_map_server/*/*.world")
tessera_fuzz_harness(carmen SEEDS "data:laser/*/*.clf" "data:laser/*/*.log")
tessera_fuzz_harness(g2o SEEDS "data:posegraph/*.g2o")
tessera_fuzz_harness(relations SEEDS "data:laser/*/*.relations")
tessera_fuzz_harness(tum_trajectory SEEDS "data:rgbd/tum_trajectories/*.txt")
tessera_fuzz_harness(tum_rgbd_lists SEEDS "tests/fixtures/io/tum_rgbd/*.txt")
tessera_fuzz_harness(tum_rgbd_intrinsics SEEDS "tests/fixtures/io/tum_rgbd/intrinsics*.txt" "data:rgbd/tum_fr1_xyz_pairs/*/intrinsics.txt")
tessera_fuzz_harness(bob_map SEEDS "tests/fixtures/io/bob/*.bobmap")
tessera_fuzz_harness(ros1_bag SEEDS "tests/fixtures/io/bags/*.bag" "data:bags/*.bag")
tessera_fuzz_harness(mcap SEEDS "tests/fixtures/io/bags/*.mcap")
tessera_fuzz_harness(rosbag2_sqlite SEEDS "tests/fixtures/io/bags/*.db3")
