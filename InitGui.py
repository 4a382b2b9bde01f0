# FairSplines start-up, GUI part: defines and registers the workbench. FreeCAD runs this
# file with exec() and no __file__, so every name a method needs is imported inside it.
import FreeCADGui


class FairSplinesWorkbench(FreeCADGui.Workbench):
    """Fair curves: csr-spline fitting, design with basic curves, fair blends, curvature analysis."""

    MenuText = "FairSplines"
    ToolTip = "Fair curves: splines through points, design with basic curves, fair blends, curvature analysis"

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
        from freecad_workbench.gui import ICON_DIR, commands, preferences, translations

        Gui.addIconPath(ICON_DIR)
        translations.install()
        preferences.register_preferences()
        commands.register()
        self.appendToolbar("FairSplines", list(commands.TOOLBAR))
        for submenu, names in commands.MENU:
            self.appendMenu(["FairSplines", submenu] if submenu else "FairSplines", list(names))

    def Activated(self):
        # Put the FairSplines toolbar on a row of its own when FreeCAD's toolbars fill the
        # first: appended there, it collapses to one button and a chevron.
        from freecad_workbench.gui.commands import place_toolbar

        place_toolbar()

    def Deactivated(self):
        pass

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(FairSplinesWorkbench())
