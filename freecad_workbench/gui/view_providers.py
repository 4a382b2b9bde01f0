"""View providers of every FairSplines feature (GUI only).

One base, `ViewProvider`: the tree icon of the feature (named after its command), with an
amber mark while its Status is a warning ("warning: ...": a shape, but short of what was
asked) and a red mark while it holds an error (FreeCAD's own error mark shows too, since
a failed recompute leaves the object invalid); double-click or Edit opens the feature's
task panel (PANEL: "module:Class" under gui/panels/, imported when it opens). Nothing is
stored in the file but properties.

Features attach these through features.base.attach_view_provider only. Documents saved
before the gui/ package was reorganised name some classes by their old modules; those
modules (design_view_providers.py, blend_commands.py) re-export them from here.
"""
import importlib
import os

import FreeCAD
import FreeCADGui

from ..features.base import StatelessProxy
from . import command_name, icon_path

translate = FreeCAD.Qt.translate


def local_shape(obj):
    """obj's shape without its own Placement (the view provider's transform applies it)."""
    shape = obj.Shape.copy()
    shape.Placement = FreeCAD.Placement()
    return shape


class ViewProvider(StatelessProxy):
    """Icon with warning and error marks, edit panel, nothing stored in the file."""

    ICON = "FairSplines"
    ERROR_ICON = None  # default ICON + "Error"
    PANEL = None  # "module:Class" under gui/panels, or None (nothing to edit but properties)

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
        if obj is None:
            return icon_path(self.ICON)
        base = self.icon_name(obj)
        status = getattr(obj, "Status", "ok")
        if status.startswith("warning:"):
            warning = icon_path(base + "Warning")
            return warning if os.path.exists(warning) else icon_path(base)
        if status != "ok" and not status.startswith("ok:"):  # "ok: 42 poles, ..." (fair fit) is fine
            return icon_path(self.ERROR_ICON or base + "Error")
        return icon_path(base)

    def updateData(self, obj, prop):
        if prop in ("Status", "Kind") and obj.ViewObject is not None:
            obj.ViewObject.signalChangeIcon()

    def onChanged(self, vobj, prop):
        pass

    def make_panel(self, obj):
        if self.PANEL is None:
            return None
        module, name = self.PANEL.split(":")
        return getattr(importlib.import_module(module, __package__), name)(obj)

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
        if panel is not None and hasattr(panel, "finish"):
            panel.finish()
        FreeCADGui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        if self.PANEL is None:
            return False  # FreeCAD's default
        FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    def setupContextMenu(self, vobj, menu):
        if self.PANEL is None:
            return
        action = menu.addAction(translate("FairSplines", "Edit {}").format(vobj.Object.Label))
        action.triggered.connect(lambda: FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name, 0))


StatusIconViewProvider = ViewProvider  # the name documents of csr fits and blends store


class ViewProviderCsrFit(ViewProvider):
    ICON = "FairSplines_CsrFit"


class ViewProviderFairFit(ViewProvider):
    ICON = "FairSplines_FairFit"


class ViewProviderFairBlend(ViewProvider):
    ICON = "FairSplines_MonotoneBlend"  # the command kept its name: toolbars people made keep it


ViewProviderMonotoneBlend = ViewProviderFairBlend  # the name documents before fair blends store


class ViewProviderMonotoneDesign(ViewProvider):
    """Double-click (or Edit) opens the Monotone design task panel."""

    ICON = "FairSplines_MonotoneDesign"
    PANEL = ".panels.monotone_design:MonotoneDesignTaskPanel"


class ViewProviderBasicCurve(ViewProvider):
    """Tree icon of its kind; double-click opens the dimensions panel."""

    ICON = "FairSplines_CircleArc"
    ERROR_ICON = "FairSplines_BasicCurveError"
    PANEL = ".panels.basic_curve:BasicCurvePanel"

    def icon_name(self, obj):
        kind = getattr(obj, "Kind", "")
        return command_name(kind) if kind else self.ICON


class PolygonViewProvider(ViewProvider):
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
        from pivy import coin

        from .overlay import Overlay

        self._ensure_properties(vobj)
        self.overlay = Overlay("FairSplinesControlPolygon")
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
                curve = local_shape(obj).Edges[0].Curve
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


class ViewProviderDesignSpline(PolygonViewProvider):
    """Double-click opens the Mark points panel."""

    ICON = "FairSplines_DesignSpline"
    PANEL = ".panels.mark_points:MarkPointsPanel"


class ViewProviderEditPolygon(PolygonViewProvider):
    """Shows its control polygon; double-click opens the Edit polygon panel."""

    ICON = "FairSplines_EditPolygon"
    POLYGON_DEFAULT = True
    PANEL = ".panels.edit_polygon:EditPolygonPanel"


class ViewProviderProfileTest(ViewProvider):
    """The surface of revolution in a 'Zebra' display mode (the default): it reflects
    black and white stripes (gui/zebra.py). The other display modes are Part's."""

    ICON = "FairSplines_ProfileTest"
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

    def mesh_zebra(self, obj):
        """Mesh the object's surface (in its own placement) into the zebra node."""
        shape = obj.Shape
        self.zebra.update(None if shape.isNull() or not shape.Faces else local_shape(obj).Faces[0].Surface)

    def update_zebra(self, force=False):
        """Re-mesh the zebra node from the object's surface if the shape changed."""
        obj = getattr(self, "Object", None)
        if obj is None or not hasattr(self, "zebra"):
            return
        shape = obj.Shape
        if not force and self.meshed is not None and self.meshed.isEqual(shape):
            return
        self.mesh_zebra(obj)
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


class ZebraFacesViewProvider(ViewProviderProfileTest):
    """Every face of the object's shape meshed in the 'Zebra' display mode (the default)."""

    def mesh_zebra(self, obj):
        from .zebra import update_zebra_faces

        update_zebra_faces(self.zebra, [] if obj.Shape.isNull() else local_shape(obj).Faces)


class ViewProviderBlendShape(ZebraFacesViewProvider):
    """The blended shell in the 'Zebra' display mode (the default; gui/zebra.py), every patch
    meshed, so that the stripes show how the basic shape, the transition and the ring join.
    Double-click opens the task panel."""

    ICON = "FairSplines_BlendBasicShape"
    PANEL = ".panels.blend_shape:BlendShapePanel"


class ViewProviderFaceBlend(ZebraFacesViewProvider):
    """The blend of two faces in the 'Zebra' display mode (the default): its stripes run on
    into the faces' own where the faces show zebra too (the panel's Zebra button). Double-click
    opens the task panel."""

    ICON = "FairSplines_BlendFaces"
    PANEL = ".panels.face_blend:FaceBlendPanel"

    def mesh_zebra(self, obj):
        """The blend's normals turned to agree with its first face's along their edge: the
        stripes (mapped from the normals) then run on into that face's zebra."""
        import Part

        from .zebra import update_zebra_faces

        faces = [] if obj.Shape.isNull() else local_shape(obj).Faces
        link = getattr(obj, "FaceA", None)
        if faces and link:
            try:
                face = Part.getShape(link[0]).getElement(link[1][0])
                blend = obj.Shape.Faces[0]
                u0, u1, v0, _ = blend.ParameterRange
                point = blend.valueAt(0.5 * (u0 + u1), v0)
                if face.normalAt(*face.Surface.parameter(point)).dot(blend.normalAt(0.5 * (u0 + u1), v0)) < 0:
                    faces = [f.reversed() for f in faces]
            except Exception:  # a source gone or failing: as the blend is oriented
                pass
        update_zebra_faces(self.zebra, faces)
