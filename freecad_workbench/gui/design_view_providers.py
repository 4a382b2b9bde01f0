"""View providers of the design-with-basic-curves features (GUI only): tree icons (with an
error variant while Status holds a message), double-click opens the feature's task panel,
the control polygon of a Design spline or Edit polygon, and the zebra display mode of the
Profile test."""
import FreeCAD
import FreeCADGui

from ..features.base import StatelessProxy
from . import icon_path

translate = FreeCAD.Qt.translate


def _local_shape(obj):
    """obj's shape without its own Placement (the view provider's transform applies it)."""
    shape = obj.Shape.copy()
    shape.Placement = FreeCAD.Placement()
    return shape


class _ViewProvider(StatelessProxy):
    """Common part: icon, error icon, edit panel, nothing stored in the file."""

    ICON = "FairSplines"
    ERROR_ICON = "FairSplines"

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object
        self.ViewObject = vobj
        self.panel = None

    def icon_name(self, obj):
        return self.ICON

    def getIcon(self):
        obj = getattr(self, "Object", None)
        if obj is not None and getattr(obj, "Status", "ok") != "ok":
            return icon_path(self.ERROR_ICON)
        return icon_path(self.icon_name(obj) if obj is not None else self.ICON)

    def updateData(self, obj, prop):
        if prop in ("Status", "Kind") and obj.ViewObject is not None:
            obj.ViewObject.signalChangeIcon()

    def onChanged(self, vobj, prop):
        pass

    def make_panel(self, obj):
        return None

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None  # Transform and the other modes: FreeCAD's own
        panel = self.make_panel(vobj.Object)
        if panel is None:
            return False
        self.panel = panel
        FreeCADGui.Control.showDialog(panel)
        return True

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        panel, self.panel = getattr(self, "panel", None), None
        if panel is not None:
            panel.finish()
        FreeCADGui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    def setupContextMenu(self, vobj, menu):
        action = menu.addAction(translate("FairSplines", "Edit {}").format(vobj.Object.Label))
        action.triggered.connect(lambda: FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name, 0))


class ViewProviderBasicCurve(_ViewProvider):
    """Tree icon of its kind; double-click opens the dimensions panel."""

    ICON = "FairSplines_CircleArc"
    ERROR_ICON = "FairSplines_BasicCurveError"

    def icon_name(self, obj):
        from .design_commands import KIND_COMMANDS

        return KIND_COMMANDS.get(getattr(obj, "Kind", ""), self.ICON)

    def make_panel(self, obj):
        from .basic_curve_panel import BasicCurvePanel

        return BasicCurvePanel(obj)


class _PolygonViewProvider(_ViewProvider):
    """Draws the control polygon of the object's B-spline edge when ControlPolygon is on."""

    POLYGON_DEFAULT = False

    def __init__(self, vobj):
        super().__init__(vobj)
        self._ensure_properties(vobj)

    def _ensure_properties(self, vobj):
        if "ControlPolygon" not in vobj.PropertiesList:
            vobj.addProperty("App::PropertyBool", "ControlPolygon", "Design",
                             translate("FairSplines", "Show the control polygon of the curve"))
            vobj.ControlPolygon = self.POLYGON_DEFAULT

    def attach(self, vobj):
        super().attach(vobj)
        from .overlay import Overlay

        self._ensure_properties(vobj)
        self.overlay = Overlay("FairSplinesControlPolygon")
        self.switch = None
        from pivy import coin

        self.switch = coin.SoSwitch()
        self.switch.addChild(self.overlay.root)
        vobj.RootNode.addChild(self.switch)
        self._update_polygon()

    def _update_polygon(self):
        vobj = getattr(self, "ViewObject", None)
        if vobj is None or getattr(self, "switch", None) is None:
            return
        show = bool(getattr(vobj, "ControlPolygon", False))
        self.switch.whichChild = 0 if show else -1
        poles = []
        if show:
            obj = vobj.Object
            if not obj.Shape.isNull() and len(obj.Shape.Edges) == 1:
                curve = _local_shape(obj).Edges[0].Curve
                if hasattr(curve, "getPoles"):
                    poles = curve.getPoles()
        self.overlay.set_polygon(poles)

    def updateData(self, obj, prop):
        super().updateData(obj, prop)
        if prop == "Shape":
            self._update_polygon()

    def onChanged(self, vobj, prop):
        if prop in ("ControlPolygon", "Visibility"):
            self._update_polygon()


class ViewProviderDesignSpline(_PolygonViewProvider):
    """Double-click opens the Mark points panel."""

    ICON = "FairSplines_DesignSpline"
    ERROR_ICON = "FairSplines_DesignSplineError"

    def make_panel(self, obj):
        from .mark_points import MarkPointsPanel

        return MarkPointsPanel(obj)


class ViewProviderEditPolygon(_PolygonViewProvider):
    """Shows its control polygon; double-click opens the Edit polygon panel."""

    ICON = "FairSplines_EditPolygon"
    ERROR_ICON = "FairSplines_EditPolygonError"
    POLYGON_DEFAULT = True

    def make_panel(self, obj):
        from .edit_polygon_panel import EditPolygonPanel

        return EditPolygonPanel(obj)


class ViewProviderProfileTest(_ViewProvider):
    """The surface of revolution in a 'Zebra' display mode (the default): it reflects
    black and white stripes (gui/zebra.py). The other display modes are Part's."""

    ICON = "FairSplines_ProfileTest"
    ERROR_ICON = "FairSplines_ProfileTestError"
    ZEBRA = "Zebra"

    def __init__(self, vobj):
        super().__init__(vobj)
        self._ensure_properties(vobj)

    def _ensure_properties(self, vobj):
        if "Stripes" not in vobj.PropertiesList:
            from .zebra import DEFAULT_STRIPES

            vobj.addProperty("App::PropertyInteger", "Stripes", "Zebra",
                             translate("FairSplines", "Number of black and white stripe pairs reflected"))
            vobj.Stripes = DEFAULT_STRIPES

    def attach(self, vobj):
        super().attach(vobj)
        from .zebra import ZebraNode

        self._ensure_properties(vobj)
        self.zebra = ZebraNode(vobj.Stripes)
        self.meshed = None  # the shape the zebra mesh was made of
        vobj.addDisplayMode(self.zebra.root, self.ZEBRA)

    def getDisplayModes(self, vobj):
        return [self.ZEBRA]

    def getDefaultDisplayMode(self):
        return self.ZEBRA

    def setDisplayMode(self, mode):
        if mode == self.ZEBRA:
            self.update_zebra()
        return mode

    def update_zebra(self, force=False):
        """Re-mesh the zebra node from the object's surface if the shape changed."""
        obj = getattr(self, "Object", None)
        if obj is None or not hasattr(self, "zebra"):
            return
        shape = obj.Shape
        if not force and self.meshed is not None and self.meshed.isEqual(shape):
            return
        if shape.isNull() or not shape.Faces:
            self.zebra.update(None)
        else:
            self.zebra.update(_local_shape(obj).Faces[0].Surface)
        self.meshed = shape

    def updateData(self, obj, prop):
        super().updateData(obj, prop)
        if prop == "Shape" and getattr(self, "ViewObject", None) is not None:
            if self.ViewObject.DisplayMode == self.ZEBRA:
                self.update_zebra()

    def onChanged(self, vobj, prop):
        if prop == "Stripes" and hasattr(self, "zebra"):
            self.zebra.set_stripes(max(1, vobj.Stripes))
        elif prop == "DisplayMode" and vobj.DisplayMode == self.ZEBRA:
            self.update_zebra()

    def make_panel(self, obj):
        return None

    def doubleClicked(self, vobj):
        return False  # nothing to edit but the properties

    def setupContextMenu(self, vobj, menu):
        pass
