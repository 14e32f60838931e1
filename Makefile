# The two commands of the README:
#   make run   - set up, build the `penumbra` program alone, and run the main job on the
#                default scene (window when a display exists, else headless export into ./out)
#   make test  - set up, build everything (the program and every test binary), and run every
#                test (GUI tests under xvfb-run)
#   make bench - regenerate the committed result sets under bench/ and docs/performance.md
#                (a long run: give it a quiet machine; bench/README.md)
#   make readme-figures - the README's screenshot and methods figure (docs/images/)
#   make stage-docs - the README's stage table and docs/stage_graph.{dot,svg}, from the
#                registry (ctest -R StageDocs fails while they are stale)
BUILD ?= build
JOBS  ?= $(shell nproc)

.PHONY: setup configure program build run test bench performance-doc clean fuzz sanitize readme-figures stage-docs
setup:
	@scripts/setup.sh

configure: setup
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

# The main job needs the program alone, not the test binaries.
program: configure
	@cmake --build $(BUILD) -j $(JOBS) --target penumbra

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

run: program
	@if [ -n "$$DISPLAY" ]; then $(BUILD)/penumbra; \
	 else $(BUILD)/penumbra export --scene cube --out out && echo "no display: exported the default scene into ./out"; fi

test: build
	@cd $(BUILD) && xvfb-run -a -s '-screen 0 1280x800x24' ctest --output-on-failure -j 2

# Every committed result set (bench/README.md lists them), then docs/performance.md from them.
# BENCH_SETS="cube-default plate-atty-4.2" regenerates only those.
bench: program
	@scripts/bench_all.sh $(BUILD)/penumbra $(BENCH_SETS)
	@scripts/performance_doc.py

# docs/performance.md from the committed result sets alone (no run).
performance-doc:
	@scripts/performance_doc.py

# docs/images/window.png and docs/images/methods.png (scripts/readme_figures.sh), about 30 s.
readme-figures: program
	@scripts/readme_figures.sh $(BUILD)

# The stage table and graph written from the stage declarations (scripts/stage_docs.sh).
stage-docs: program
	@scripts/stage_docs.sh $(BUILD)

# Reliability (docs/reliability.md): libFuzzer on the scene JSON reader and the glTF importer
# (FUZZ_SECONDS each, default 60), and the test suite under ASan + UBSan with leak checking.
fuzz:
	@scripts/setup.sh fuzz
	@scripts/fuzz.sh

sanitize: setup
	@scripts/sanitize.sh

clean:
	rm -rf $(BUILD) build-fuzz build-sanitize out
