"""The CMake configuration honours the variables the README gives for building against a
FreeCAD that is not Debian's (conda-forge, self-built): OCCT_INCLUDE_DIR, OCCT_LIBRARY_DIR,
Eigen3_DIR, Python_EXECUTABLE, or one CMAKE_PREFIX_PATH.

The other FreeCAD is played by a prefix of links to this machine's own OpenCASCADE,
Eigen and interpreter: its paths differ from the system's, so the cache shows which one
CMake took. Configure only (no build), about 2 s a run.
"""
import os
import re
import shutil
import subprocess
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOLKITS = ("TKernel", "TKMath", "TKG2d", "TKG3d", "TKGeomBase", "TKGeomAlgo", "TKBRep", "TKTopAlgo", "TKMesh")


def configure(build, *definitions):
    """Run cmake's configure step; (exit code, output, cache entries)."""
    cmake = shutil.which("cmake")
    assert cmake, "cmake is not installed (make deps installs it)"
    args = [cmake, "-S", REPO, "-B", str(build), "-DFAIRSPLINES_BUILD_TESTS=OFF", "-DFAIRSPLINES_BUILD_BENCH=OFF"]
    run = subprocess.run(args + ["-D" + d for d in definitions], capture_output=True, text=True, timeout=120)
    cache = {}
    cache_file = build / "CMakeCache.txt"
    if cache_file.exists():
        for line in cache_file.read_text().splitlines():
            m = re.match(r"^([A-Za-z_0-9]+):[A-Z]+=(.*)$", line)
            if m:
                cache[m.group(1)] = m.group(2)
    return run.returncode, run.stdout + run.stderr, cache


@pytest.fixture(scope="module")
def system(tmp_path_factory):
    """What a plain configure finds on this machine: the Debian packages."""
    code, out, cache = configure(tmp_path_factory.mktemp("plain"), "Python_EXECUTABLE=" + sys.executable)
    assert code == 0, out
    return cache


def occt_version(include_dir):
    text = open(os.path.join(include_dir, "Standard_Version.hxx"), encoding="utf-8").read()
    return re.search(r'#define OCC_VERSION_COMPLETE\s+"([^"]+)"', text).group(1)


@pytest.fixture(scope="module")
def prefix(tmp_path_factory, system):
    """A conda-like prefix: include/{opencascade,eigen3}, lib/libTK*.so, share/eigen3/cmake, bin/python3."""
    root = tmp_path_factory.mktemp("otherfreecad")
    (root / "include").mkdir()
    os.symlink(system["OCCT_INCLUDE_DIR"], root / "include" / "opencascade")
    (root / "lib").mkdir()
    for toolkit in TOOLKITS:
        real = system[f"OCCT_{toolkit}_LIBRARY"]
        os.symlink(os.path.realpath(real), root / "lib" / os.path.basename(real))
    (root / "share" / "eigen3").mkdir(parents=True)
    os.symlink(system["Eigen3_DIR"], root / "share" / "eigen3" / "cmake")
    # Eigen's config names its headers relative to itself: <prefix>/share/eigen3/cmake/../../../include/eigen3
    eigen_prefix = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(system["Eigen3_DIR"]))))
    os.symlink(os.path.join(eigen_prefix, "include", "eigen3"), root / "include" / "eigen3")
    (root / "bin").mkdir()
    os.symlink(sys.executable, root / "bin" / "python3")
    return root


def assert_took_the_prefix(cache, out, root):
    assert cache["OCCT_INCLUDE_DIR"] == str(root / "include" / "opencascade")
    for toolkit in TOOLKITS:
        assert os.path.dirname(cache[f"OCCT_{toolkit}_LIBRARY"]) == str(root / "lib"), toolkit
    assert cache["Eigen3_DIR"] == str(root / "share" / "eigen3" / "cmake")
    assert cache["Python_EXECUTABLE"] == str(root / "bin" / "python3")
    version = occt_version(root / "include" / "opencascade")
    assert f"OpenCASCADE {version}: headers {root}/include/opencascade, libraries {root}/lib" in out


def test_the_explicit_variables_are_honoured(tmp_path, prefix):
    code, out, cache = configure(
        tmp_path / "build",
        f"OCCT_INCLUDE_DIR={prefix}/include/opencascade",
        f"OCCT_LIBRARY_DIR={prefix}/lib",
        f"Eigen3_DIR={prefix}/share/eigen3/cmake",
        f"Python_EXECUTABLE={prefix}/bin/python3",
    )
    assert code == 0, out
    assert_took_the_prefix(cache, out, prefix)


def test_one_prefix_path_finds_everything_in_it(tmp_path, prefix):
    code, out, cache = configure(
        tmp_path / "build", f"CMAKE_PREFIX_PATH={prefix}", f"Python_EXECUTABLE={prefix}/bin/python3"
    )
    assert code == 0, out
    assert_took_the_prefix(cache, out, prefix)


def test_a_wrong_folder_is_named_in_the_error(tmp_path):
    empty = tmp_path / "empty"
    empty.mkdir()
    code, out, _ = configure(tmp_path / "b1", f"OCCT_INCLUDE_DIR={empty}", "Python_EXECUTABLE=" + sys.executable)
    assert code != 0
    assert "OpenCASCADE's headers not found" in out and str(empty) in out

    code, out, _ = configure(tmp_path / "b2", f"OCCT_LIBRARY_DIR={empty}", "Python_EXECUTABLE=" + sys.executable)
    assert code != 0
    assert "OpenCASCADE's TKernel library not found" in out and str(empty) in out
