# The two README commands: `make run` and `make test`. Both install whatever Debian package is
# missing first (apt-get; sudo when not root), then build Release into build/.
BUILD      ?= build
JOBS       ?= $(shell nproc)
PACKAGES   := cmake g++ make pkg-config libtbb-dev libeigen3-dev libhdf5-dev libspdlog-dev \
              doctest-dev libtomlplusplus-dev libcli11-dev libbenchmark-dev nlohmann-json3-dev \
              libmuparser-dev libcgal-dev
PY_PACKAGES := python3-numpy python3-h5py python3-matplotlib python3-scipy
# The real-client test: ParaView's own readers, rendering under a virtual X display; ffmpeg
# for `ryushi render --movie`.
PV_PACKAGES := paraview python3-paraview xvfb xauth ffmpeg
SUDO       := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps py-deps pv-deps render-deps build run test test-long test-paraview test-sanitize bench plots tradeoffs docs fuzz fuzz-check clean

all: build

deps:
	@missing=""; for p in $(PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing missing packages:$$missing"; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	fi

py-deps:
	@missing=""; for p in $(PY_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	fi

pv-deps:
	@missing=""; for p in $(PV_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	fi

# `ryushi render --movie`: Python's packages and ffmpeg (not in `make run`: the PNGs need no
# ffmpeg).
render-deps: py-deps
	@dpkg -s ffmpeg >/dev/null 2>&1 || { $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends ffmpeg; }

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS)

# The run, then its last frame as a picture (out/dam_break_2d/render/pressure_NNNNN.png).
run: build py-deps
	$(BUILD)/ryushi run scenes/dam_break_2d.toml --out out/dam_break_2d --overwrite
	$(BUILD)/ryushi render out/dam_break_2d --frames last

# The suite less the tests labelled long (the three 200-period sloshing tanks and three heavy
# validations, tests/slow_tests.cmake), which test-long runs; CI runs both.
test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) -LE long

test-long: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) -L long

# Short WCSPH, MPS and 3D runs opened in ParaView's XDMF readers, and drawn by `ryushi render`
# (tools/test_paraview.sh).
test-paraview: build py-deps pv-deps
	tools/test_paraview.sh $(BUILD)

# Same tests under AddressSanitizer + UndefinedBehaviorSanitizer.
test-sanitize: deps
	cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRYUSHI_SANITIZE=ON
	cmake --build build-sanitize -j$(JOBS)
	cd build-sanitize && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j$(JOBS)

bench: build py-deps
	@# issue 13's goals in one sitting and one table (the triad, tools/bench_speedup.sh and
	@# tools/bench_time_per_unit_T.sh among them); about 20 minutes and 16 GiB
	/usr/bin/python3 tools/bench_issue13.py --build $(BUILD)
	$(BUILD)/bench/ryushi_bench_neighbours
	tools/bench_dam_break.sh $(BUILD)
	tools/bench_isph.sh $(BUILD) 10
	mkdir -p docs/img
	$(BUILD)/bench/ryushi_bench_solvers 2
	/usr/bin/python3 tools/bench_mps_solvers.py --build $(BUILD)
	$(BUILD)/bench/ryushi_bench_operators docs/img/operators.csv 2
	/usr/bin/python3 tools/plot_operators.py docs/img/operators.csv docs/img/operators_speed_accuracy.png

plots: build py-deps
	mkdir -p docs/img
	test -f out/dam_break_2d/probes.csv || $(BUILD)/ryushi run scenes/dam_break_2d.toml --out out/dam_break_2d --quiet --overwrite
	/usr/bin/python3 tools/plot_dam_break.py out/dam_break_2d docs/img/dam_break_front.png
	@# every sweep's plot from its table (ryushi sweep draws it too; this redraws after a change to the tool)
	@for csv in $$(find out -name sweep.csv 2>/dev/null); do \
	  keys=$$(head -1 $$csv | tr , '\n' | sed -n '/^run$$/q;p' | sed 's/^/--key /'); \
	  /usr/bin/python3 tools/plot_sweep.py $$csv $$(dirname $$csv)/sweep.png $$keys || exit 1; \
	done

# docs/tradeoffs.md: the speed-accuracy sweeps (tools/tradeoffs.py; about three minutes on 2 cores;
# resumable: delete out/tradeoffs to measure anew).
tradeoffs: build py-deps
	/usr/bin/python3 tools/tradeoffs.py --build $(BUILD) --out out/tradeoffs --doc docs/tradeoffs.md

# Seeded scene mutations through `ryushi check` (tools/fuzz_check.py; 300 of them run in make test).
FUZZ_CHECK_COUNT ?= 1000
fuzz-check: build
	/usr/bin/python3 tools/fuzz_check.py $(BUILD)/ryushi --count $(FUZZ_CHECK_COUNT) --keep fuzz/check-findings

FUZZ_SECONDS ?= 600
# libFuzzer on the scene loader (fuzz/README.md); new coverage is merged into fuzz/corpus/.
fuzz: deps
	@dpkg -s clang >/dev/null 2>&1 || { $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq clang; }
	cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRYUSHI_FUZZ=ON
	cmake --build build-fuzz -j$(JOBS) --target ryushi_scene_fuzzer
	mkdir -p fuzz/corpus-new fuzz/crashes
	build-fuzz/ryushi_scene_fuzzer -max_total_time=$(FUZZ_SECONDS) -timeout=10 -max_len=8192 -dict=fuzz/toml.dict \
	  -artifact_prefix=fuzz/crashes/ -print_final_stats=1 fuzz/corpus-new fuzz/corpus
	build-fuzz/ryushi_scene_fuzzer -merge=1 fuzz/corpus fuzz/corpus-new
	rm -rf fuzz/corpus-new

docs: build
	$(BUILD)/ryushi keys --markdown > docs/scenes.md

clean:
	rm -rf $(BUILD) build-sanitize
