# FairSplines: the two commands are `make demo` and `make test` (see README.md).
PYTHON   ?= /usr/bin/python3
BUILD    ?= build
OUT      ?= out
MOD_DIR  ?= $(HOME)/.local/share/FreeCAD/Mod
JOBS     ?= 2
FREECADCMD ?= freecadcmd
XVFB     := xvfb-run -a -s "-screen 0 1280x1024x24"
export QTWEBENGINE_DISABLE_SANDBOX=1

# Sanitized builds with clang (fuzz/README.md): `make fuzz` runs every libFuzzer harness of
# fuzz/ for FUZZ_SECONDS each; `make test-sanitize` runs the C++ tests under ASan + UBSan.
# Both use one build (the kernel compiled once, with the fuzzer's coverage too), so CI
# compiles the sanitized kernel once, not twice.
FUZZ_BUILD   ?= build-fuzz
ASAN_BUILD   ?= $(FUZZ_BUILD)
FUZZ_SECONDS ?= 30
FUZZ_TIMEOUT ?= 5
FUZZ_SEED    ?=
SANITIZED_CMAKE = -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
                  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g"

.PHONY: deps deps-sanitizers build install demo test test-cpp test-python run bench bench-smoke clean \
        test-freecad-1.0 test-freecad-1.1 test-matrix test-first-run test-first-run-absent translations fuzz test-sanitize lint \
        format format-check deps-format

deps:
	@bash tools/install-deps.sh

deps-sanitizers:
	@bash tools/install-deps.sh sanitizers

deps-format:
	@bash tools/install-deps.sh format

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=$(PYTHON) >/dev/null
	cmake --build $(BUILD) -j $(JOBS)

# The add-on is the repository itself, linked into FreeCAD's user Mod folder.
install: build
	mkdir -p $(MOD_DIR)
	ln -sfn $(CURDIR) $(MOD_DIR)/FairSplines

demo: install
	mkdir -p $(OUT)/demo
	FAIRSPLINES_OUT=$(CURDIR)/$(OUT)/demo $(FREECADCMD) demo/demo.py
	@echo "demo: wrote $(OUT)/demo/"

test-cpp: build
	cd $(BUILD) && ctest --output-on-failure

test-python: install
	mkdir -p $(OUT)/test-artifacts
	$(XVFB) $(PYTHON) -m pytest -v tests

test: test-cpp test-python

# The FreeCAD 1.x matrix: `make test` on a fresh clone of HEAD inside a Debian chroot
# (trixie: FreeCAD 1.0, Qt5; sid: FreeCAD 1.1, Qt6), kept in $(FAIRSPLINES_CHROOTS)
# (default /var/cache/fairsplines/chroots). Needs root. See tools/chroot-test.sh.
test-freecad-1.0:
	bash tools/chroot-test.sh trixie test

test-freecad-1.1:
	bash tools/chroot-test.sh sid test

test-matrix: test test-freecad-1.1 test-freecad-1.0

# A new user's first run (issue 30): a clone placed where the Addon Manager puts it, in a
# throwaway overlay of each chroot, FreeCAD's GUI under Xvfb driven through the first-run
# dialog, without the build tools (the dialog lists them) and with them (it builds the
# kernel, at -j 1: minutes). Needs root. Not part of test-matrix (see docs/INSTALL.md).
test-first-run: test-first-run-absent
	bash tools/first-run-test.sh trixie present
	bash tools/first-run-test.sh sid present

# The first run without the build tools only (about 15 s each): CI runs it after the chroots' tests.
test-first-run-absent:
	bash tools/first-run-test.sh trixie absent
	bash tools/first-run-test.sh sid absent

run: install
	freecad

bench: build
	$(BUILD)/bench/bench_csr
	$(BUILD)/bench/bench_design
	$(BUILD)/bench/bench_blend
	$(BUILD)/bench/bench_monotone
	$(BUILD)/bench/bench_fair_blend
	$(BUILD)/bench/bench_fair_blend_space
	$(BUILD)/bench/bench_fair_fit
	$(BUILD)/bench/bench_surface_analysis
	$(PYTHON) bench/bench_handover.py
	$(PYTHON) bench/bench_design_recompute.py
	$(PYTHON) bench/bench_blend.py
	$(PYTHON) bench/bench_surface_analysis.py
	$(PYTHON) bench/bench_face_blend.py

# Every benchmark at its smallest size with few repeats (issue 26): only that each still runs
# to its end, in under 2 minutes; the figures mean nothing. .ci/run runs it.
bench-smoke: build
	$(BUILD)/bench/bench_csr smoke
	$(BUILD)/bench/bench_design smoke
	$(BUILD)/bench/bench_blend smoke
	$(BUILD)/bench/bench_monotone smoke
	$(BUILD)/bench/bench_fair_blend smoke
	$(BUILD)/bench/bench_fair_blend_space smoke
	$(BUILD)/bench/bench_fair_fit 1000
	$(BUILD)/bench/bench_surface_analysis smoke
	$(PYTHON) bench/bench_handover.py smoke
	$(PYTHON) bench/bench_design_recompute.py smoke
	$(PYTHON) bench/bench_blend.py smoke
	$(PYTHON) bench/bench_surface_analysis.py smoke
	$(PYTHON) bench/bench_face_blend.py smoke

# The kernel instrumented for libFuzzer (-fsanitize=address,undefined,fuzzer-no-link) and
# the harnesses; each runs FUZZ_SECONDS from its seed corpus fuzz/corpus/<harness>/.
# Findings land in $(FUZZ_BUILD)/findings/; the target fails if there is one.
fuzz: deps-sanitizers
	cmake -S . -B $(FUZZ_BUILD) $(SANITIZED_CMAKE) -DFAIRSPLINES_FUZZ=ON >/dev/null
	cmake --build $(FUZZ_BUILD) -j $(JOBS)
	FUZZ_SEED=$(FUZZ_SEED) bash fuzz/run.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TIMEOUT)

# The GoogleTest suite built with -fsanitize=address,undefined (UBSan does not recover), and
# the corpus replayed by the harnesses (FuzzReplay.*), in the fuzz build.
test-sanitize: deps-sanitizers
	cmake -S . -B $(ASAN_BUILD) $(SANITIZED_CMAKE) -DFAIRSPLINES_FUZZ=ON >/dev/null
	cmake --build $(ASAN_BUILD) -j $(JOBS)
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure

clean:
	rm -rf $(BUILD) $(OUT) freecad_workbench/_kernel*.so

# The translation template translations/FairSplines.ts, from every translate() and
# QT_TRANSLATE_NOOP() in the sources (tests/toolchain/test_translations.py checks it is current).
translations:
	$(PYTHON) tools/update_translations.py

# flake8 over every Python file of the repository (configuration: .flake8, 120 columns);
# Debian's python3-flake8, which make deps installs.
PY_SOURCES = freecad_workbench fairsplines_setup tests bench tools demo fuzz Init.py InitGui.py
lint: deps
	$(PYTHON) -m flake8 $(PY_SOURCES)

# The C++ style of .clang-format (Google at 120 columns): `make format` rewrites the C++
# files of cpp/, fuzz/ and bench/ in place; `make format-check` changes nothing and fails
# where a file differs from the style.
CLANG_FORMAT ?= clang-format
FORMAT_FILES = $(shell find cpp fuzz bench -name '*.cpp' -o -name '*.hpp' | sort)

format: deps-format
	$(CLANG_FORMAT) -i $(FORMAT_FILES)

format-check: deps-format
	$(CLANG_FORMAT) --dry-run --Werror $(FORMAT_FILES)
