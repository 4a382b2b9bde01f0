"""Locating FreeCAD's Python modules when running outside FreeCAD."""
import os
import sys

_CANDIDATES = ("/usr/lib/freecad-python3/lib", "/usr/lib/freecad/lib", "/usr/local/lib/freecad/lib")


def ensure_freecad_path():
    """Make FreeCAD importable from a plain interpreter (Debian's layout first) and
    import it: FreeCAD must be initialised before ``Part`` is imported, and before the
    kernel loads the OpenCASCADE libraries they share."""
    try:
        import FreeCAD  # noqa: F401
        return
    except ImportError:
        pass
    for path in _CANDIDATES:
        if os.path.exists(os.path.join(path, "FreeCAD.so")):
            if path not in sys.path:
                sys.path.append(path)
            import FreeCAD  # noqa: F401,F811
            return
