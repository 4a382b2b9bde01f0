"""The workbench as a designer meets it: one short toolbar of drop-down groups, a menu that
holds every command, and every command with its own icon, words, shortcut where it has
one, and What's This help that points to its section of the documentation (README or docs/)."""
import os
import re

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def gui():
    import FreeCADGui

    return FreeCADGui


class _Recorder:
    """Stands in for the workbench while its Initialize runs: records toolbars and menus."""

    def __init__(self):
        self.toolbars, self.menus = [], []

    def appendToolbar(self, name, commands):
        self.toolbars.append((name, list(commands)))

    def appendMenu(self, name, commands):
        self.menus.append((name, list(commands)))


def _layout():
    recorder = _Recorder()
    type(gui().getWorkbench("FairSplinesWorkbench")).Initialize(recorder)
    return recorder


def test_one_toolbar_of_few_buttons_with_groups_that_hold_every_command():
    from freecad_workbench.gui import commands

    g = gui()
    g.activateWorkbench("FairSplinesWorkbench")
    assert g.activeWorkbench().getToolbarItems()["FairSplines"] == list(commands.TOOLBAR)
    recorder = _layout()
    assert [name for name, _ in recorder.toolbars] == ["FairSplines"]
    (toolbar,) = [c for _, c in recorder.toolbars]
    assert len(toolbar) <= 6
    objects = commands.command_objects()
    reachable = set()
    for name in toolbar:
        reachable.add(name)
        if hasattr(objects[name], "GetCommands"):
            reachable.update(objects[name].GetCommands())
    menu = {c for _, names in recorder.menus for c in names if c != "Separator"}
    groups = {n for n, c in objects.items() if hasattr(c, "GetCommands")}
    # every command is in the menu; the toolbar reaches all but the few opened by double-click too
    # (and the first-run build, fairsplines_setup, which works without the kernel)
    assert set(objects) - groups | {"FairSplines_BuildKernel"} == menu
    assert set(objects) - groups - reachable <= {"FairSplines_MarkPoints"}
    assert all(c in g.listCommands() for c in objects)


def test_every_command_has_its_icon_words_and_help():
    from freecad_workbench.gui import commands, icon_path
    from freecad_workbench.gui.qt import qt_module

    QtSvg = qt_module("QtSvg")
    accels = []
    for name, command in commands.command_objects().items():
        resources = command.GetResources()
        menu = resources["MenuText"]
        assert menu and resources["ToolTip"], name
        assert menu[0].isupper() and not re.search(r" [A-Z][a-z]", menu), f"{name}: {menu!r} is not sentence case"
        if hasattr(command, "GetCommands"):
            continue
        assert resources["Pixmap"] == icon_path(name) and QtSvg.QSvgRenderer(resources["Pixmap"]).isValid(), name
        help_text = resources["WhatsThis"]
        section = re.search("\u201c(.+?)\u201d:\n(.+)$", help_text)
        assert section, f"{name}: What's This names no documentation section"
        path = section.group(2)
        assert os.path.realpath(path).startswith(os.path.realpath(REPO) + os.sep) and path.endswith(".md")
        text = open(path, encoding="utf-8").read()
        headings = {m.group(1).strip() for m in re.finditer(r"^#+ (.+)$", text, flags=re.M)}
        assert section.group(1) in headings, f"{name}: {path} has no section {section.group(1)!r}"
        assert resources["ToolTip"].split("\n")[0] in help_text
        if "Accel" in resources:
            accels.append(resources["Accel"])
    assert len(accels) >= 6 and len(set(accels)) == len(accels)


def test_whats_this_of_the_action_is_the_help_not_the_command_name():
    g = gui()
    g.activateWorkbench("FairSplinesWorkbench")
    from freecad_workbench.gui.qt import QtWidgets

    from freecad_workbench.gui.qt import main_window

    main = main_window()
    actions = {a.objectName(): a for a in main.findChildren(QtWidgets.QAction)} if hasattr(QtWidgets, "QAction") else {}
    if not actions:
        from freecad_workbench.gui.qt import QtGui

        actions = {a.objectName(): a for a in main.findChildren(QtGui.QAction)}
    action = actions.get("FairSplines_CsrFit") or next(
        (a for a in actions.values() if a.text() == "Spline through points"), None)
    assert action is not None
    assert "documentation" in action.whatsThis() and action.whatsThis() != "FairSplines_CsrFit"


@pytest.mark.parametrize("group", ["FairSplines_FitGroup", "FairSplines_BasicCurves", "FairSplines_BlendGroup",
                                   "FairSplines_AnalysisGroup"])
def test_groups_default_to_their_first_or_most_used_command(group):
    from freecad_workbench.gui import commands

    command = commands.command_objects()[group]
    members = command.GetCommands()
    assert len(members) >= 2 and 0 <= command.GetDefaultCommand() < len(members)
    assert all(m in gui().listCommands() for m in members)
