# tessera: `make demo` and `make test` do all the set-up on a fresh Debian 12 machine.
# With CI=true, `make test` builds once with warnings as errors under AddressSanitizer and
# UndefinedBehaviorSanitizer and runs the suite there (docs/decisions/0018-one-ci-build.md), then
# the firmware on QEMU, a short fuzzing smoke and the ThreadSanitizer tests (make tsan).
JOBS ?= $(shell nproc)
DEMO_OUT ?= out/demo
TESSERA := build/dev/apps/tessera/tessera

.PHONY: all deps configure build cli demo test test-dev test-ci bench clean
.PHONY: fuzz-build fuzz fuzz-smoke kill-test

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	cmake --preset dev

build: configure
	cmake --build --preset dev -j $(JOBS)

# Only the program, so that the demo does not wait for the test suite to compile.
cli: configure
	cmake --build --preset dev -j $(JOBS) --target tessera

# Three lidar robots share one map of the built-in office (lecture Algo 9.1), served live: open
# the printed address in a browser (the map growing, robots, frontier, each robot's goal and its
# a/d priority; replay step by step) or in Foxglove; recorded as ROS 2 messages to run.mcap too.
# The run is paced at DEMO_STEP_MS per step and the page stays up DEMO_LINGER_S seconds after it.
DEMO_PORT ?= 0
DEMO_STEP_MS ?= 60
DEMO_LINGER_S ?= 30
demo: cli
	$(TESSERA) explore --sensor lidar --robots 3 --out $(DEMO_OUT) --record $(DEMO_OUT)/run.mcap \
	  --serve $(DEMO_PORT) --step-delay-ms $(DEMO_STEP_MS) --serve-linger $(DEMO_LINGER_S)

ifeq ($(CI),true)
test: test-ci bob-firmware bob-firmware-test fuzz-smoke tsan
else
test: test-dev
endif

test-dev: build
	ctest --test-dir build/dev --output-on-failure -j $(JOBS)

test-ci: deps
	cmake --preset ci
	cmake --build --preset ci -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --test-dir build/ci --output-on-failure -j $(JOBS)

bench: build
	build/dev/bench/explore/explore_bench
	build/dev/bench/team/map_match_bench

# Issue 12's real-log SLAM table: 4 dev logs x seeds 1-3 x drift 0.15 and 0.3 deg/m, scored by the
# shared ATE tool; prints the Markdown table of docs/slam-results.md and copies the maps.
.PHONY: slam-table
slam-table: cli
	python3 scripts/slam_log_table.py --images docs/images

# The same protocol on simulated buildings scored against their exact poses (docs/slam-results.md);
# GMAPPING=<folder with gfs_nogui and gfs2log> adds GMapping's figure on the first seed.
.PHONY: slam-sim-table
slam-sim-table: cli
	cmake --build build/dev --target simulated_corrected_log
	python3 scripts/slam_log_table.py --sim --out out/slam-sim --images docs/images \
	  $(if $(GMAPPING),--gmapping $(GMAPPING))

# Issue 18 item 7: the same table with --manhattan (docs/slam-manhattan.md).
.PHONY: slam-table-manhattan
slam-table-manhattan: cli
	python3 scripts/slam_log_table.py --slam-args=--manhattan --out out/slam-logs-manhattan

# Issue 18 item 10: motion from depth alone on blank simulated views and the real TUM pairs
# (docs/fusion-depth-icp.md).
.PHONY: depth-icp-table
depth-icp-table: build
	build/dev/bench/fusion/depth_icp_table 10

# Issue 18 item 9: the obstacle course in four floor plans, ours against the thesis' navigation,
# with and without boxes on the route (docs/fusion-navigation.md).
.PHONY: obstacle-course
obstacle-course: cli
	python3 scripts/obstacle_course_table.py --images docs/images

# Issue 18 item 11: the thesis' claims (docs/fusion-claims.md) - Appendix B/C figures of the ORB
# teach-and-repeat runs, the same runs with half the frames dropped and with posters from 3 photos,
# and the ablation of the cells and the graph gate with 84 and 3 photos (about 35 minutes).
.PHONY: fusion-claims
fusion-claims: cli
	python3 scripts/fusion_table.py --features orb --out out/claims-base
	python3 scripts/fusion_table.py --features orb --out out/claims-base --appendix --reuse-only
	python3 scripts/fusion_table.py --features orb --drop-frames 0.5 --out out/claims-drop50
	python3 scripts/fusion_table.py --features orb --photos 3 --out out/claims-photos3
	for c in cells whole-map; do for g in on off; do \
	  python3 scripts/fusion_table.py --features orb --candidates $$c --match-gate $$g --keep-going \
	    --out out/claims-$$c-$$g-84 && \
	  python3 scripts/fusion_table.py --features orb --candidates $$c --match-gate $$g --keep-going \
	    --photos 3 --out out/claims-$$c-$$g-3 || exit 1; done; done

# Issue 16's localization figures on the Intel log: map 0-600 s, localize 600-1,088 s (relations,
# real-time factor), relocalize from 50 starts with no initial pose, 10 kidnappings
# (docs/localization.md).
.PHONY: localize-bench
localize-bench: build
	build/dev/bench/slam/localize_bench

# The same on another building: Freiburg 079, map 0-530 s, localize 530-1,061 s (about 25 minutes;
# docs/localization.md, "Another building").
FR079 = $${TESSERA_DATA_DIR:-../shared/data}/laser/fr079
.PHONY: localize-bench-fr079
localize-bench-fr079: build
	build/dev/bench/slam/localize_bench --log $(FR079)/freiburg-079-corrected.log \
	  --relations $(FR079)/fr079.relations --time-offset 1211.467 --map-s 530

# And on two corrected radish logs with known true poses (ACES, FHW: one scan a metre, so made
# drifting and 0.2 s apart by the shared perturb_carmen.py, seed 1, 0.15 deg/m, as the SLAM table
# does): map 0-44 s, localize the rest, every pose judged against the truth too (about 30 and
# 10 minutes; docs/localization.md, "Corrected logs with true poses").
RADISH = $${TESSERA_DATA_DIR:-../shared/data}/maps/radish_carmen
TOOLS = $${TESSERA_DATA_DIR:-../shared/data}/../tools
.PHONY: localize-bench-radish
localize-bench-radish: build
	mkdir -p out/localize-radish
	for n in aces fhw; do \
	  gzip -dc $(RADISH)/$$n-corrected.log.gz > out/localize-radish/$$n.log && \
	  python3 $(TOOLS)/perturb_carmen.py out/localize-radish/$$n.log out/localize-radish/$$n-drift.log \
	    --seed 1 --restamp 0.2 --drift-deg-per-m 0.15 --truth out/localize-radish/$$n-truth.txt && \
	  build/dev/bench/slam/localize_bench --log out/localize-radish/$$n-drift.log --relations none \
	    --truth out/localize-radish/$$n-truth.txt --map-s 44 || exit 1; done

# Issue 16's bounded lifelong mapping: the Intel log mapped, then resumed five times over the same
# session; nodes, peak memory, file size and relations per pass (docs/sessions.md).
.PHONY: lifelong
lifelong: cli
	python3 scripts/lifelong_table.py

# The same on Freiburg 079 (about 10 minutes on an idle machine; docs/sessions.md).
.PHONY: lifelong-fr079
lifelong-fr079: cli
	python3 scripts/lifelong_table.py --log $(FR079)/freiburg-079-corrected.log \
	  --relations $(FR079)/fr079.relations --time-offset 1211.467 --out out/lifelong-fr079

# Issue 14's throughput benchmark: tessera team with 1, 3 and 8 robot processes over DDS; prints
# map and claim traffic per robot and the scan-to-map latency (docs/ros2.md).
.PHONY: team-bench
team-bench: cli
	python3 scripts/team_bench.py

clean:
	rm -rf build out

# The freestanding bob core and its example Cortex-M4 firmware; prints flash and RAM use.
.PHONY: bob-firmware
bob-firmware: deps
	cmake --preset cortex-m
	cmake --build --preset cortex-m -j $(JOBS)

# The firmware images on an emulated Cortex-M4 (QEMU mps2-an386), fed by the host simulator over
# the serial port: their final maps must be the host build's (scripts/bob_firmware_test.sh).
# Uses the ci build's tessera when there is one (make test), the dev build's otherwise.
.PHONY: bob-firmware-test
bob-firmware-test: bob-firmware
	@if [ -x build/ci/apps/tessera/tessera ]; then t=build/ci/apps/tessera/tessera; else \
	  cmake --preset dev && cmake --build --preset dev -j $(JOBS) --target tessera && t=$(TESSERA); fi; \
	bash scripts/bob_firmware_test.sh $$t build/cortex-m/firmware/bob

# libFuzzer harnesses of the readers (fuzz/, docs/fuzzing.md): clang with ASan and UBSan, only the
# readers and what they need. `make fuzz` runs each harness FUZZ_SECONDS on its corpus (JOBS at a
# time); `make fuzz-smoke` runs each 15 s, two at a time (CI). Both fail when a harness finds a
# crash, a hang, a leak, a sanitizer report or an error that does not name the file.
FUZZ_SECONDS ?= 600
fuzz-build: deps
	cmake --preset fuzz
	cmake --build --preset fuzz -j $(JOBS)

fuzz: fuzz-build
	scripts/fuzz.sh $(FUZZ_SECONDS) $(JOBS)

fuzz-smoke: fuzz-build
	scripts/fuzz.sh 15 2

# ThreadSanitizer (issue 17, docs/fuzzing.md): tessera's own code runs no thread (the live view is
# driven by the run, decision 0020; Ceres runs with one thread), but OpenCV runs its TBB workers
# inside the feature extraction and matching of the fusion front end, and the live server's asio
# code must stay race-free if a thread ever drives it. These tests run those paths under TSan
# (CI too); tests/tsan.supp holds the reports inside OpenCV, TBB and GDAL and says why.
TSAN_TARGETS := live_tests fusion_tests fusion_image_tests fusion_fusion_slam_test \
  posegraph_pose_graph_test
.PHONY: tsan
tsan: deps
	cmake --preset tsan
	cmake --build --preset tsan -j $(JOBS) --target $(TSAN_TARGETS)
	TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$(CURDIR)/tests/tsan.supp \
	  ctest --test-dir build/tsan --output-on-failure -j $(JOBS) -R '^(live|fusion|posegraph)\.'

# The kill test with 200 kills per command (ctest runs it with 20).
kill-test: configure
	cmake --build --preset dev -j $(JOBS) --target tessera apps_cli_tests
	TESSERA_KILL_RUNS=200 build/dev/tests/apps/apps_cli_tests --gtest_filter='CliKill.*'
