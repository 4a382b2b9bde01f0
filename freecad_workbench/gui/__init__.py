"""FreeCAD GUI layer of FairSplines.

    view_providers.py   every view provider (one base: status icon, error mark, edit panel)
    panels/             one module per task panel, and form.py, what they share
    commands/           one module per capability, commands only; register() adds them all
    comb.py, plot.py, zebra.py, overlay.py, preferences.py, qt.py

Importing any module here has no side effects: commands are registered by
InitGui.Initialize (commands.register()). comb.comb_lines, plot.curvature_plot (to a
file) and zebra.zebra_mesh work headless too."""
import os

ICON_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "icons")


def icon_path(name):
    """Absolute path of icons/<name>.svg."""
    return os.path.join(ICON_DIR, name + ".svg")


def command_name(kind):
    """The command (and icon) name of a basic curve kind: "Circle arc" -> FairSplines_CircleArc."""
    return "FairSplines_" + kind.title().replace(" ", "")
