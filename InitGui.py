# FairSplines start-up, GUI part: defines and registers the workbench. FreeCAD runs this
# file with exec() and no __file__, so every name a method needs is imported inside it.
import FreeCADGui


class FairSplinesWorkbench(FreeCADGui.Workbench):
    """Fair curves: csr-spline fitting, design with basic curves, curvature combs and plots."""

    MenuText = "FairSplines"
    ToolTip = "Fair curves: csr-spline fitting, design with basic curves, curvature combs and curvature plots"

    def __init__(self):
        import importlib.util
        import os

        # Locate icons/ beside the package without importing it (nothing slow at start-up).
        spec = importlib.util.find_spec("freecad_workbench")
        if spec is not None and spec.submodule_search_locations:
            root = os.path.dirname(list(spec.submodule_search_locations)[0])
        else:
            import FreeCAD

            root = os.path.join(FreeCAD.getUserAppDataDir(), "Mod", "FairSplines")
        self.__class__.Icon = os.path.join(root, "icons", "FairSplines.svg")

    def Initialize(self):
        import FreeCADGui as Gui
        from freecad_workbench.gui import ICON_DIR, blend_commands, commands, design_commands, monotone_commands

        Gui.addIconPath(ICON_DIR)
        self.appendToolbar("FairSplines", list(commands.COMMANDS))
        self.appendMenu("FairSplines", list(commands.COMMANDS))
        # Design with basic curves: its own toolbar; in the menu the kinds in a submenu.
        self.appendToolbar("FairSplines design", list(design_commands.DESIGN_COMMANDS))
        self.appendMenu("FairSplines", ["Separator"])
        self.appendMenu(["FairSplines", "Basic curve"], list(design_commands.KIND_COMMANDS.values()))
        self.appendMenu("FairSplines", list(design_commands.DESIGN_COMMANDS[1:]))
        # Monotone curvature: its own toolbar, and a submenu.
        self.appendToolbar("FairSplines monotone", list(monotone_commands.COMMANDS))
        self.appendMenu(["FairSplines", "Monotone curvature"], list(monotone_commands.COMMANDS))
        # Basic shapes blended into NURBS: its own toolbar, and a submenu.
        self.appendToolbar("FairSplines blend", list(blend_commands.COMMANDS))
        self.appendMenu(["FairSplines", "Blending"], list(blend_commands.COMMANDS))

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(FairSplinesWorkbench())
