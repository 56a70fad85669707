# Scalable DOGs: `make demo` and `make test` install what is missing (Debian 12 packages), build
# (CMake + Ninja, RelWithDebInfo) and run. `make fuzz` runs the libFuzzer targets (clang), each for
# FUZZ_SECONDS. `make format` formats the C++ sources with clang-format (.clang-format), `make
# format-check` fails on a source it would change (CI runs it).
BUILD    ?= build
FUZZ_BUILD ?= build-fuzz
JOBS     ?= 2
FUZZ_SECONDS ?= 60
# -noreset: Xvfb otherwise resets when its last client leaves, and a test that connects meanwhile
# (the studio tests start one after another) fails with "could not connect to display".
XVFB     = xvfb-run -a -s "-screen 0 1920x1080x24 -noreset"
SDOG     = $(BUILD)/app/sdog
DEMO_PATTERN = datasets/four_corner_arcs.svg
DEMO_RES = 41x41

DEPS = cmake ninja-build g++ libeigen3-dev libcgal-dev libceres-dev libsuitesparse-dev \
       libopenblas-dev libtbb-dev libvtk9-dev libvtk9-qt-dev qtbase5-dev libgtest-dev \
       libpugixml-dev libcli11-dev nlohmann-json3-dev xvfb xauth python3 clang-format
FUZZ_DEPS = clang libclang-rt-14-dev

.PHONY: all deps fuzz-deps configure build demo test format format-check fuzz previews reference-docs clean

all: build

# Installs missing packages: apt-get as root, sudo otherwise, else prints the command and stops.
define install_packages
	@missing=""; for p in $(1); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  if [ "$$(id -u)" = 0 ]; then apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q $$missing; \
	  elif sudo -n true 2>/dev/null; then sudo apt-get update -q && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y -q $$missing; \
	  else echo "missing Debian packages; install them with:"; echo "  sudo apt-get install$$missing"; exit 1; fi; \
	fi
endef

deps:
	$(call install_packages,$(DEPS))

fuzz-deps:
	$(call install_packages,$(FUZZ_DEPS))

configure: deps
	@[ -f $(BUILD)/build.ninja ] || cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	@rm -rf out/demo.tmp && mkdir -p out
	$(SDOG) mesh $(DEMO_PATTERN) --res $(DEMO_RES) --out out/demo.tmp
	$(XVFB) $(SDOG) render $(DEMO_PATTERN) --res $(DEMO_RES) --size 1600x800 --out out/demo.tmp/vertex_types.png
	$(SDOG) run $(DEMO_PATTERN) --res $(DEMO_RES) --scenario corners --frames-every 10 --out out/demo.tmp/run
	@rm -rf out/demo && mv out/demo.tmp out/demo
	@echo ""; echo "Demo results in out/demo/:"; ls -1 out/demo | sed 's/^/  out\/demo\//'; \
	echo "  out/demo/run/: run.csv (one row per solver iteration), run.json, frames.pvd + $$(ls out/demo/run | grep -c vtu) frames"; \
	echo "Open the .vtu/.vtp files and out/demo/run/frames.pvd in ParaView (File > Open), the picture with any image viewer."

test: build
	cd $(BUILD) && $(XVFB) ctest --output-on-failure -j $(JOBS)

format: deps
	git ls-files '*.cpp' '*.h' | xargs clang-format -i

format-check: deps
	@git ls-files '*.cpp' '*.h' | xargs clang-format --dry-run --Werror 2>&1 | grep -E "error:" | sed 's/: error: code should be clang-formatted.*/: not formatted (make format)/' ; \
	git ls-files '*.cpp' '*.h' | xargs clang-format --dry-run --Werror >/dev/null 2>&1 && echo "clang-format: every C++ source is formatted"

fuzz: fuzz-deps deps
	@[ -f $(FUZZ_BUILD)/build.ninja ] || CXX=clang++ CC=clang cmake -S . -B $(FUZZ_BUILD) -G Ninja -DSDOG_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build $(FUZZ_BUILD) -j $(JOBS)
	mkdir -p $(FUZZ_BUILD)/corpus/svg && cp -n datasets/*.svg tests/fuzz/seeds/*.svg $(FUZZ_BUILD)/corpus/svg/ 2>/dev/null || true
	$(FUZZ_BUILD)/tests/fuzz/fuzz_svg_pattern -max_total_time=$(FUZZ_SECONDS) -max_len=4096 \
	  -dict=tests/fuzz/svg.dict -artifact_prefix=$(FUZZ_BUILD)/ $(FUZZ_BUILD)/corpus/svg
	mkdir -p $(FUZZ_BUILD)/corpus/fold && cp -n datasets/*.fold tests/fuzz/seeds/*.fold $(FUZZ_BUILD)/corpus/fold/ 2>/dev/null || true
	$(FUZZ_BUILD)/tests/fuzz/fuzz_fold_pattern -max_total_time=$(FUZZ_SECONDS) -max_len=4096 \
	  -dict=tests/fuzz/fold.dict -artifact_prefix=$(FUZZ_BUILD)/fold- $(FUZZ_BUILD)/corpus/fold

# Regenerates the dataset previews (datasets/README.md) and the README pictures (also the studio's).
previews: build
	@mkdir -p docs/datasets
	@for f in datasets/*.svg datasets/*.fold; do n=$$(basename $${f%.*}); \
	  $(XVFB) $(SDOG) render $$f --size 1200x600 --out docs/datasets/$$n.png || exit 1; done
	$(XVFB) $(SDOG) render datasets/curved_pleats.svg --res 41x41 --scenario fold --iters 40 --view 3d \
	  --overlay patches,crease-curves --size 1200x700 --out docs/curved_pleats_folded.png
	$(SDOG) run datasets/curved_pleats.svg --res 41x41 --scenario fold --angle 60 --iters 40 --hold 20 \
	  --out out/previews/pleats --export obj
	$(XVFB) $(SDOG) render --run out/previews/pleats --view 3d --style paper --size 1800x1050 \
	  --out docs/curved_pleats_paper.png
	$(XVFB) $(SDOG) render $(DEMO_PATTERN) --res 21x21 --size 1600x800 --out docs/vertex_types.png
	$(XVFB) $(SDOG) render $(DEMO_PATTERN) --res 41x41 --iters 60 --overlay dog-residual,handles,crease-curves --view 3d --size 1600x900 --out docs/dog_residual.png
	$(XVFB) $(BUILD)/app/sdog-studio --screenshot docs/studio_vertex_types.png $(DEMO_PATTERN) --res 21x21 \
	  --overlay vertex-types,crease-curves,wireframe --size 1400x800
	$(XVFB) $(BUILD)/app/sdog-studio --screenshot docs/studio_dog_residual.png $(DEMO_PATTERN) --res 41x41 \
	  --overlay dog-residual,handles,crease-curves --iters 60 --size 1400x800

# Rewrites the generated tables of docs/reference/ (everything after the marker line) from the
# program's own option definitions; a test checks that they match.
REFERENCE_MARKER = <!-- generated tables below: make reference-docs -->
reference-docs: build
	@for page in command-line configuration; do f=docs/reference/$$page.md; \
	  sed -n '1,/^$(REFERENCE_MARKER)$$/p' $$f > $$f.tmp && $(BUILD)/app/sdog-reference $$page >> $$f.tmp && mv $$f.tmp $$f || exit 1; \
	  echo "wrote $$f"; done

clean:
	rm -rf $(BUILD) $(FUZZ_BUILD) out
