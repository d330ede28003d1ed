# SPDX-License-Identifier: MIT
# tristream: every target installs what it needs first (tools/install-deps.sh), then builds.
#   make run     build the tools only, then render the demo data with every method into out/ and print a table
#   make test    build, then run every test through ctest
# More: make build | tools | python | test-sanitize | fuzz | cross | bench | bench-mcu | experiments | experiments-quick | rd | baselines | methods | clean

BUILD      ?= build
JOBS       ?= $(shell nproc)
FUZZ_TIME  ?= 60
BENCH_MCU_ARGS ?=

.PHONY: all deps build tools python run test test-sanitize fuzz cross bench bench-mcu clean experiments experiments-quick rd baselines methods

all: build

deps:
	@bash tools/install-deps.sh build

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS)

# The tools alone (trisim, tripack, triencode): no tests, examples or benchmarks.
tools: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS) --target tristream_tools

# The Python module tristream (python/) into $(BUILD)/python/, and the tools its tests compare it with.
python: deps
	@bash tools/install-deps.sh python
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DTRISTREAM_PYTHON=ON
	cmake --build $(BUILD) -j$(JOBS) --target tristream_python tristream_tools

run: tools
	bash tools/run-demo.sh $(BUILD)/bin out

# The mcu group first: the build finds unicorn and capstone when it configures (bench_mcu tests).
test: deps
	@bash tools/install-deps.sh checks experiments mcu ecosystems python
	$(MAKE) build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

# The tests again, built with AddressSanitizer and UndefinedBehaviorSanitizer.
test-sanitize: deps
	@bash tools/install-deps.sh checks experiments ecosystems
	cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DTRISTREAM_SANITIZE=ON -DTRISTREAM_BENCH=OFF
	cmake --build build-sanitize -j$(JOBS)
	cd build-sanitize && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j$(JOBS)

# libFuzzer (clang 14) on every fuzz target for FUZZ_TIME seconds each, from the shipped corpus.
fuzz:
	@bash tools/install-deps.sh build fuzz
	cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 \
	  -DCMAKE_CXX_COMPILER=clang++-14 -DTRISTREAM_FUZZ=ON -DTRISTREAM_TESTS=OFF -DTRISTREAM_BENCH=OFF
	cmake --build build-fuzz -j$(JOBS)
	bash tools/run-fuzzers.sh build-fuzz/bin $(FUZZ_TIME)

# Speed: Google Benchmark of the core (Mpixel/s for triangle counts, tilings and formats), then
# callgrind instructions per pixel (repeatable on a busy machine).
bench: build
	@bash tools/install-deps.sh bench
	$(BUILD)/bin/bench_core
	bash tests/core/callgrind_core.sh $(BUILD)/bin/core_frames

# firmware_core on an emulated Cortex-M4, Cortex-M0+ and RISC-V rv32imc (docs/MCU_BENCH.md):
# instructions, modelled cycles, stack, RAM and flash per configuration, pixels checked against the
# host build. BENCH_MCU_CPUS="m4" (or "m0plus", "rv32imc", any of them) runs fewer cores. A subset:
# make bench-mcu BENCH_MCU_ARGS="--meshes kodim23 --opts O2 --dither off".
BENCH_MCU_CPUS ?= m4 m0plus rv32imc
bench-mcu: deps
	@bash tools/install-deps.sh mcu
	$(MAKE) build
	BENCH_MCU_CPUS="$(BENCH_MCU_CPUS)" bash tools/bench-mcu/run.sh $(BUILD) $(BENCH_MCU_ARGS)

# firmware_core for Cortex-M4 (size report, fails if an allocator is linked), then the golden-image
# test as a 32-bit ARM binary under qemu-arm (pixels must equal the x86-64 goldens).
cross:
	@bash tools/install-deps.sh build cross
	bash firmware_core/cross/build.sh build-cross
	bash firmware_core/cross/run-golden-qemu.sh build-cross

clean:
	rm -rf build build-sanitize build-fuzz build-cross out

# The experiments need trisim and triencode alone (make tools), not the tests.
experiments: tools
	@bash tools/install-deps.sh experiments
	/usr/bin/python3 tools/experiments/run_experiments.py $(BUILD)/bin out/report --set full --jobs 2

experiments-quick: tools
	@bash tools/install-deps.sh experiments browser
	/usr/bin/python3 tools/experiments/run_experiments.py $(BUILD)/bin out/report --set quick --jobs 2
	/usr/bin/python3 tools/experiments/check_page.py out/report/index.html \
	  --figures out/report/charts out/report/pictures --screenshot out/report/screenshot.png

# Rate-distortion of the blobs against JPEG, WebP and JPEG 2000 at equal PSNR (tools/experiments/README.md):
# the shipped images and every PNG under $TRISTREAM_IMAGES, into out/rd/ (rd.csv, rd.png).
rd: tools
	@bash tools/install-deps.sh experiments
	/usr/bin/python3 tools/experiments/rate_distortion.py $(BUILD)/bin out/rd --jobs 2

# triencode against greedy point removal (GPR and GPR + LSQ, tribaseline) at 0.5 to 4 % of the pixels as
# vertices, on every PNG under IMAGES (default $TRISTREAM_IMAGES, else the shipped ones), into
# out/baselines/ (baselines.csv) and a table on stdout (tools/experiments/README.md).
IMAGES ?=
baselines: tools
	/usr/bin/python3 tools/experiments/baselines.py $(BUILD)/bin out/baselines --jobs 2 $(if $(IMAGES),--images $(IMAGES))

# zienkiewicz and clough-tocher (values and gradients fitted for each) against bilinear at equal
# compressed-blob bytes, on every PNG under IMAGES (default $TRISTREAM_IMAGES, else the shipped ones),
# into out/methods/ (methods.csv) and a table on stdout (tools/experiments/README.md).
methods: tools
	@bash tools/install-deps.sh experiments
	/usr/bin/python3 tools/experiments/methods_at_equal_bytes.py $(BUILD)/bin out/methods --jobs 2 $(if $(IMAGES),--images $(IMAGES))
