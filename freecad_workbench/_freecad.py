"""Locating FreeCAD's Python modules when running outside FreeCAD."""
import importlib
import os
import sys

_CANDIDATES = ("/usr/lib/freecad-python3/lib", "/usr/lib/freecad/lib", "/usr/local/lib/freecad/lib")
# A FreeCAD elsewhere (conda-forge, self-built): the folder that holds its FreeCAD.so.
_OVERRIDE = "FAIRSPLINES_FREECAD_LIB"


def ensure_freecad_path():
    """Make FreeCAD importable from a plain interpreter ($FAIRSPLINES_FREECAD_LIB, then
    Debian's layout) and import it: FreeCAD must be initialised before ``Part`` is
    imported, and before the kernel loads the OpenCASCADE libraries they share."""
    override = os.environ.get(_OVERRIDE)
    for path in ((override,) if override else ()) + (None,) + _CANDIDATES:
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
