"""What a build of the kernel needs, detected on this machine, and the packages that provide it.

Each requirement is checked by looking for the tool on PATH or the header / library file
itself (not by asking the package manager: a self-built OpenCASCADE counts too). The missing
ones are named with the packages of the running distribution (Debian and Ubuntu share the
names; others get the files to look for), and one install command for all of them, which
the user runs: nothing here runs sudo.
"""
from __future__ import annotations

import os
import re
import shutil
import sys
import sysconfig
from collections import namedtuple

Requirement = namedtuple("Requirement", "name why package found optional")
Requirement.__doc__ = (
    "name: what is needed, in words; why: what it is for; package: the Debian/Ubuntu package; "
    "found: the file or tool found (None when missing); optional: the build works without it."
)

# Root folders searched for headers and libraries (tests point them elsewhere).
PREFIXES = ("/usr", "/usr/local")


def _lib_dirs(prefix):
    multiarch = sysconfig.get_config_var("MULTIARCH") or ""
    return [os.path.join(prefix, "lib", multiarch), os.path.join(prefix, "lib64"), os.path.join(prefix, "lib")]


def _find_file(relative_paths, prefixes=None):
    for prefix in prefixes or PREFIXES:
        for rel in relative_paths:
            path = os.path.join(prefix, rel)
            if os.path.exists(path):
                return path
    return None


def _find_library(name, prefixes=None):
    """The link-time library lib<name>.so (the -dev package's symlink), or None."""
    for prefix in prefixes or PREFIXES:
        for folder in _lib_dirs(prefix):
            path = os.path.join(folder, "lib" + name + ".so")
            if os.path.exists(path):
                return path
    return None


def _tool(name, path=None):
    return shutil.which(name, path=path)


def occt_header_version(header):
    """OCC_VERSION_COMPLETE from Standard_Version.hxx ("7.8.1"), or None."""
    try:
        with open(header, encoding="utf-8", errors="replace") as f:
            match = re.search(r'#define\s+OCC_VERSION_COMPLETE\s+"([^"]+)"', f.read())
    except OSError:
        return None
    return match.group(1) if match else None


def detect(prefixes=None, path=None):
    """Every requirement of a kernel build, each with what was found (None: missing).
    prefixes: the folders searched for headers and libraries (default /usr, /usr/local);
    path: the PATH searched for tools (default the process's)."""
    py_include = sysconfig.get_paths().get("include", "")
    python_h = os.path.join(py_include, "Python.h")
    reqs = [
        Requirement("CMake", "runs the build", "cmake", _tool("cmake", path), False),
        Requirement("a C++ compiler", "compiles the kernel", "g++",
                    _tool("c++", path) or _tool("g++", path) or _tool("clang++", path), False),
        Requirement("make", "drives the compiler", "make", _tool("make", path) or _tool("ninja", path), False),
        Requirement(f"Python {sys.version_info.major}.{sys.version_info.minor} headers",
                    "the kernel is a Python module", "python3-dev",
                    python_h if os.path.isfile(python_h) and prefixes is None else
                    _find_file([os.path.join("include", os.path.basename(py_include), "Python.h")], prefixes),
                    False),
        Requirement("pybind11", "the kernel's Python binding", "pybind11-dev",
                    _find_file(["include/pybind11/pybind11.h"], prefixes), False),
        Requirement("Eigen", "the kernel's linear algebra", "libeigen3-dev",
                    _find_file(["include/eigen3/Eigen/Core", "include/Eigen/Core"], prefixes), False),
        Requirement("OpenCASCADE headers", "the kernel's geometry (FreeCAD's own OCCT)", "libocct-foundation-dev",
                    _find_file(["include/opencascade/Standard_Version.hxx"], prefixes), False),
        Requirement("OpenCASCADE modelling data", "B-spline curves, surfaces and shapes",
                    "libocct-modeling-data-dev", _find_library("TKBRep", prefixes), False),
        Requirement("OpenCASCADE modelling algorithms", "B-spline algorithms and meshing",
                    "libocct-modeling-algorithms-dev", _find_library("TKTopAlgo", prefixes), False),
        Requirement("SWIG", "the fast hand-over of shapes to FreeCAD (optional: without it, arrays)",
                    "swig", _tool("swig", path) or _tool("swig4.0", path), True),
    ]
    return reqs


def missing(reqs, optional=True):
    """The requirements not found (with the optional ones unless optional=False)."""
    return [r for r in reqs if r.found is None and (optional or not r.optional)]


def can_build(reqs):
    """Whether everything a build cannot do without is there."""
    return not missing(reqs, optional=False)


def distribution(os_release="/etc/os-release"):
    """The running distribution's ID and ID_LIKE words from os-release ({"debian"}, {"ubuntu", "debian"})."""
    words = set()
    try:
        with open(os_release, encoding="utf-8") as f:
            for line in f:
                key, _, value = line.strip().partition("=")
                if key in ("ID", "ID_LIKE"):
                    words.update(value.strip('"').split())
    except OSError:
        pass
    return words


def install_command(reqs, os_release="/etc/os-release"):
    """The one command that installs the missing requirements (optional ones included), or
    None when nothing is missing or the distribution is not Debian-like (then the packages'
    names are only a guide)."""
    packages = sorted({r.package for r in missing(reqs)})
    if not packages:
        return None
    if distribution(os_release) & {"debian", "ubuntu"}:
        return "sudo apt install " + " ".join(packages)
    return None


def occt_matches(reqs, running):
    """None when the OCCT headers are missing or FreeCAD's OCCT is unknown; else whether the
    headers are the OCCT FreeCAD runs (otherwise the fast hand-over is switched off)."""
    header = next((r.found for r in reqs if r.package == "libocct-foundation-dev"), None)
    if header is None or running is None:
        return None
    return occt_header_version(header) == running
