"""Curvature comb: teeth along a curve, each as long as the curvature there times a scale,
and the envelope through the teeth's tips.

The geometry (`comb_lines`, `auto_scale`) is headless numpy. The rest draws it with coin
into the 3D views as an annotation beside the object: `toggle` shows or hides combs,
`set_style` changes scale, sample count and the common scale, and combs follow their
object's shape when it is recomputed. Scale factor, sample count and common scale are
the preferences CombScale, CombSamples and CombCommonScale (freecad_workbench/preferences.py).

Direction: for a planar curve a tooth is kappa * (n x t) with signed kappa, plane
normal n and unit tangent t, i.e. the curvature vector, pointing to the centre of
curvature; the comb changes sides where the curvature changes sign. For a space curve it
is kappa times the principal normal. A negative scale draws the comb on the other side.

Torsion (preference CombTorsion, off by default). A space curve also gets a second comb,
in orange: tooth i is tau_i * b_i times a scale, with torsion tau = det(c', c'', c''') /
|c' x c''|^2 and binormal b = c' x c'' / |c' x c''|, both from OCCT's derivatives of the
curve. Its teeth change sides where the torsion changes sign, so a designer sees a torsion
flip. Its automatic scale makes the longest tooth AUTO_LENGTH of the box's diagonal (there
is no centre to stay short of), times the same scale factor. Planar curves (tau = 0) and
straight stretches (no binormal) get no torsion teeth.

Scale. A comb's automatic scale (`auto_scale`) is the largest that satisfies two rules:
the longest tooth is at most AUTO_LENGTH (a quarter) of the diagonal of the box around
the sampled curve points, and every tooth ends short of its centre of curvature. Tooth i
is scale * |kappa_i| long and its centre of curvature lies 1 / |kappa_i| away, so the
second rule is scale * |kappa_i| <= REACH / |kappa_i|, i.e. scale <= REACH / max kappa_i^2:
with REACH = 0.9 no tooth goes more than 90% of the way to its centre, and teeth of an
arc do not cross. The scale drawn is the scale factor (CombScale, default 1) times the
automatic scale; a factor above 1 is the user's choice to reach past the centres.
With CombCommonScale on, every comb of a document is drawn to one absolute scale, the
factor times the smallest automatic scale of its visible combs (straight ones aside), so
tooth lengths compare between curves and still no tooth reaches its centre at factor 1.

Visibility. A comb hides with its object: the comb's SoSwitch is off while the object's
ViewObject.Visibility is False (the comb stays in `shown()`), and on again when it is
shown. Hidden combs do not count for the common scale.

Saved with the document. The comb of a whole object (subname '') is the view property
CurvatureComb (group FairSplines) of the object's view object, added the first time a
comb of the object is shown, for any object with edges: sketches, Part features,
FairSplines features. Setting it in the property editor shows or hides that comb, `show`,
`hide` and `toggle` (the toolbar command) set it, and a document opened with it True
shows the comb again. Combs of single edges (subname 'EdgeN') are for the session only:
they are not saved.

Observers (an App and a GUI document observer) are installed by `install`, the first
time a comb is shown or when the workbench creates its comb command, never on import.
A document opened before that (in another workbench) gets its saved combs drawn when
`install` runs.
"""
from collections import namedtuple
import math

import numpy as np

import FreeCAD
import Part

from .. import preferences
from ..analysis import curvature_profile
from .scene import set_values

translate = FreeCAD.Qt.translate

Comb = namedtuple("Comb", "base tip kappa s")
Comb.__doc__ = "Comb teeth: base points (n,3) on the curve, tips (n,3), curvature and arc length (n,)."

PARAM_PATH = preferences.PARAM_PATH
DEFAULT_SCALE = preferences.default("CombScale")
DEFAULT_SAMPLES = preferences.default("CombSamples")
# With scale factor 1 the longest tooth is at most this fraction of the diagonal of the
# box around the sampled curve points...
AUTO_LENGTH = 0.25
# ...and every tooth at most this fraction of its radius of curvature (module docstring).
REACH = 0.9

# The view property of a whole object's comb, saved with the document.
PROPERTY = "CurvatureComb"
PROPERTY_GROUP = "FairSplines"

TOOTH_COLOR = (0.35, 0.55, 1.0)
ENVELOPE_COLOR = (0.0, 0.2, 0.85)
TORSION_TOOTH_COLOR = (1.0, 0.6, 0.2)
TORSION_ENVELOPE_COLOR = (0.85, 0.35, 0.0)


def torsion_tooltip():
    """The tooltip of the torsion switch (the comb panel and the preferences page)."""
    return translate(
        "FairSplines",
        "Space curves also get a comb of their torsion, in orange, along the binormal. Its teeth change "
        "sides where the curve's twist changes direction (a torsion sign change). Planar curves have none.")


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


def torsion_lines(edge, scale=1.0, n=DEFAULT_SAMPLES):
    """Torsion comb of an edge or curve (module docstring): tooth i goes from base[i] to
    tip[i] = base[i] + scale * tau_i * b_i; Comb.kappa holds tau. Empty for a planar curve."""
    curve = as_bspline(edge)
    profile = curvature_profile(curve, n)
    if profile.signed:  # planar: tau = 0 everywhere
        return Comb(np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0), np.zeros(0))
    base = np.empty((len(profile.u), 3))
    binormal = np.zeros((len(profile.u), 3))
    tau = np.zeros(len(profile.u))
    for i, u in enumerate(profile.u):
        p, d1, d2 = curve.getD2(float(u))
        d3 = curve.getDN(float(u), 3)
        base[i] = (p.x, p.y, p.z)
        d1, d2, d3 = (np.array((v.x, v.y, v.z)) for v in (d1, d2, d3))
        cross = np.cross(d1, d2)
        area = float(np.dot(cross, cross))
        # |c' x c''| against its size scale |c'| |c''|: below 1e-9 the curve is straight there.
        if area == 0.0 or area <= (1e-9 * np.linalg.norm(d1) * np.linalg.norm(d2)) ** 2:
            continue
        tau[i] = float(np.dot(cross, d3)) / area
        binormal[i] = cross / math.sqrt(area)
    tip = base + (scale * tau)[:, None] * binormal
    return Comb(base, tip, tau, profile.s)


def _torsion_automatic(unit_combs, diagonal):
    """Scale of torsion combs drawn at scale 1: the longest tooth AUTO_LENGTH of the
    diagonal; inf when there is no torsion."""
    tau_max = max((float(np.max(np.abs(c.kappa))) for c in unit_combs if len(c.kappa)), default=0.0)
    return AUTO_LENGTH * diagonal / tau_max if tau_max > 0.0 and diagonal > 0.0 else math.inf


def auto_scale(edges, n=DEFAULT_SAMPLES):
    """Absolute scale for a comb of these edges: the largest that keeps the longest tooth
    within AUTO_LENGTH of the diagonal of their sampled points' bounding box and every
    tooth within REACH of the way to its centre of curvature (1.0 if they are straight)."""
    scale = _automatic([comb_lines(edge, 1.0, n) for edge in edges])
    return 1.0 if math.isinf(scale) else scale


def _automatic(unit_combs):
    """auto_scale of combs drawn at scale 1; inf when there is no curvature to scale."""
    kappa_max = max((float(np.max(np.abs(c.kappa))) for c in unit_combs if len(c.kappa)), default=0.0)
    diagonal = _diagonal(unit_combs)
    if kappa_max == 0.0 or diagonal == 0.0:
        return math.inf
    # Longest tooth kappa_max * scale <= AUTO_LENGTH * diagonal, and for every tooth
    # |kappa_i| * scale <= REACH / |kappa_i| (its radius of curvature), the tightest at kappa_max.
    return min(AUTO_LENGTH * diagonal / kappa_max, REACH / kappa_max**2)


def _diagonal(unit_combs):
    """Diagonal of the box around the combs' base points."""
    # The box of the samples, not Shape.BoundBox: OCCT tightens that once the shape is
    # tessellated, which would make the comb change size without its curve changing.
    points = np.vstack([c.base for c in unit_combs]) if unit_combs else np.zeros((0, 3))
    return float(np.linalg.norm(points.max(axis=0) - points.min(axis=0))) if len(points) else 0.0


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
    """(scale factor, samples) from the preferences (freecad_workbench/preferences.py)."""
    return preferences.get("CombScale"), preferences.get("CombSamples")


def torsion_shown():
    """Whether space curves get a torsion comb too (preference CombTorsion)."""
    return preferences.get("CombTorsion")


def common_scale():
    """Whether every comb is drawn to one scale (preference CombCommonScale)."""
    return preferences.get("CombCommonScale")


# --- coin: the combs shown in the 3D views -------------------------------------------

_combs = {}  # (document name, object name, subname) -> _CombNode
_observers = None  # (App observer, GUI observer) once installed
_pending = set()  # (document name, object name): saved combs to show once the document has loaded
_flush_scheduled = False


class _CombNode:
    """One comb annotation: a coin switch (on while its object is visible) holding a
    separator, added to every 3D view of the document."""

    def __init__(self, key):
        from pivy import coin

        self.key = key
        self.root = coin.SoSwitch()
        self.root.setName("FairSplinesComb")
        self.group = coin.SoSeparator()
        self.root.addChild(self.group)
        self.root.whichChild = 0
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        self.coords = coin.SoCoordinate3()
        self.group.addChild(pick)
        self.group.addChild(self.coords)
        self.teeth = self._lines(coin, TOOTH_COLOR, 1.0)
        self.envelope = self._lines(coin, ENVELOPE_COLOR, 2.0)
        self.torsion_teeth = self._lines(coin, TORSION_TOOTH_COLOR, 1.0)
        self.torsion_envelope = self._lines(coin, TORSION_ENVELOPE_COLOR, 2.0)
        self.views = []
        self.unit = []  # the Comb of each edge at scale 1
        self.automatic = math.inf  # _automatic(self.unit)
        self.torsion_unit = []  # the torsion Comb of each edge at scale 1 (none while CombTorsion is off)
        self.torsion_automatic = math.inf  # _torsion_automatic(self.torsion_unit, ...)

    def _lines(self, coin, color, width):
        group = coin.SoSeparator()
        material = coin.SoBaseColor()
        material.rgb = color
        style = coin.SoDrawStyle()
        style.lineWidth = width
        lines = coin.SoIndexedLineSet()
        for node in (material, style, lines):
            group.addChild(node)
        self.group.addChild(group)
        return lines

    @property
    def visible(self):
        return self.root.whichChild.getValue() == 0

    def set_visible(self, visible):
        from pivy import coin

        value = 0 if visible else coin.SO_SWITCH_NONE
        if self.root.whichChild.getValue() != value:
            self.root.whichChild = value

    def update(self, combs, torsion_combs=()):
        """Draw these Comb tuples (one per edge), and the torsion combs."""
        points = []
        offset = 0
        for lines, envelope_lines, group in ((self.teeth, self.envelope, combs),
                                             (self.torsion_teeth, self.torsion_envelope, torsion_combs)):
            teeth, envelope = [], []
            for comb in group:
                n = len(comb.base)
                if n == 0:
                    continue
                points.append(comb.base)
                points.append(comb.tip)
                for i in range(n):
                    teeth += [offset + i, offset + n + i, -1]
                envelope += list(range(offset + n, offset + 2 * n)) + [-1]
                offset += 2 * n
            lines.coordIndex.deleteValues(0)
            envelope_lines.coordIndex.deleteValues(0)
            if teeth:
                lines.coordIndex.setValues(0, len(teeth), teeth)
                envelope_lines.coordIndex.setValues(0, len(envelope), envelope)
        set_values(self.coords.point, np.vstack(points) if points else np.zeros((0, 3)))

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


def _keys_of(obj):
    return [key for key in _combs if key[0] == obj.Document.Name and key[1] == obj.Name]


def _visible(obj):
    vobj = getattr(obj, "ViewObject", None)
    if vobj is not None:
        return bool(vobj.Visibility)
    return bool(getattr(obj, "Visibility", True))


def _unit(key):
    """The curvature and torsion combs (the latter empty while CombTorsion is off) at
    scale 1 of the edges of a key's object (or of its one edge)."""
    obj = _object(key)
    edges = edges_of(obj, key[2]) if obj is not None else []
    samples = get_style()[1]
    torsion = [torsion_lines(edge, 1.0, samples) for edge in edges] if torsion_shown() else []
    return [comb_lines(edge, 1.0, samples) for edge in edges], torsion


def _common_automatic(doc_name):
    """The smallest automatic scale of the visible combs of a document (inf if all are
    straight)."""
    return min((node.automatic for key, node in _combs.items() if key[0] == doc_name and node.visible),
               default=math.inf)


def _draw(keys=None):
    """Redraw combs from their stored unit combs: the given keys, or all (always all
    with the common scale, since one comb changes everyone's scale)."""
    factor = get_style()[0]
    common = {key[0]: None for key in _combs}
    if common_scale():
        common = {name: _common_automatic(name) for name in common}
        keys = None
    for key in list(_combs) if keys is None else keys:
        node = _combs.get(key)
        if node is None:
            continue
        automatic = common[key[0]]
        if automatic is None or math.isinf(automatic):
            automatic = node.automatic
        if math.isinf(automatic):  # straight: nothing to scale
            automatic = 1.0
        twist = 1.0 if math.isinf(node.torsion_automatic) else node.torsion_automatic
        node.update([scaled(c, factor * automatic) for c in node.unit],
                    [scaled(c, factor * twist) for c in node.torsion_unit])


def shown():
    """Keys (document name, object name, subname) of the combs shown (combs of hidden
    objects too: they come back with their object)."""
    return list(_combs)


def is_shown(obj, sub=""):
    return _key(obj, sub) in _combs


def is_drawn(obj, sub=""):
    """Whether the comb is shown and its object visible, i.e. whether it is drawn."""
    node = _combs.get(_key(obj, sub))
    return node is not None and node.visible


def show(obj, sub=""):
    """Show the comb of an object's edge (sub 'EdgeN') or of all its edges (sub ''; this
    sets the object's CurvatureComb view property, saved with the document)."""
    key = _key(obj, sub)
    node = _combs.get(key)
    if node is None:
        install()
        node = _CombNode(key)
        _combs[key] = node
        _recompute(node)
        node.set_visible(_visible(obj))
        node.attach(_views(obj.Document))
        _draw([key])
    _set_property(obj, True if not sub else None)
    return node


def hide(obj=None, sub=""):
    """Hide one comb, or every comb when obj is None. Hiding the comb of a whole object
    clears its CurvatureComb view property."""
    keys = list(_combs) if obj is None else [_key(obj, sub)]
    for key in keys:
        node = _combs.pop(key, None)
        if node is not None:
            node.detach()
        if not key[2]:
            target = obj if obj is not None else _object(key)
            if target is not None:
                _set_property(target, False, add=False)
    if common_scale():
        _draw()


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


def set_style(scale=None, samples=None, common=None, torsion=None):
    """Store a new scale factor, sample count, common scale (bool) and/or torsion comb
    (bool) and redraw every comb."""
    if scale is not None:
        preferences.set_value("CombScale", float(scale))
    if samples is not None:
        preferences.set_value("CombSamples", int(samples))
    if common is not None:
        preferences.set_value("CombCommonScale", bool(common))
    if torsion is not None:
        preferences.set_value("CombTorsion", bool(torsion))
    refresh()


def _recompute(node):
    try:
        node.unit, node.torsion_unit = _unit(node.key)
    except Exception as exc:  # a broken shape must not break the recompute
        FreeCAD.Console.PrintWarning(f"Curvature comb of {node.key[1]}: {exc}\n")
        node.unit, node.torsion_unit = [], []
    node.automatic = _automatic(node.unit)
    node.torsion_automatic = _torsion_automatic(node.torsion_unit, _diagonal(node.unit))


def refresh(keys=None):
    """Recompute combs (all, or the given keys) from their objects' current shapes."""
    keys = list(_combs) if keys is None else [key for key in keys if key in _combs]
    for key in keys:
        _recompute(_combs[key])
    _draw(keys)


def _set_property(obj, value, add=True):
    """Set obj's CurvatureComb view property to value (None: leave it), adding it first
    when add is true. Nothing without a GUI view object."""
    vobj = getattr(obj, "ViewObject", None)
    if vobj is None:
        return
    if PROPERTY not in vobj.PropertiesList:
        if not add:
            return
        vobj.addProperty("App::PropertyBool", PROPERTY, PROPERTY_GROUP,
                         translate("FairSplines", "Show the curvature comb of this object's edges"))
    if value is not None and bool(getattr(vobj, PROPERTY)) != value:  # unchanged: no signal, no loop
        setattr(vobj, PROPERTY, value)


def _saved_on(obj):
    vobj = getattr(obj, "ViewObject", None)
    return vobj is not None and PROPERTY in vobj.PropertiesList and bool(getattr(vobj, PROPERTY))


def _show_saved(doc):
    """Show the combs a document was saved with (CurvatureComb True)."""
    for obj in doc.Objects:
        if _saved_on(obj) and not is_shown(obj):
            show(obj)


def _flush_pending():
    """Show the saved combs of documents that have finished loading."""
    global _flush_scheduled
    _flush_scheduled = False
    for doc_name, name in list(_pending):
        doc = FreeCAD.listDocuments().get(doc_name)
        if doc is not None and doc.Restoring:
            continue
        _pending.discard((doc_name, name))
        obj = doc.getObject(name) if doc is not None else None
        if obj is not None and _saved_on(obj) and not is_shown(obj):
            try:
                show(obj)
            except Exception as exc:
                FreeCAD.Console.PrintWarning(f"Curvature comb of {name}: {exc}\n")


def _schedule_flush():
    """Flush once the event loop runs, for a document that loads without being activated."""
    global _flush_scheduled
    if _flush_scheduled:
        return
    _flush_scheduled = True
    try:
        from .qt import QtCore

        QtCore.QTimer.singleShot(0, _flush_pending)
    except Exception:
        _flush_scheduled = False


class _Observer:
    """App document observer: redraws combs when their object's shape changes, hides
    them with it, drops them with the object or document, and draws saved combs once a
    document has loaded."""

    def slotChangedObject(self, obj, prop):
        if not _combs or prop not in ("Shape", "Visibility"):
            return
        keys = _keys_of(obj)
        if not keys:
            return
        if prop == "Shape":
            refresh(keys)
            return
        visible = _visible(obj)
        changed = [key for key in keys if _combs[key].visible != visible]
        for key in changed:
            _combs[key].set_visible(visible)
        if changed and common_scale():
            _draw()

    def slotDeletedObject(self, obj):
        for key in _keys_of(obj):
            _combs.pop(key).detach()
        _pending.discard((obj.Document.Name, obj.Name))

    def slotDeletedDocument(self, doc):
        for key in [k for k in _combs if k[0] == doc.Name]:
            _combs.pop(key).views = []
        for item in [p for p in _pending if p[0] == doc.Name]:
            _pending.discard(item)

    def slotActivateDocument(self, doc):  # FreeCAD 0.20: the first signal after a document loaded
        if _pending:
            _flush_pending()

    def slotFinishRestoreDocument(self, doc):  # FreeCAD 0.21 and later
        if _pending:
            _flush_pending()


class _GuiObserver:
    """GUI document observer: the CurvatureComb view property shows and hides the comb."""

    def slotChangedObject(self, vobj, prop):
        # Test prop before touching vobj: GUI signals also come from view providers
        # still being built, whose .Object is not set yet.
        if prop != PROPERTY:
            return
        obj = vobj.Object
        if obj.Document.Restoring:  # loading: show once the whole document is there
            if getattr(vobj, PROPERTY):
                _pending.add((obj.Document.Name, obj.Name))
                _schedule_flush()
            return
        if getattr(vobj, PROPERTY):
            show(obj)
        elif is_shown(obj):
            hide(obj)


def install():
    """Install the document observers (once) and draw the saved combs of the documents
    open already. show() calls it; so does the workbench when it creates its comb command."""
    global _observers
    if _observers is not None:
        return
    import FreeCADGui

    _observers = (_Observer(), _GuiObserver())
    FreeCAD.addDocumentObserver(_observers[0])
    FreeCADGui.addDocumentObserver(_observers[1])
    for doc in list(FreeCAD.listDocuments().values()):
        if not doc.Restoring:
            _show_saved(doc)
