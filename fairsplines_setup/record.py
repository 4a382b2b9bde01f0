"""The build record of the compiled kernel, and the folder it is loaded from.

CMake writes ``_kernel_build.json`` beside the module it links (cpp/CMakeLists.txt): the
Python (major.minor) and the OpenCASCADE (complete version) it was built against, and the
FairSplines version and commit. Before ``freecad_workbench.kernel`` imports ``_kernel`` it
asks ``locate`` for a folder whose record matches the running interpreter:

- the package folder (``make build``, a developer's tree), then
- the user's kernel folder (the first-run build from the GUI, ``user_kernel_dir``).

A kernel built for another Python cannot load: that is an ImportError naming both versions.
A kernel built against another OpenCASCADE than FreeCAD's may load, but the fast hand-over
(occ_bridge: OCCT shapes passed by pointer to ``Part``) needs the very same OCCT, so it is
switched off and Part geometry goes over as arrays (``bridge_allowed``).
"""
from __future__ import annotations

import glob
import json
import os
import sys
import sysconfig

RECORD = "_kernel_build.json"
PACKAGE_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "freecad_workbench")


class KernelUnavailable(ImportError):
    """No compiled kernel that this FreeCAD can load: missing, or built for another Python."""


def python_version():
    """The running interpreter's major.minor, as recorded ("3.13")."""
    return f"{sys.version_info.major}.{sys.version_info.minor}"


def occt_version():
    """The OpenCASCADE FreeCAD runs (Part.OCC_VERSION, "7.8.1"), or None without FreeCAD."""
    try:
        import Part
    except ImportError:
        return None
    return getattr(Part, "OCC_VERSION", None)


def read(folder):
    """The build record in `folder` as a dict, or None (no record, or not readable)."""
    try:
        with open(os.path.join(folder, RECORD), encoding="utf-8") as f:
            record = json.load(f)
    except (OSError, ValueError):
        return None
    return record if isinstance(record, dict) else None


def module_file(folder):
    """The `_kernel` extension in `folder` that this interpreter can import, or None."""
    suffix = sysconfig.get_config_var("EXT_SUFFIX") or ".so"
    path = os.path.join(folder, "_kernel" + suffix)
    return path if os.path.isfile(path) else None


def user_data_dir():
    """FreeCAD's user data folder (versioned on 1.1: .../FreeCAD/v1-1/), or its usual place."""
    try:
        import FreeCAD

        return FreeCAD.getUserAppDataDir()
    except (ImportError, AttributeError):
        return os.path.join(os.path.expanduser("~"), ".local", "share", "FreeCAD")


def user_kernel_dir():
    """Where the first-run build puts the kernel: FAIRSPLINES_KERNEL_DIR, or
    <user data>/FairSplines/kernel-py<X.Y> (one per Python, so FreeCAD versions sharing the
    data folder do not overwrite each other's kernel)."""
    return os.environ.get("FAIRSPLINES_KERNEL_DIR") or os.path.join(
        user_data_dir(), "FairSplines", "kernel-py" + python_version())


def mismatches(record, python=None, occt=None):
    """What differs between a build record and the running FreeCAD, as sentences (empty: none).
    python / occt: the running versions (default: this interpreter, FreeCAD's Part)."""
    python = python or python_version()
    occt = occt if occt is not None else occt_version()
    found = []
    if record.get("python") != python:
        found.append(f"it was built for Python {record.get('python', '?')}, FreeCAD runs Python {python}")
    if occt is not None and record.get("occt") != occt:
        found.append(f"it was built against OpenCASCADE {record.get('occt', '?')}, FreeCAD runs {occt}")
    return found


def candidates():
    """The folders a kernel is looked for in, in order: the package's, then the user's."""
    folders = [PACKAGE_DIR, user_kernel_dir()]
    return [f for i, f in enumerate(folders) if f not in folders[:i]]


def describe(folder):
    """One line on the kernel in `folder`: what it was built for, or that there is none."""
    record = read(folder)
    built = glob.glob(os.path.join(folder, "_kernel*.so")) + glob.glob(os.path.join(folder, "_kernel*.pyd"))
    if not built:
        return f"{folder}: no kernel"
    if record is None:
        return f"{folder}: a kernel without a build record ({os.path.basename(built[0])})"
    return (f"{folder}: FairSplines {record.get('fairsplines', '?')} ({record.get('commit', '?')}), "
            f"Python {record.get('python', '?')}, OpenCASCADE {record.get('occt', '?')}")


def locate(python=None, occt=None):
    """The folder to import `_kernel` from, and what keeps its fast hand-over off (a list of
    sentences; empty when the kernel matches FreeCAD's OpenCASCADE too).

    A folder qualifies when it holds a module this interpreter can import and its record is
    for this Python (a module without a record, from before records, qualifies with a
    note). One matching OpenCASCADE too is preferred. KernelUnavailable says what was found
    and how to build one."""
    python = python or python_version()
    occt = occt if occt is not None else occt_version()
    usable = []
    for folder in candidates():
        record = read(folder)
        if module_file(folder) is None:
            continue
        if record is None:
            usable.append((folder, ["the kernel has no build record (built before records): "
                                    "the versions it was built for are unknown"]))
            continue
        found = mismatches(record, python, occt)
        if any("Python" in m for m in found):
            continue
        usable.append((folder, found))
    if not usable:
        raise KernelUnavailable(unavailable_message(python))
    usable.sort(key=lambda pair: len(pair[1]) > 0)  # a full match first, else the first found
    return usable[0]


def unavailable_message(python=None):
    """Why no kernel can be loaded, folder by folder, and what to do."""
    python = python or python_version()
    lines = [f"The FairSplines C++ kernel is not built for this FreeCAD (Python {python}, "
             f"OpenCASCADE {occt_version() or '?'})."]
    for folder in candidates():
        record = read(folder)
        found = mismatches(record, python) if record is not None else []
        lines.append("  " + describe(folder) + ("" if not found else ": " + "; ".join(found)))
    lines.append("Activate the FairSplines workbench in FreeCAD to build it (no root needed), or run "
                 "'make build' in the add-on's folder with this FreeCAD's Python.")
    return "\n".join(lines)


def bridge_allowed(notes):
    """Whether the fast hand-over may be used: only when the kernel's OpenCASCADE is known to
    be FreeCAD's (`notes` from locate empty)."""
    return not notes


def activate(package_path, python=None, occt=None):
    """Make `from freecad_workbench import _kernel` load the located kernel: its folder goes
    first on the package's __path__ (package_path, modified). Returns locate's notes."""
    folder, notes = locate(python, occt)
    if folder in package_path:
        package_path.remove(folder)
    package_path.insert(0, folder)
    return notes
