"""FreeCAD GUI layer: commands, view providers, the curvature comb and plot.

Importing this package imports no GUI module; `commands` and `view_providers` need
FreeCADGui, while `comb.comb_lines` and `plot.curvature_plot` work headless too."""
import os

ICON_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "icons")


def icon_path(name):
    """Absolute path of icons/<name>.svg."""
    return os.path.join(ICON_DIR, name + ".svg")
