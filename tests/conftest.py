"""pytest set-up: this repository and FreeCAD importable from Debian's /usr/bin/python3,
a temporary-document fixture, and (for tests/gui only) one FreeCAD GUI per session.

Run:  xvfb-run -a /usr/bin/python3 -m pytest tests
(QTWEBENGINE_DISABLE_SANDBOX=1 is set here, since FreeCAD exits without it as root.)
GUI tests run after all others, so the headless tests run with FreeCAD.GuiUp false.
"""
import importlib.util
import itertools
import os
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The folder of FreeCAD.so: Debian's, or another FreeCAD's (README, "Building against another FreeCAD").
FREECAD_LIB = os.environ.get("FAIRSPLINES_FREECAD_LIB", "/usr/lib/freecad-python3/lib")
ARTIFACTS = os.path.join(REPO, "out", "test-artifacts")
GUI_DIR = os.path.join(REPO, "tests", "gui")

os.environ.setdefault("QTWEBENGINE_DISABLE_SANDBOX", "1")
if FREECAD_LIB not in sys.path:
    sys.path.append(FREECAD_LIB)

import FreeCAD  # noqa: E402  (FreeCAD first, before Part and the kernel)

# Importing FreeCAD puts the user's Mod folders first on sys.path; the code under test
# is this checkout, whatever ~/.local/share/FreeCAD/Mod/FairSplines points to.
while REPO in sys.path:
    sys.path.remove(REPO)
sys.path.insert(0, REPO)

_spec = importlib.util.find_spec("freecad_workbench")
assert _spec is not None and os.path.realpath(_spec.origin).startswith(os.path.realpath(REPO) + os.sep), (
    "freecad_workbench resolves to " + (_spec.origin if _spec else "nothing")
)


def _is_gui_test(item):
    return os.path.realpath(str(item.fspath)).startswith(os.path.realpath(GUI_DIR) + os.sep)


def pytest_collection_modifyitems(config, items):
    """GUI tests last: once the GUI is up FreeCAD.GuiUp stays true for the session."""
    items.sort(key=_is_gui_test)  # stable: keeps the order inside each group


_names = itertools.count()


@pytest.fixture
def doc():
    """A new empty document, closed after the test."""
    name = f"Test{next(_names)}"
    document = FreeCAD.newDocument(name)
    yield document
    if name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(name)


@pytest.fixture(scope="session")
def artifacts():
    """out/test-artifacts/ (screenshots and plots the tests leave for people to look at)."""
    os.makedirs(ARTIFACTS, exist_ok=True)
    return ARTIFACTS


def _freecad_mod_dir():
    """FreeCAD's own Mod folder. Hosted by plain python, FreeCAD takes its home to be
    /usr/lib/freecad-python3/, where Debian has no Mod: look where the package puts it."""
    for candidate in (os.path.join(FreeCAD.getHomePath(), "Mod"), "/usr/share/freecad/Mod", "/usr/lib/freecad/Mod"):
        if os.path.isdir(candidate):
            return candidate
    return None


@pytest.fixture(scope="session")
def gui():
    """The FreeCAD main window (under Xvfb), with the FairSplines workbench registered.
    Used by every test in tests/gui (their conftest makes it autouse)."""
    if not os.environ.get("DISPLAY"):
        pytest.fail("GUI tests need a display: run them under xvfb-run -a")
    mod_dir = _freecad_mod_dir()
    if mod_dir:  # Python parts of PartGui and SketcherGui (AttachmentEditor, ...)
        for module in ("Part", "Sketcher"):
            path = os.path.join(mod_dir, module)
            if os.path.isdir(path) and path not in sys.path:
                sys.path.append(path)
    import FreeCADGui

    # FreeCAD 1.1 animates view changes: a picture taken right after viewTop() is empty.
    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/View").SetBool("UseNavigationAnimations", False)
    FreeCADGui.showMainWindow()
    # The workbench under test is this checkout's: the user Mod folder may link another one
    # (make install), whose InitGui.py FreeCAD has just run. Run ours the way FreeCAD does.
    if "FairSplinesWorkbench" in FreeCADGui.listWorkbenches():
        FreeCADGui.removeWorkbench("FairSplinesWorkbench")
    with open(os.path.join(REPO, "InitGui.py"), encoding="utf-8") as f:
        exec(compile(f.read(), os.path.join(REPO, "InitGui.py"), "exec"), {"__name__": "InitGui"})
    FreeCADGui.activateWorkbench("FairSplinesWorkbench")
    FreeCADGui.updateGui()
    yield FreeCADGui
    for name in list(FreeCAD.listDocuments()):
        FreeCAD.closeDocument(name)
    _close_plot_windows()
    FreeCADGui.updateGui()


def _close_plot_windows():
    """Close matplotlib's Qt windows while Qt can still delete them: left for interpreter
    exit, Shiboken tears them down after Python (a crash at exit on PySide6)."""
    if "matplotlib.pyplot" in sys.modules:
        sys.modules["matplotlib.pyplot"].close("all")
    from freecad_workbench.gui import plot
    from freecad_workbench.gui.qt import QtCore, QtWidgets

    plot.close_plot_tabs()  # the plot tabs of the main window

    QtCore.QCoreApplication.sendPostedEvents(None, QtCore.QEvent.DeferredDelete)
    for _ in range(3):
        QtWidgets.QApplication.processEvents()
