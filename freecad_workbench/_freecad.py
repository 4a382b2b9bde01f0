"""Locating FreeCAD's Python modules when running outside FreeCAD."""
import importlib
import os
import sys

_CANDIDATES = ("/usr/lib/freecad-python3/lib", "/usr/lib/freecad/lib", "/usr/local/lib/freecad/lib")


def ensure_freecad_path():
    """Make FreeCAD importable from a plain interpreter (Debian's layout first) and
    import it: FreeCAD must be initialised before ``Part`` is imported, and before the
    kernel loads the OpenCASCADE libraries they share."""
    for path in (None,) + _CANDIDATES:
        if path is not None:
            if not os.path.exists(os.path.join(path, "FreeCAD.so")):
                continue
            if path not in sys.path:
                sys.path.append(path)
        try:
            importlib.import_module("FreeCAD")
            return
        except ImportError:
            continue
