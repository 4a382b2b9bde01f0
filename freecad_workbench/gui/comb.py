"""Curvature comb: teeth along a curve, each as long as the curvature there times a scale,
and the envelope through the teeth's tips.

The geometry (`comb_lines`, `auto_scale`) is headless numpy. The rest draws it with coin
into the 3D views as an annotation beside the object: `toggle` shows or hides combs,
`set_style` changes scale and sample count, and combs follow their object's shape when
it is recomputed. The scale factor and sample count persist as parameters in
User parameter:BaseApp/Preferences/Mod/FairSplines (CombScale, CombSamples).

Direction: for a planar curve a tooth is kappa * (n x t) with signed kappa, plane
normal n and unit tangent t, i.e. the curvature vector, pointing to the centre of
curvature; the comb changes sides where the curvature changes sign. For a space curve it
is kappa times the principal normal. A negative scale draws the comb on the other side.
"""
from collections import namedtuple

import numpy as np

import FreeCAD
import Part

from ..analysis import curvature_profile

Comb = namedtuple("Comb", "base tip kappa s")
Comb.__doc__ = "Comb teeth: base points (n,3) on the curve, tips (n,3), curvature and arc length (n,)."

PARAM_PATH = "User parameter:BaseApp/Preferences/Mod/FairSplines"
DEFAULT_SCALE = 1.0
DEFAULT_SAMPLES = 256
# With scale factor 1 the longest tooth is this fraction of the diagonal of the box
# around the sampled curve points.
AUTO_LENGTH = 0.25

TOOTH_COLOR = (0.35, 0.55, 1.0)
ENVELOPE_COLOR = (0.0, 0.2, 0.85)


def as_bspline(edge):
    """The Part.BSplineCurve of an edge (or curve) over the edge's range, converted the
    way the kernel converts it, so curvature samples and positions share parameters."""
    if isinstance(edge, Part.Shape):
        if len(edge.Edges) != 1:
            raise ValueError(f"expected one edge, got a shape with {len(edge.Edges)} edges")
        edge = edge.Edges[0]
        geom = edge.Curve
        first, last = edge.FirstParameter, edge.LastParameter
        if isinstance(geom, Part.BSplineCurve) and np.isclose(first, geom.FirstParameter) and np.isclose(
            last, geom.LastParameter
        ):
            return geom
        return geom.toBSpline(first, last)
    if isinstance(edge, Part.BSplineCurve):
        return edge
    return edge.toBSpline()


def comb_lines(edge, scale=1.0, n=DEFAULT_SAMPLES):
    """Comb of an edge or curve: tooth i goes from base[i] to tip[i] = base[i] + scale *
    kappa_i * direction_i (see the module docstring); tip is the envelope polyline.
    scale is absolute (length = scale * kappa); see auto_scale for a size-relative one."""
    curve = as_bspline(edge)
    profile = curvature_profile(curve, n)
    base = np.empty((len(profile.u), 3))
    direction = np.zeros((len(profile.u), 3))
    plane_normal = np.asarray(profile.normal, dtype=float)
    for i, u in enumerate(profile.u):
        p, d1, d2 = curve.getD2(float(u))
        base[i] = (p.x, p.y, p.z)
        d1 = np.array((d1.x, d1.y, d1.z))
        speed = np.linalg.norm(d1)
        if speed == 0.0:
            continue
        t = d1 / speed
        if profile.signed:
            direction[i] = np.cross(plane_normal, t)  # in-plane normal n x t
        else:
            d2 = np.array((d2.x, d2.y, d2.z))
            k = d2 - np.dot(d2, t) * t  # curvature vector * speed^2: along the principal normal
            length = np.linalg.norm(k)
            if length > 1e-12 * max(1.0, np.linalg.norm(d2)):
                direction[i] = k / length
    tip = base + (scale * profile.kappa)[:, None] * direction
    return Comb(base, tip, profile.kappa, profile.s)


def auto_scale(edges, n=DEFAULT_SAMPLES):
    """Absolute scale that makes the longest tooth of these edges AUTO_LENGTH of the
    diagonal of their sampled points' bounding box (1.0 if they are straight)."""
    return _auto_scale([comb_lines(edge, 1.0, n) for edge in edges])


def _auto_scale(unit_combs):
    # The box of the samples, not Shape.BoundBox: OCCT tightens that once the shape is
    # tessellated, which would make the comb change size without its curve changing.
    points = np.vstack([c.base for c in unit_combs]) if unit_combs else np.zeros((0, 3))
    kappa_max = max((float(np.max(np.abs(c.kappa))) for c in unit_combs if len(c.kappa)), default=0.0)
    diagonal = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0))) if len(points) else 0.0
    if kappa_max == 0.0 or diagonal == 0.0:
        return 1.0
    return AUTO_LENGTH * diagonal / kappa_max


def scaled(comb, scale):
    """The comb with its teeth multiplied by scale."""
    return Comb(comb.base, comb.base + scale * (comb.tip - comb.base), comb.kappa, comb.s)


def edges_of(obj, sub=""):
    """Edges of a selection entry: the named edge, or every edge of the whole object."""
    if sub:
        shape = Part.getShape(obj, sub, needSubElement=True)
        return [shape] if not shape.isNull() and shape.ShapeType == "Edge" else []
    shape = Part.getShape(obj)
    return [] if shape.isNull() else list(shape.Edges)


def get_style():
    """(scale factor, samples) from the parameters."""
    params = FreeCAD.ParamGet(PARAM_PATH)
    return params.GetFloat("CombScale", DEFAULT_SCALE), params.GetInt("CombSamples", DEFAULT_SAMPLES)


# --- coin: the combs shown in the 3D views -------------------------------------------

_combs = {}  # (document name, object name, subname) -> _CombNode
_observer = None


class _CombNode:
    """One comb annotation: a coin separator added to every 3D view of the document."""

    def __init__(self, key):
        from pivy import coin

        self.key = key
        self.root = coin.SoSeparator()
        self.root.setName("FairSplinesComb")
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        self.coords = coin.SoCoordinate3()
        self.root.addChild(pick)
        self.root.addChild(self.coords)
        self.teeth = self._lines(coin, TOOTH_COLOR, 1.0)
        self.envelope = self._lines(coin, ENVELOPE_COLOR, 2.0)
        self.views = []

    def _lines(self, coin, color, width):
        group = coin.SoSeparator()
        material = coin.SoBaseColor()
        material.rgb = color
        style = coin.SoDrawStyle()
        style.lineWidth = width
        lines = coin.SoIndexedLineSet()
        for node in (material, style, lines):
            group.addChild(node)
        self.root.addChild(group)
        return lines

    def update(self, combs):
        """Draw these Comb tuples (one per edge)."""
        points, teeth, envelope = [], [], []
        offset = 0
        for comb in combs:
            n = len(comb.base)
            points.append(comb.base)
            points.append(comb.tip)
            for i in range(n):
                teeth += [offset + i, offset + n + i, -1]
            envelope += list(range(offset + n, offset + 2 * n)) + [-1]
            offset += 2 * n
        data = np.vstack(points).tolist() if points else []
        self.coords.point.deleteValues(0)
        if data:
            self.coords.point.setValues(0, len(data), data)
        self.teeth.coordIndex.deleteValues(0)
        self.envelope.coordIndex.deleteValues(0)
        if teeth:
            self.teeth.coordIndex.setValues(0, len(teeth), teeth)
            self.envelope.coordIndex.setValues(0, len(envelope), envelope)

    def attach(self, views):
        for view in views:
            view.getSceneGraph().addChild(self.root)
            self.views.append(view)

    def detach(self):
        for view in self.views:
            try:
                view.getSceneGraph().removeChild(self.root)
            except Exception:  # the view was closed
                pass
        self.views = []


def _views(doc):
    import FreeCADGui

    gui_doc = FreeCADGui.getDocument(doc.Name)
    if gui_doc is None:
        return []
    return list(gui_doc.mdiViewsOfType("Gui::View3DInventor"))


def _key(obj, sub=""):
    return (obj.Document.Name, obj.Name, sub)


def _object(key):
    doc = FreeCAD.listDocuments().get(key[0])
    return doc.getObject(key[1]) if doc is not None else None


def _compute(key):
    obj = _object(key)
    edges = edges_of(obj, key[2]) if obj is not None else []
    if not edges:
        return []
    factor, samples = get_style()
    unit = [comb_lines(edge, 1.0, samples) for edge in edges]
    scale = factor * _auto_scale(unit)
    return [scaled(c, scale) for c in unit]


def shown():
    """Keys (document name, object name, subname) of the combs shown."""
    return list(_combs)


def is_shown(obj, sub=""):
    return _key(obj, sub) in _combs


def show(obj, sub=""):
    """Show the comb of an object's edge (sub 'EdgeN') or of all its edges (sub '')."""
    key = _key(obj, sub)
    if key in _combs:
        return _combs[key]
    _install_observer()
    node = _CombNode(key)
    node.update(_compute(key))
    node.attach(_views(obj.Document))
    _combs[key] = node
    return node


def hide(obj=None, sub=""):
    """Hide one comb, or every comb when obj is None."""
    keys = list(_combs) if obj is None else [_key(obj, sub)]
    for key in keys:
        node = _combs.pop(key, None)
        if node is not None:
            node.detach()


def toggle(links):
    """Run-again-to-hide: if any of these (obj, sub) combs is hidden, show them all;
    else hide them. With no links, hide every comb. Returns True if combs were shown."""
    links = [(obj, sub) for obj, sub in links]
    if not links:
        hide()
        return False
    if all(is_shown(obj, sub) for obj, sub in links):
        for obj, sub in links:
            hide(obj, sub)
        return False
    for obj, sub in links:
        show(obj, sub)
    return True


def set_style(scale=None, samples=None):
    """Store a new scale factor and/or sample count and redraw every comb."""
    params = FreeCAD.ParamGet(PARAM_PATH)
    if scale is not None:
        params.SetFloat("CombScale", float(scale))
    if samples is not None:
        params.SetInt("CombSamples", max(8, int(samples)))
    refresh()


def refresh(keys=None):
    """Recompute combs (all, or the given keys) from their objects' current shapes."""
    for key in list(_combs) if keys is None else keys:
        node = _combs.get(key)
        if node is not None:
            try:
                node.update(_compute(key))
            except Exception as exc:  # a broken shape must not break the recompute
                FreeCAD.Console.PrintWarning(f"Curvature comb of {key[1]}: {exc}\n")
                node.update([])


class _Observer:
    """Redraws combs when their object's shape changes; drops them with the object."""

    def slotChangedObject(self, obj, prop):
        if prop == "Shape" and _combs:
            refresh([key for key in _combs if key[0] == obj.Document.Name and key[1] == obj.Name])

    def slotDeletedObject(self, obj):
        for key in [k for k in _combs if k[0] == obj.Document.Name and k[1] == obj.Name]:
            _combs.pop(key).detach()

    def slotDeletedDocument(self, doc):
        for key in [k for k in _combs if k[0] == doc.Name]:
            _combs.pop(key).views = []


def _install_observer():
    global _observer
    if _observer is None:
        _observer = _Observer()
        FreeCAD.addDocumentObserver(_observer)
