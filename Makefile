# The README's two commands: `make run` and `make test`. Both install missing Debian
# packages and configure into build/; `make run` builds the viewer and the CLI, `make test`
# everything. Binaries land in build/bin/.
BUILD_DIR      ?= build
SANITIZE_DIR   ?= build-sanitize
CMAKE_ARGS     ?=
JOBS           ?= $(shell nproc 2>/dev/null || echo 2)
CTEST_ARGS     ?=

.PHONY: all deps configure build apps run test test-sanitize bench fuzz fuzz-build fuzz-regressions fuzz-sanitized clean

all: build

deps:
	@bash .ci/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# What `make run` runs, and only that: the viewer (when its GUI packages were found) and the
# CLI, with the libraries they link and the pose detector's models (the video library depends
# on them). No test or benchmark: `make test` builds those. Time: docs/DEVELOPING.md.
apps: configure
	@if cmake --build $(BUILD_DIR) --target help | grep -E '^(\.\.\. )?eigenwalker(:|$$)' >/dev/null; then \
	  cmake --build $(BUILD_DIR) -j $(JOBS) --target eigenwalker eigenwalker-cli; \
	else \
	  cmake --build $(BUILD_DIR) -j $(JOBS) --target eigenwalker-cli; \
	fi

# The viewer on the synthetic default population (RUN_ARGS: data paths, --size, …).
RUN_ARGS ?=
run: apps
	@if [ -x ./$(BUILD_DIR)/bin/eigenwalker ]; then \
	  ./$(BUILD_DIR)/bin/eigenwalker $(RUN_ARGS); \
	else \
	  echo "eigenwalker: the viewer was not built (GUI packages missing); the CLI:"; \
	  ./$(BUILD_DIR)/bin/eigenwalker-cli --help; \
	fi

test: build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS) $(CTEST_ARGS)

# clang: the same ASan + UBSan checks as GCC, and the sanitized build of every target and
# test compiles in less than half GCC's time (tests/snippet/test_snippet_prior.cpp with ASan + UBSan
# at -O1 -g: 64 s → 28 s).
# Without the viewer by default (SANITIZE_GUI=ON adds it): its tests drive Mesa's software
# renderer and were 56 % of the sanitized suite's test time (305 of 545 s) and its sources
# 66 of 230 sanitized compilations in CI; they run unsanitized in `make test`.
SANITIZE_CXX ?= clang++
SANITIZE_GUI ?= OFF
# Tests left out of the sanitized run, and where their code runs sanitized: docs/DEVELOPING.md.
SANITIZE_SKIP ?= ^(ModelLoopOnSharedWalkers\..*|TrackStudyCli\.FilmsTracksAndFitsAHeldOutWalker|EngineCli\.EvaluateScoresTheEnginesAskedFor|EnginesExperiment\.NoiseIsOneDrawPerClipWhateverRunsBesideIt|CameraExperiment\.(ClipsGoThroughOpenPoseJsonAndBack|TheScenesHorizonIsGivenToTheFitAsRead)|LiftedFeetOnSharedWalkers\..*|CameraExperimentOnSharedWalkers\..*|TrackCli\.(ReconstructsTheTrackAsTheViewerFitsIt|ATreadmillWalkerIsTrackedAndFittedInPlace|AWalkPeopleDoNotWalkIsCautioned)|CameraReconstruction\.(SeenFromBehindOrTheSideTheFeetGiveTheStride|RecoversAnApproachingWalkerExactly|AWalkerOnATreadmillIsFittedInPlace)|VideoSource\.SeekingInTheSharedClipsGivesTheSequentialDecodesFrames|DetectCli\.TheWalkingVideoBecomesAWalkerWithNoOtherTool)$$
test-sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_CXX_COMPILER=$(SANITIZE_CXX) -DCMAKE_BUILD_TYPE=Debug -DEW_SANITIZE=ON \
	  -DEW_BUILD_BENCH=OFF -DEW_BUILD_GUI=$(SANITIZE_GUI) $(CMAKE_ARGS)
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(SANITIZE_DIR) --output-on-failure -j $(JOBS) $(if $(SANITIZE_SKIP),-E '$(SANITIZE_SKIP)') $(CTEST_ARGS)

bench: build
	@for b in $(BUILD_DIR)/bin/bench_*; do echo "== $$b"; $$b; done

# libFuzzer (docs/FUZZING.md): a clang build of core and tests/fuzz only, with ASan +
# UBSan, then each harness for FUZZ_SECONDS (FUZZ_JOBS at once). Fails on any finding;
# crashers land in $(FUZZ_DIR)/crashes/<harness>/. `fuzz-regressions` replays the
# committed regression corpus and the seeds once with the same binaries.
FUZZ_DIR       ?= build-fuzz
FUZZ_SECONDS   ?= 30
FUZZ_JOBS      ?= $(JOBS)
FUZZ_CMAKE_ARGS ?=

fuzz-build: deps
	cmake -S . -B $(FUZZ_DIR) -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
	  -DEW_FUZZ=ON $(FUZZ_CMAKE_ARGS)
	cmake --build $(FUZZ_DIR) -j $(JOBS)

fuzz: fuzz-build
	FUZZ_JOBS=$(FUZZ_JOBS) bash tests/fuzz/run_fuzz.sh $(FUZZ_DIR) $(FUZZ_SECONDS)

fuzz-regressions: fuzz-build
	FUZZ_JOBS=$(FUZZ_JOBS) bash tests/fuzz/run_fuzz.sh $(FUZZ_DIR) 0

# The same smoke fuzz on the libFuzzer harnesses of a sanitized build configured with
# -DEW_SANITIZE_FUZZ=ON (CI: `make test-sanitize` builds them, so core is compiled with clang
# once for both).
fuzz-sanitized:
	FUZZ_JOBS=$(FUZZ_JOBS) FUZZ_PREFIX=libfuzzer_ bash tests/fuzz/run_fuzz.sh $(SANITIZE_DIR) $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) $(FUZZ_DIR)
