# FairSplines: the two commands are `make demo` and `make test` (see README.md).
PYTHON   ?= /usr/bin/python3
BUILD    ?= build
OUT      ?= out
MOD_DIR  ?= $(HOME)/.local/share/FreeCAD/Mod
JOBS     ?= 2
FREECADCMD ?= freecadcmd
XVFB     := xvfb-run -a -s "-screen 0 1280x1024x24"
export QTWEBENGINE_DISABLE_SANDBOX=1

.PHONY: deps build install demo test test-cpp test-python run bench clean \
        test-freecad-1.0 test-freecad-1.1 test-matrix translations

deps:
	@bash tools/install-deps.sh

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

run: install
	freecad

bench: build
	$(BUILD)/bench/bench_csr
	$(BUILD)/bench/bench_design
	$(BUILD)/bench/bench_blend
	$(BUILD)/bench/bench_monotone
	$(BUILD)/bench/bench_fair_blend
	$(PYTHON) bench/bench_handover.py
	$(PYTHON) bench/bench_design_recompute.py
	$(PYTHON) bench/bench_blend.py

clean:
	rm -rf $(BUILD) $(OUT) freecad_workbench/_kernel*.so

# The translation template translations/FairSplines.ts, from every translate() and
# QT_TRANSLATE_NOOP() in the sources (tests/toolchain/test_translations.py checks it is current).
translations:
	$(PYTHON) tools/update_translations.py
