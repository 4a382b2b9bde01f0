"""The FairSplines commands, one module per capability, and how the workbench shows them.

    csr.py         Spline through points (csr fit), Fair fit
    design.py      basic curves, Design spline, Mark points, Edit control points, Profile test
    fair_blend.py  Fair blend, Monotone design
    blend.py       Blend basic shape
    face_blend.py  Blend faces
    analysis.py    Curvature comb, Curvature plot, Check curvature monotonicity
    common.py      what they share: the selection, macro lines, resources

Importing these modules registers nothing; InitGui.Initialize calls register() and lays
out TOOLBAR and MENU. Drop-down groups keep the toolbar short: each shows the command last
used.
"""
from . import analysis, blend, csr, design, face_blend, fair_blend
from .common import QT_TRANSLATE_NOOP, resources

BLEND_GROUP = "FairSplines_BlendGroup"
FIT_GROUP = "FairSplines_FitGroup"

TOOLBAR = (
    FIT_GROUP,
    design.GROUP,
    "FairSplines_DesignSpline",
    "FairSplines_EditPolygon",
    BLEND_GROUP,
    analysis.GROUP,
)

# (submenu or None, commands); "Separator" draws a line.
MENU = (
    (None, [csr.NAME, csr.FAIR_NAME]),
    (QT_TRANSLATE_NOOP("Workbench", "Basic curve"), list(design.KIND_COMMANDS.values())),
    (None, ["FairSplines_DesignSpline", "FairSplines_MarkPoints", "FairSplines_EditPolygon", "Separator",
            fair_blend.NAME, fair_blend.DESIGN_NAME, blend.NAME, face_blend.NAME, "Separator",
            *analysis.COMMANDS, "FairSplines_ProfileTest"]),
)


class CommandGroup:
    """A drop-down button of commands (FreeCAD's command group): the first is the default."""

    def __init__(self, name, commands, menu_text, tooltip, help_section, icon):
        self.name, self.commands = name, tuple(commands)
        self.menu_text, self.tooltip, self.help_section, self.icon = menu_text, tooltip, help_section, icon

    def GetCommands(self):
        return self.commands

    def GetDefaultCommand(self):
        return 0

    def GetResources(self):
        return resources(self.name, self.menu_text, self.tooltip, self.help_section, icon=self.icon)

    def IsActive(self):
        return True


def _groups():
    fit = CommandGroup(
        FIT_GROUP, (csr.NAME, csr.FAIR_NAME),
        QT_TRANSLATE_NOOP(FIT_GROUP, "Fit points"),
        QT_TRANSLATE_NOOP(FIT_GROUP, "Spline through points (csr fit), fair fit within a tolerance"),
        "Using it in the FreeCAD GUI", csr.NAME)
    blends = CommandGroup(
        BLEND_GROUP, (fair_blend.NAME, fair_blend.DESIGN_NAME, blend.NAME, face_blend.NAME),
        QT_TRANSLATE_NOOP(BLEND_GROUP, "Blends"),
        QT_TRANSLATE_NOOP(BLEND_GROUP, "Fair blend between two curves, monotone design, blend basic shape, "
                                       "blend faces"),
        "Fair blends (G1 and G2)", fair_blend.NAME)
    return {FIT_GROUP: fit, BLEND_GROUP: blends}


def command_objects():
    """{name: command} of every FairSplines command."""
    commands = {}
    for module in (csr, design, fair_blend, blend, face_blend, analysis):
        commands.update(module.command_objects())
    commands.update(_groups())
    return commands


def place_toolbar(name="FairSplines"):
    """Start the workbench's toolbar on a new row of the top toolbar area if the row it is
    in leaves it too little room to show all its buttons. Returns True if it moved."""
    from ..qt import QtCore, QtWidgets, main_window

    main = main_window()
    if main is None:
        return False
    bars = [b for b in main.findChildren(QtWidgets.QToolBar) if b.windowTitle() == name or b.objectName() == name]
    if not bars:
        return False
    bar = bars[0]
    if main.toolBarArea(bar) != QtCore.Qt.TopToolBarArea or main.toolBarBreak(bar):
        return False
    if bar.sizeHint().width() <= bar.width() + 1:
        return False  # every button shows already
    main.insertToolBarBreak(bar)
    return True


def register():
    """Add every command to FreeCADGui (once)."""
    import FreeCADGui

    existing = FreeCADGui.listCommands()
    for name, command in command_objects().items():
        if name not in existing:
            FreeCADGui.addCommand(name, command)
