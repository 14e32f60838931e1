# The two commands of the README:
#   make run   - set up, build, and run the main job on the default scene
#                (window when a display exists, else headless export into ./out)
#   make test  - set up, build, and run every test (GUI tests under xvfb-run)
#   make readme-figures - the README's screenshot and methods figure (docs/images/)
BUILD ?= build
JOBS  ?= $(shell nproc)

.PHONY: setup build run test clean fuzz sanitize readme-figures
setup:
	@scripts/setup.sh

build: setup
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

run: build
	@if [ -n "$$DISPLAY" ]; then $(BUILD)/penumbra; \
	 else $(BUILD)/penumbra export --scene cube --out out && echo "no display: exported the default scene into ./out"; fi

test: build
	@cd $(BUILD) && xvfb-run -a -s '-screen 0 1280x800x24' ctest --output-on-failure -j 2

# docs/images/window.png and docs/images/methods.png (scripts/readme_figures.sh), about 30 s.
readme-figures: build
	@scripts/readme_figures.sh $(BUILD)

# Reliability (docs/reliability.md): libFuzzer on the scene JSON reader and the glTF importer
# (FUZZ_SECONDS each, default 60), and the test suite under ASan + UBSan with leak checking.
fuzz:
	@scripts/setup.sh fuzz
	@scripts/fuzz.sh

sanitize: setup
	@scripts/sanitize.sh

clean:
	rm -rf $(BUILD) build-fuzz build-sanitize out
