"""Coin drawings the design tools put into the 3D view: control polygons (Fig. 10a) and
marked points, as unpickable annotations. GUI only (pivy).

    overlay = Overlay(); overlay.attach(view)
    overlay.set_polygon(poles); overlay.set_points(marks); overlay.set_highlight([p])
    overlay.detach()
"""
from pivy import coin

from .scene import ViewAttached

POLYGON_COLOR = (0.1, 0.65, 0.2)  # green, as the paper's control points
POLE_COLOR = (0.1, 0.65, 0.2)
MARK_COLOR = (0.0, 0.0, 0.0)
HIGHLIGHT_COLOR = (0.9, 0.1, 0.1)
MOVED_COLOR = (1.0, 0.55, 0.0)


def _vec3(points):
    return [(float(p[0]), float(p[1]), float(p[2])) for p in points]


class _Markers:
    """A set of markers (filled circles of a fixed pixel size) in one colour."""

    def __init__(self, parent, color, marker="CIRCLE_FILLED_9_9"):
        self.root = coin.SoSeparator()
        material = coin.SoBaseColor()
        material.rgb = color
        self.coords = coin.SoCoordinate3()
        self.markers = coin.SoMarkerSet()
        self.markers.markerIndex = getattr(coin.SoMarkerSet, marker)
        self.root.addChild(material)
        self.root.addChild(self.coords)
        self.root.addChild(self.markers)
        parent.addChild(self.root)
        self.set([])  # a new SoCoordinate3 holds one point, (0, 0, 0): no marker until set

    def set(self, points):
        points = _vec3(points)
        self.coords.point.deleteValues(0)
        if points:
            self.coords.point.setValues(0, len(points), points)
        self.markers.numPoints = len(points)


class Overlay(ViewAttached):
    """Control polygon (lines + pole markers), mark markers, highlighted and moved points."""

    def __init__(self, name="FairSplinesOverlay"):
        self.root = coin.SoSeparator()
        self.root.setName(name)
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        self.root.addChild(pick)
        lines = coin.SoSeparator()
        material = coin.SoBaseColor()
        material.rgb = POLYGON_COLOR
        style = coin.SoDrawStyle()
        style.lineWidth = 1.5
        style.linePattern = 0xF0F0
        self.polygon_coords = coin.SoCoordinate3()
        self.polygon_lines = coin.SoLineSet()
        for node in (material, style, self.polygon_coords, self.polygon_lines):
            lines.addChild(node)
        self.root.addChild(lines)
        self.poles = _Markers(self.root, POLE_COLOR)
        self.moved = _Markers(self.root, MOVED_COLOR)
        self.marks = _Markers(self.root, MARK_COLOR)
        self.highlight = _Markers(self.root, HIGHLIGHT_COLOR, "CIRCLE_FILLED_9_9")
        self.views = []

    def set_polygon(self, points):
        points = _vec3(points)
        self.polygon_coords.point.deleteValues(0)
        if points:
            self.polygon_coords.point.setValues(0, len(points), points)
        self.polygon_lines.numVertices.deleteValues(0)
        if points:
            self.polygon_lines.numVertices.setValues(0, 1, [len(points)])
        self.poles.set(points)

    def set_points(self, points):
        self.marks.set(points)

    def set_moved(self, points):
        self.moved.set(points)

    def set_highlight(self, points):
        self.highlight.set(points)

    def polygon_points(self):
        return [tuple(p.getValue()) for p in self.polygon_coords.point]

    def mark_points(self):
        return [tuple(p.getValue()) for p in self.marks.coords.point][: self.marks.markers.numPoints.getValue()]

    def highlight_points(self):
        return [tuple(p.getValue()) for p in self.highlight.coords.point][: self.highlight.markers.numPoints.getValue()]


def active_view(doc):
    """The active 3D view of a document, or None."""
    import FreeCADGui

    gui_doc = FreeCADGui.getDocument(doc.Name) if doc is not None else None
    view = getattr(gui_doc, "ActiveView", None) if gui_doc is not None else None
    return view if view is not None and hasattr(view, "getSceneGraph") else None
