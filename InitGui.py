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
        import FreeCAD
        import FreeCADGui as Gui
        from fairsplines_setup import dialog, record

        # The compiled kernel missing or built for another Python: the first-run dialog says
        # what the build needs and builds it into the user's folder (fairsplines_setup).
        try:
            import freecad_workbench  # noqa: F401
        except record.KernelUnavailable as exc:
            built = dialog.offer_build(str(exc))
            try:
                import freecad_workbench  # noqa: F401,F811
            except record.KernelUnavailable as again:
                FreeCAD.Console.PrintError(str(again) + "\n")
                if built:
                    FreeCAD.Console.PrintError("FairSplines: the kernel was built; restart FreeCAD to use it.\n")
                dialog.register_build_command()
                self.appendToolbar("FairSplines", [dialog.COMMAND])
                self.appendMenu("FairSplines", [dialog.COMMAND])
                return
        from freecad_workbench import kernel
        from freecad_workbench.gui import ICON_DIR, commands, preferences, translations

        if kernel.BRIDGE_OFF:
            FreeCAD.Console.PrintWarning(
                "FairSplines: " + "; ".join(kernel.BRIDGE_OFF) + ". Shapes are handed to FreeCAD as arrays "
                "(exact, slower); FairSplines > Build the kernel builds one for this FreeCAD.\n")
        Gui.addIconPath(ICON_DIR)
        translations.install()
        preferences.register_preferences()
        commands.register()
        dialog.register_build_command()
        self.appendToolbar("FairSplines", list(commands.TOOLBAR))
        for submenu, names in commands.MENU:
            self.appendMenu(["FairSplines", submenu] if submenu else "FairSplines", list(names))
        self.appendMenu("FairSplines", [dialog.COMMAND])

    def Activated(self):
        # Put the FairSplines toolbar on a row of its own when FreeCAD's toolbars fill the
        # first: appended there, it collapses to one button and a chevron.
        from fairsplines_setup import record

        try:
            from freecad_workbench.gui.commands import place_toolbar
        except record.KernelUnavailable:  # no kernel yet: only "Build the kernel" is there
            return
        place_toolbar()

    def Deactivated(self):
        pass

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(FairSplinesWorkbench())
