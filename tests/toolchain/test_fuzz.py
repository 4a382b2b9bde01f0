"""The fuzzing set-up of fuzz/README.md: every harness is built and has a seed corpus, the
corpus is what fuzz/make_corpus.py writes, `make fuzz` and `make test-sanitize` install
their Debian packages, and the fuzz build refuses a compiler other than clang. Reads files
and configures once (about 2 s); the fuzzing itself is `make fuzz`."""
import glob
import os
import re
import shutil
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FUZZ = os.path.join(REPO, "fuzz")


def harnesses():
    return sorted(os.path.basename(p)[:-4] for p in glob.glob(os.path.join(FUZZ, "fuzz_*.cpp")))


def test_every_harness_is_built_and_has_a_small_seed_corpus():
    cmake = open(os.path.join(FUZZ, "CMakeLists.txt"), encoding="utf-8").read()
    listed = re.search(r"set\(FAIRSPLINES_FUZZ_TARGETS(.*?)\)", cmake, re.S).group(1).split()
    assert sorted(listed) == harnesses() and len(listed) >= 9
    for h in listed:
        seeds = glob.glob(os.path.join(FUZZ, "corpus", h, "*"))
        assert len(seeds) >= 4, h
        assert sum(os.path.getsize(s) for s in seeds) < 4096, h
        source = open(os.path.join(FUZZ, h + ".cpp"), encoding="utf-8").read()
        assert 'extern "C" int LLVMFuzzerTestOneInput' in source, h


def test_the_corpus_is_what_make_corpus_writes():
    run = subprocess.run([sys.executable, os.path.join(FUZZ, "make_corpus.py"), "--check"], capture_output=True,
                         text=True, timeout=60)
    assert run.returncode == 0, run.stdout + run.stderr


def test_the_sanitizer_targets_install_clang_and_its_runtimes():
    script = open(os.path.join(REPO, "tools", "install-deps.sh"), encoding="utf-8").read()
    extra = re.search(r"sanitizer_packages=\((.*?)\)", script, re.S).group(1).split()
    assert extra == ["clang", "libclang-rt-dev", "llvm"]
    makefile = open(os.path.join(REPO, "Makefile"), encoding="utf-8").read()
    assert "install-deps.sh sanitizers" in makefile
    for target in ("fuzz", "test-sanitize"):
        assert re.search(rf"^{target}: deps-sanitizers$", makefile, re.M), target


def test_the_fuzz_build_refuses_gcc(tmp_path):
    gxx = shutil.which("g++")
    assert gxx, "g++ is not installed (make deps installs it)"
    run = subprocess.run(["cmake", "-S", REPO, "-B", str(tmp_path), f"-DCMAKE_CXX_COMPILER={gxx}",
                          "-DFAIRSPLINES_FUZZ=ON"], capture_output=True, text=True, timeout=120)
    assert run.returncode != 0
    assert "FAIRSPLINES_FUZZ needs clang" in run.stdout + run.stderr
