"""View providers of the FairSplines features (GUI only)."""
from ..features.base import StatelessProxy
from . import icon_path


class StatusIconViewProvider(StatelessProxy):
    """Tree icon of a feature with a Status property: its icon (ICON, named after its
    command), the amber-marked ICON + "Warning" while Status begins with "warning:" (a shape,
    but short of what was asked), or the red-marked ICON + "Error" while Status holds an
    error (the message is in the Status property and the report view)."""

    ICON = "FairSplines"

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        obj = getattr(self, "Object", None)
        status = getattr(obj, "Status", "ok") if obj is not None else "ok"
        if status.startswith("warning:"):
            return icon_path(self.ICON + "Warning")
        if status != "ok":
            return icon_path(self.ICON + "Error")
        return icon_path(self.ICON)

    def updateData(self, obj, prop):
        if prop == "Status" and obj.ViewObject is not None:
            obj.ViewObject.signalChangeIcon()

    def onChanged(self, vobj, prop):
        pass


class ViewProviderCsrFit(StatusIconViewProvider):
    ICON = "FairSplines_CsrFit"


class ViewProviderFairBlend(StatusIconViewProvider):
    ICON = "FairSplines_MonotoneBlend"  # the command kept its name: toolbars people made keep it


ViewProviderMonotoneBlend = ViewProviderFairBlend  # the name documents before fair blends store


class ViewProviderMonotoneDesign(StatusIconViewProvider):
    """Double-click (or Edit) opens the Monotone design task panel."""

    ICON = "FairSplines_MonotoneDesign"

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        import FreeCADGui

        from .monotone_commands import MonotoneDesignTaskPanel

        FreeCADGui.Control.showDialog(MonotoneDesignTaskPanel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        import FreeCADGui

        FreeCADGui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        vobj.Document.setEdit(vobj.Object.Name)
        return True
