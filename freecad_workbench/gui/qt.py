"""The Qt binding of the running FreeCAD GUI, for every module of the workbench:

    from .qt import QtCore, QtGui, QtWidgets

FreeCAD 0.20 and 1.0 run on Qt5 (PySide2), FreeCAD 1.1 on Qt6 (PySide6 only). The binding
is the one FreeCADGui already loaded, so a Qt5 FreeCAD never gets Qt6 loaded beside it
(two Qt libraries in one process crash). Neither is loaded when plain python hosts
FreeCADGui before any Python Qt code ran: then the Qt library FreeCADGui itself links
decides. FreeCAD's own `PySide` wrapper is not used: it is missing under plain python
(tests), and 0.20's has no QtWidgets.

This is the only place that knows there are two bindings.
"""
import importlib
import importlib.util
import sys

_BINDINGS = ("PySide6", "PySide2")
_QT_LIBRARY = {"PySide6": "libQt6Core", "PySide2": "libQt5Core"}


def _linked_qt():
    """The binding matching the Qt core library mapped into this process, or None."""
    try:
        with open("/proc/self/maps", encoding="utf-8", errors="replace") as maps:
            text = maps.read()
    except OSError:
        return None
    for binding in _BINDINGS:
        if _QT_LIBRARY[binding] in text:
            return binding
    return None


def _choose():
    for binding in _BINDINGS:
        if binding in sys.modules:
            return binding
    linked = _linked_qt()
    if linked:
        return linked
    for binding in _BINDINGS:  # no Qt in the process yet: the newest installed
        if importlib.util.find_spec(binding) is not None:
            return binding
    raise ImportError("FairSplines' GUI needs PySide6 or PySide2, and neither is installed")


BINDING = _choose()
QtCore = importlib.import_module(BINDING + ".QtCore")
QtGui = importlib.import_module(BINDING + ".QtGui")
QtWidgets = importlib.import_module(BINDING + ".QtWidgets")
QT_MAJOR = int(QtCore.qVersion().split(".")[0])


def qt_module(name):
    """Another module of the same binding, e.g. qt_module("QtSvg")."""
    return importlib.import_module(BINDING + "." + name)


_main_window = []  # the one wrapper of FreeCAD's main window this process keeps


def main_window():
    """FreeCAD's main window (a QMainWindow), or None.

    Found among Qt's top-level widgets and kept: PySide invalidates the wrappers found
    through a widget's wrapper (its QMdiArea, the tabs) when that wrapper goes. Not
    FreeCADGui.getMainWindow(): FreeCAD releases the wrapper it gives at process exit, after
    Python, which crashes where python hosts FreeCADGui (the tests) once a child was wrapped."""
    if _main_window:
        try:
            _main_window[0].objectName()
            return _main_window[0]
        except RuntimeError:  # deleted
            _main_window.clear()
    for widget in QtWidgets.QApplication.topLevelWidgets():
        if widget.metaObject().className() == "Gui::MainWindow":
            _main_window.append(widget)
            return widget
    return None
