"""FairSplines' first run: which compiled kernel to load, what a build of it needs, the build.

Importable without the kernel (``freecad_workbench`` is not), so the workbench can say what
is missing and build it from the GUI:

- record: the build record (Python, OpenCASCADE, FairSplines version) of a compiled kernel,
  compared with the running FreeCAD; which folder the kernel is loaded from.
- requirements: the build tools and headers a kernel build needs, detected, and the
  distribution packages that provide the missing ones.
- builder: the build itself (cmake), headless, reporting progress and keeping a log.
- dialog: the thin Qt dialog over the three (GUI only).
"""
