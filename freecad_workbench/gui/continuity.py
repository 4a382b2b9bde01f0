"""Continuity check (issue 27): the edges of a shape, or of a set of touching faces, drawn
in the colour of their verdict (gap, G0, G1, G2, boundary) over the object, with the worst
point of one edge marked. The verdicts are fw.edge_continuity's; the table of the task
panel (panels/continuity.py) lists the same records.

    check = show([(obj, "")], angle_tolerance=0.1)   # a Check: .records, .links, .node
    check.mark(i)                                     # mark record i's worst point
    hide()

GUI only (pivy); the records come from the macro API.
"""
import numpy as np

import FreeCAD

from .scene import ViewAttached

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

# verdict: (colour, the legend's words)
VERDICTS = {
    "gap": ((0.85, 0.0, 0.0), QT_TRANSLATE_NOOP("FairSplines", "Gap")),
    "G0": ((1.0, 0.55, 0.0), QT_TRANSLATE_NOOP("FairSplines", "G0: kink")),
    "G1": ((0.95, 0.85, 0.0), QT_TRANSLATE_NOOP("FairSplines", "G1: tangent")),
    "G2": ((0.0, 0.7, 0.1), QT_TRANSLATE_NOOP("FairSplines", "G2: curvature")),
    "boundary": ((0.2, 0.35, 0.95), QT_TRANSLATE_NOOP("FairSplines", "Boundary")),
}
# Free, degenerate (a collapsed side) and non-manifold edges.
OTHER = ((0.6, 0.0, 0.6), QT_TRANSLATE_NOOP("FairSplines", "Not judged"))
MARK_COLOUR = (0.9, 0.0, 0.9)
LINE_WIDTH = 4.0
SAMPLES = 48  # points a drawn edge, at least


def colour_of(verdict):
    return VERDICTS.get(verdict, OTHER)[0]


def worst_point(record):
    """The point that decided the verdict: the gap's, the angle's or the curvature jump's."""
    if record.continuity == "gap":
        return record.gap_point
    if record.continuity == "G0":
        return record.angle_point
    return record.curvature_point


def _element(sub):
    return sub.rsplit(".", 1)[-1] if sub else ""


def checked_shape(links):
    """(shape in global coordinates, object, {record edge name: object's edge name}) of
    selection-style links: one whole object, or faces of one object. Faces of several objects
    (a blend and the faces it joins) make one shell (Part.Shell shares their coincident edges),
    so that the edges where they meet are judged; object is None then (the shell's edges are
    nobody's)."""
    import Part

    obj = links[0][0]
    if any(o is not obj for o, _ in links):
        faces = [Part.getShape(o).getElement(_element(sub)) if _element(sub) else Part.getShape(o)
                 for o, sub in links]
        return Part.Shell([f for shape in faces for f in shape.Faces]), None, {}
    whole = Part.getShape(obj)
    faces = sorted({_element(sub) for o, sub in links if o is obj and _element(sub).startswith("Face")})
    if not faces or any(not _element(sub) for o, sub in links if o is obj):
        return whole, obj, {f"Edge{i + 1}": f"Edge{i + 1}" for i in range(len(whole.Edges))}
    shape = Part.Compound([whole.getElement(name) for name in faces])
    names = {}
    for i, edge in enumerate(shape.Edges):
        for j, own in enumerate(whole.Edges):
            if edge.isSame(own):
                names[f"Edge{i + 1}"] = f"Edge{j + 1}"
                break
    return shape, obj, names


class Check:
    """The records of one check and their drawing."""

    def __init__(self, links, **tolerances):
        import freecad_workbench as fw

        self.links = list(links)
        self.tolerances = tolerances
        self.shape, self.obj, self.names = checked_shape(self.links)
        self.records = fw.edge_continuity(self.shape, **tolerances)
        self.node = _Node()
        self.node.draw(self.shape, self.records)
        self.marked = None

    def object_edge(self, i):
        """The object's own name of record i's edge ('Edge7')."""
        return self.names.get(self.records[i].edge, self.records[i].edge)

    def mark(self, i):
        """Mark record i's worst point (None: no mark) and select its edge in FreeCAD."""
        import FreeCADGui

        self.marked = i
        if i is None:
            self.node.set_mark(None)
            return
        self.node.set_mark(worst_point(self.records[i]))
        if self.obj is None:
            return  # a sewn shell of several objects' faces: its edges are nobody's to select
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(self.obj, self.object_edge(i))


class _Node(ViewAttached):
    def __init__(self):
        from pivy import coin

        self.coin = coin
        self.root = coin.SoSeparator()
        self.root.setName("FairSplinesContinuity")
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        light = coin.SoLightModel()
        light.model = coin.SoLightModel.BASE_COLOR
        style = coin.SoDrawStyle()
        style.lineWidth = LINE_WIDTH
        style.pointSize = 11
        self.material = coin.SoMaterial()
        binding = coin.SoMaterialBinding()
        binding.value = coin.SoMaterialBinding.PER_FACE  # for a SoLineSet: one colour a polyline (PER_PART: a segment)
        self.coords = coin.SoCoordinate3()
        self.lines = coin.SoLineSet()
        mark = coin.SoSeparator()
        mark_colour = coin.SoBaseColor()
        mark_colour.rgb = MARK_COLOUR
        self.mark_coords = coin.SoCoordinate3()
        self.marker = coin.SoMarkerSet()
        self.marker.markerIndex = coin.SoMarkerSet.CIRCLE_FILLED_9_9
        for node in (mark_colour, self.mark_coords, self.marker):
            mark.addChild(node)
        # drawn over the object's own edges: a depth offset would still hide parts of them
        depth = coin.SoDepthBuffer() if hasattr(coin, "SoDepthBuffer") else None
        children = [pick, light, style]
        if depth is not None:
            depth.function = coin.SoDepthBuffer.LEQUAL
            children.append(depth)
        for node in children + [self.material, binding, self.coords, self.lines, mark]:
            self.root.addChild(node)
        self.set_mark(None)
        self.legend_texts = self._legend(coin)
        self.views = []

    def _legend(self, coin):
        """The verdicts' colours and words at the lower left of the view (its own camera)."""
        legend = coin.SoAnnotation()
        camera = coin.SoOrthographicCamera()
        camera.viewportMapping = coin.SoCamera.LEAVE_ALONE
        camera.position = (0.0, 0.0, 5.0)
        camera.height = 2.0
        legend.addChild(camera)
        font = coin.SoFont()
        font.size = 14
        legend.addChild(font)
        texts = []
        for k, (colour, words) in enumerate(list(VERDICTS.values())):
            y = -0.9 + 0.08 * (len(VERDICTS) - 1 - k)
            item = coin.SoSeparator()
            base = coin.SoBaseColor()
            base.rgb = colour
            coords = coin.SoCoordinate3()
            coords.point.setValues(0, 2, [(-0.96, y, 0.0), (-0.91, y, 0.0)])
            line = coin.SoLineSet()
            text_colour = coin.SoBaseColor()
            text_colour.rgb = (0.05, 0.05, 0.05)
            move = coin.SoTranslation()
            move.translation = (-0.895, y - 0.015, 0.0)
            text = coin.SoText2()
            text.string = translate("FairSplines", words)
            for node in (base, coords, line, text_colour, move, text):
                item.addChild(node)
            legend.addChild(item)
            texts.append(text)
        self.root.addChild(legend)
        return texts

    def draw(self, shape, records):
        points, counts, colours = [], [], []
        for record in records:
            edge = shape.Edges[int(record.edge[4:]) - 1]
            try:
                polyline = edge.discretize(Deflection=max(edge.Length, 1e-9) * 1e-3)
                if len(polyline) < SAMPLES:
                    polyline = edge.discretize(SAMPLES)
            except Exception:  # a degenerate edge (a sphere's pole): its ends, so rows and parts still match
                polyline = [v.Point for v in edge.Vertexes] or [FreeCAD.Vector()]
                polyline = (polyline * 2)[:2]
            points.extend((p.x, p.y, p.z) for p in polyline)
            counts.append(len(polyline))
            colours.append(colour_of(record.continuity))
        self.coords.point.deleteValues(0)
        self.lines.numVertices.deleteValues(0)
        self.material.diffuseColor.deleteValues(0)
        if points:
            self.coords.point.setValues(0, len(points), points)
            self.lines.numVertices.setValues(0, len(counts), counts)
            self.material.diffuseColor.setValues(0, len(colours), colours)
        self.drawn = [r for r in records]

    def edge_colours(self):
        """[(first point, colour)] per drawn edge, as the coin nodes hold them."""
        counts = list(self.lines.numVertices.getValues())
        points = [tuple(p.getValue()) for p in self.coords.point]
        colours = [tuple(c.getValue()) for c in self.material.diffuseColor]
        starts = np.cumsum([0] + counts[:-1])
        return [(np.array(points[s:s + n]), colours[k]) for k, (s, n) in enumerate(zip(starts, counts))]

    def set_mark(self, point):
        self.mark_coords.point.deleteValues(0)
        if point is None:
            self.marker.numPoints = 0
            return
        self.mark_coords.point.setValues(0, 1, [(point.x, point.y, point.z)])
        self.marker.numPoints = 1

    def mark_points(self):
        n = self.marker.numPoints.getValue()
        return [tuple(p.getValue()) for p in self.mark_coords.point][:n]


_checks = []


def current():
    return _checks[-1] if _checks else None


def show(links, gap_tolerance=None, angle_tolerance=None, curvature_tolerance=None):
    """Check the edges of selection-style links [(obj, sub)] (one object: the whole or some
    of its faces; or faces of several objects, one shell) and draw them; replaces the check shown
    before. Returns the Check."""
    import freecad_workbench as fw

    from .overlay import active_view

    hide()
    links = [(obj, sub) for obj, sub in links if getattr(obj, "Shape", None) is not None]
    if not links:
        return None
    tolerances = {"gap_tolerance": gap_tolerance,
                  "angle_tolerance": fw.surface_analysis.ANGLE_TOLERANCE if angle_tolerance is None
                  else angle_tolerance,
                  "curvature_tolerance": fw.surface_analysis.CURVATURE_TOLERANCE if curvature_tolerance is None
                  else curvature_tolerance}
    check = Check(links, **tolerances)
    check.node.attach(active_view(links[0][0].Document))
    _checks.append(check)
    return check


def hide():
    while _checks:
        _checks.pop().node.detach()
