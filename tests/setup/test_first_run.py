"""The first run (fairsplines_setup): which kernel is loaded and what a build of it needs.

A kernel built for another Python is an ImportError that names both versions; one built
against another OpenCASCADE loads with the fast hand-over off, handing Part the same
geometry through arrays. The requirements are detected from files and tools (a fake prefix
without Eigen misses exactly Eigen); the builder reports a failing compiler's last lines.
"""
import json
import os
import stat
import subprocess
import sys
import textwrap

import pytest

from fairsplines_setup import builder, record, requirements

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXT = __import__("sysconfig").get_config_var("EXT_SUFFIX")


def _fake_kernel(folder, python, occt="7.6.3"):
    os.makedirs(folder, exist_ok=True)
    open(os.path.join(folder, "_kernel" + EXT), "wb").close()
    with open(os.path.join(folder, record.RECORD), "w") as f:
        json.dump({"fairsplines": "0.1.0", "commit": "abc", "python": python, "occt": occt}, f)


@pytest.fixture
def folders(tmp_path, monkeypatch):
    package, user = str(tmp_path / "package"), str(tmp_path / "user")
    monkeypatch.setattr(record, "PACKAGE_DIR", package)
    monkeypatch.setenv("FAIRSPLINES_KERNEL_DIR", user)
    return package, user


def test_the_build_record_names_this_python_and_freecads_occt():
    import Part

    folder, notes = record.locate()
    built = record.read(folder)
    assert built["python"] == f"{sys.version_info.major}.{sys.version_info.minor}"
    assert built["occt"] == Part.OCC_VERSION and notes == []
    assert built["fairsplines"] == "0.1.0" and built["commit"]


def test_a_kernel_for_another_python_is_reported_with_both_versions(folders):
    package, _ = folders
    _fake_kernel(package, "3.11")
    with pytest.raises(record.KernelUnavailable) as err:
        record.locate(python="3.13", occt="7.6.3")
    assert "built for Python 3.11, FreeCAD runs Python 3.13" in str(err.value)
    assert isinstance(err.value, ImportError)


def test_no_kernel_at_all_says_how_to_build_one(folders):
    with pytest.raises(record.KernelUnavailable, match="Activate the FairSplines workbench"):
        record.locate(python="3.11", occt="7.6.3")


def test_a_full_match_in_the_users_folder_wins_over_another_occt_in_the_package(folders):
    package, user = folders
    _fake_kernel(package, "3.11", occt="7.6.3")
    _fake_kernel(user, "3.11", occt="7.8.1")
    assert record.locate(python="3.11", occt="7.8.1") == (user, [])
    folder, notes = record.locate(python="3.11", occt="7.9.2")  # neither: the first, bridge off
    assert folder == package and "OpenCASCADE 7.6.3, FreeCAD runs 7.9.2" in notes[0]
    assert not record.bridge_allowed(notes)
    path = ["somewhere"]
    record.activate(path, python="3.11", occt="7.8.1")
    assert path == [user, "somewhere"]


def _run(code):
    script = "import sys; sys.path.insert(0, %r)\n" % REPO + textwrap.dedent(code)
    return subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, FAIRSPLINES_KERNEL_DIR=os.path.join(REPO, "out", "no-kernel")))


def test_importing_under_another_python_fails_cleanly_naming_the_versions():
    run = _run("""
        from fairsplines_setup import record
        record.python_version = lambda: "3.99"   # FreeCAD now runs another Python
        try:
            import freecad_workbench
        except record.KernelUnavailable as exc:
            print("UNAVAILABLE", exc)
        """)
    assert run.returncode == 0, run.stderr
    assert "UNAVAILABLE" in run.stdout and "FreeCAD runs Python 3.99" in run.stdout


_CURVE = """
    import numpy as np
    import freecad_workbench as fw
    from freecad_workbench import kernel
    t = np.linspace(0, 3, 9)
    c = fw.csr_spline(np.c_[t, np.sin(t), 0 * t])
    print("BRIDGE", kernel.has_bridge(), kernel.BRIDGE_OFF)
    print("POLES", [tuple(p) for p in c.getPoles()], c.getKnots(), c.value(1.3))
    """


def test_another_occt_loads_with_the_array_hand_over_and_the_same_geometry():
    normal = _run(_CURVE)
    other = _run(textwrap.dedent("""
        from fairsplines_setup import record
        record.occt_version = lambda: "7.0.0"    # FreeCAD now runs another OpenCASCADE
        """) + textwrap.dedent(_CURVE))
    assert normal.returncode == 0 and other.returncode == 0, normal.stderr + other.stderr
    assert "BRIDGE True []" in normal.stdout
    assert "BRIDGE False" in other.stdout and "FreeCAD runs 7.0.0" in other.stdout
    poles = [line for line in normal.stdout.splitlines() if line.startswith("POLES")]
    assert poles and poles == [line for line in other.stdout.splitlines() if line.startswith("POLES")]


def _fake_prefix(root, without=()):
    files = {
        "eigen": "include/eigen3/Eigen/Core",
        "occt": "include/opencascade/Standard_Version.hxx",
        "pybind11": "include/pybind11/pybind11.h",
        "python": f"include/python{sys.version_info.major}.{sys.version_info.minor}/Python.h",
        "tkbrep": "lib/libTKBRep.so",
        "tktopalgo": "lib/libTKTopAlgo.so",
    }
    for key, rel in files.items():
        if key not in without:
            path = os.path.join(root, rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w") as f:
                f.write('#define OCC_VERSION_COMPLETE "7.6.3"\n' if key == "occt" else "")
    return str(root)


def _fake_tools(folder, names):
    os.makedirs(folder, exist_ok=True)
    for name in names:
        path = os.path.join(folder, name)
        with open(path, "w") as f:
            f.write("#!/bin/sh\nexit 0\n")
        os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)
    return folder


def test_a_missing_header_package_is_detected_and_named_in_the_install_command(tmp_path):
    prefix = _fake_prefix(tmp_path / "usr", without=("eigen",))
    tools = _fake_tools(str(tmp_path / "bin"), ["cmake", "g++", "make", "swig"])
    reqs = requirements.detect(prefixes=[prefix], path=tools)
    assert [r.package for r in requirements.missing(reqs)] == ["libeigen3-dev"]
    assert not requirements.can_build(reqs)
    os_release = tmp_path / "os-release"
    os_release.write_text('ID=ubuntu\nID_LIKE="debian"\n')
    assert requirements.install_command(reqs, str(os_release)) == "sudo apt install libeigen3-dev"
    assert requirements.occt_matches(reqs, "7.6.3") is True and requirements.occt_matches(reqs, "7.8.1") is False


def test_nothing_installed_lists_every_package_and_swig_is_optional(tmp_path):
    reqs = requirements.detect(prefixes=[str(tmp_path)], path=str(tmp_path))
    os_release = tmp_path / "os-release"
    os_release.write_text("ID=debian\n")
    assert requirements.install_command(reqs, str(os_release)) == (
        "sudo apt install cmake g++ libeigen3-dev libocct-foundation-dev libocct-modeling-algorithms-dev "
        "libocct-modeling-data-dev make pybind11-dev python3-dev swig")
    assert [r.package for r in requirements.missing(reqs, optional=False)][-1] == "libocct-modeling-algorithms-dev"
    full = requirements.detect(prefixes=[_fake_prefix(tmp_path / "usr")],
                               path=_fake_tools(str(tmp_path / "bin"), ["cmake", "c++", "make"]))
    assert requirements.can_build(full) and [r.package for r in requirements.missing(full)] == ["swig"]
    os_release.write_text("ID=fedora\n")
    assert requirements.install_command(reqs, str(os_release)) is None  # names only a guide there


def _fake_cmake(folder, body):
    path = os.path.join(folder, "cmake")
    with open(path, "w") as f:
        f.write("#!/bin/sh\n" + body)
    os.chmod(path, 0o755)
    return path


def test_a_failing_compiler_shows_its_last_lines_and_the_log(tmp_path):
    cmake = _fake_cmake(str(tmp_path), textwrap.dedent("""\
        [ "$1" = "--build" ] || { echo "-- Configuring done"; exit 0; }
        echo "[ 10%] Building CXX object csr.cpp.o"
        echo "csr.cpp:12:3: error: 'Eigen' has not been declared" >&2
        exit 2
        """))
    seen = []
    result = builder.build(lambda f, line: seen.append((f, line)), kernel_dir=str(tmp_path / "kernel"), jobs=1,
                           cmake=cmake)
    assert not result.ok
    assert "error: 'Eigen' has not been declared" in result.tail and "exit status 2" in result.tail
    assert os.path.isfile(result.log_path) and result.tail in open(result.log_path).read()
    assert any(abs(f - (0.05 + 0.95 * 0.10)) < 1e-9 for f, _ in seen)


def test_a_build_succeeds_only_with_a_module_and_its_record_and_progress_reaches_the_end(tmp_path):
    kernel_dir = str(tmp_path / "kernel")
    # A stale module from an earlier build is removed first: a build that writes nothing fails.
    _fake_kernel(kernel_dir, "3.11")
    silent = builder.build(kernel_dir=kernel_dir, jobs=1, cmake=_fake_cmake(str(tmp_path), "exit 0\n"))
    assert not silent.ok and record.module_file(kernel_dir) is None
    writes = _fake_cmake(str(tmp_path), textwrap.dedent(f"""\
        [ "$1" = "--build" ] || exit 0
        echo "[ 50%] Building"
        echo "[100%] Linking"
        touch {kernel_dir}/_kernel{EXT}
        echo '{{"python": "3.11"}}' > {kernel_dir}/{record.RECORD}
        """))
    seen = []
    result = builder.build(lambda f, line: seen.append(f), kernel_dir=kernel_dir, jobs=1, cmake=writes)
    assert result.ok and seen == sorted(seen) and seen[-1] == 1.0


def test_the_build_command_builds_only_the_module_into_the_kernel_folder():
    configure, compile_ = builder.commands("/k", "/b", 3)
    assert "-DFAIRSPLINES_MODULE_DIR=/k" in configure and "-DFAIRSPLINES_BUILD_TESTS=OFF" in configure
    python = [a for a in configure if a.startswith("-DPython_EXECUTABLE=")][0].split("=", 1)[1]
    out = subprocess.run([python, "-c", "import sys; print(sys.version_info[:2])"], capture_output=True, text=True)
    assert out.stdout.strip() == str(sys.version_info[:2])
    assert compile_[-2:] == ["-j", "3"]
