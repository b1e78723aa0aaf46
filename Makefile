# The two commands of README.md. Each installs what is missing, configures and builds.
#   make demo   renders the built-in scene to demo.png and builds the Python module
#   make test   builds everything and runs the whole test suite
#   make wheel  builds the Python wheel (pip install . does the same and installs it)
# CMAKE_ARGS adds configure options, e.g. make test CMAKE_ARGS=-DRAYLAB_WERROR=ON

PRESET ?= release
BUILD_DIR := build/$(PRESET)
CMAKE_ARGS ?=
JOBS ?= $(shell nproc)

.PHONY: deps configure demo test wheel bench fuzz format clean

deps:
	@bash scripts/install-deps.sh

configure: deps
	cmake --preset $(PRESET) -DRAYLAB_BUILD_TESTS=ON $(CMAKE_ARGS)

demo: configure
	cmake --build $(BUILD_DIR) --target raylab_cli raylab_python -j $(JOBS)
	$(BUILD_DIR)/bin/raylab render demo -o demo.png
	PYTHONPATH=$(BUILD_DIR)/python /usr/bin/python3 -c "import raylab; print('python: raylab', raylab.__version__)"
	@echo "demo: image at $(CURDIR)/demo.png"
	@echo "demo: Python module: PYTHONPATH=$(CURDIR)/$(BUILD_DIR)/python /usr/bin/python3 (docs/python.md)"

test: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

# The Python wheel (pyproject.toml, setup.py) in build/dist, built offline with Debian's
# setuptools through its own CMake build in build/wheel: pip install build/dist/raylab-*.whl.
wheel: deps
	/usr/bin/python3 -m pip wheel --no-build-isolation --no-deps -w build/dist .

bench: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)
	bash scripts/bench.sh $(BUILD_DIR)

# Each libFuzzer target for FUZZ_SECONDS, starting from the seeds in fuzz/corpus/NAME; new inputs
# go to build/fuzz/corpus (never into the repository); a crash stops with the input saved there.
FUZZ_SECONDS ?= 60
fuzz: deps
	cmake --preset fuzz
	cmake --build build/fuzz --target raylab_fuzz_targets -j $(JOBS)
	bash scripts/fuzz.sh build/fuzz $(FUZZ_SECONDS)

format:
	clang-format -i $$(git ls-files '*.cpp' '*.h')

clean:
	rm -rf build
