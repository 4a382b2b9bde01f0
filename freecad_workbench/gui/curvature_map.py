"""Curvature map (issue 27): any shape's faces coloured by a curvature quantity, drawn as a
coin overlay over the object, with a legend (a colour bar with values and units) in the 3D
view. An analysis is a view on the object, not a new object: it turns on and off without
changing the document, and follows the object when it recomputes.

    show([(obj, ""), (obj, "Face3")], quantity="mean")   # map the whole object or some faces
    set_range(obj, lower, upper)  /  set_range(obj)       # manual range / automatic range
    hide(obj)  /  hide()                                  # off for one object / for all

The triangulation and the values come from `fw.curvature_map` (exact evaluation on the
faces). Recolouring after a range or colour change sets the colours only (`recolour`), it
does not re-mesh. While a map is shown its object is drawn as wireframe (edges only) under
the coloured faces, and its display mode comes back when the map is turned off. Faces of the
object not asked for are drawn grey.

`colours` and `auto_range` are headless numpy; the rest needs pivy and FreeCADGui.
"""
import numpy as np

import FreeCAD

from .scene import ViewAttached, event_position, restore_display_mode, set_values

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

# quantity: (designer's words, unit); the kernel's names are fw.QUANTITIES.
QUANTITY_TEXT = {
    "gaussian": (QT_TRANSLATE_NOOP("FairSplines", "Gaussian curvature"), "1/mm\u00b2"),
    "mean": (QT_TRANSLATE_NOOP("FairSplines", "Mean curvature"), "1/mm"),
    "max_abs": (QT_TRANSLATE_NOOP("FairSplines", "Largest |curvature|"), "1/mm"),
    "min": (QT_TRANSLATE_NOOP("FairSplines", "Minimum curvature"), "1/mm"),
    "max": (QT_TRANSLATE_NOOP("FairSplines", "Maximum curvature"), "1/mm"),
    "radius": (QT_TRANSLATE_NOOP("FairSplines", "Radius of curvature"), "mm"),
}
QUANTITIES = tuple(QUANTITY_TEXT)
# Colour stops from the lower end of the range to the upper: blue, cyan, green, yellow, red
# (Rhino's and Alias's false colours).
STOPS = np.array([(0.0, 0.0, 1.0), (0.0, 1.0, 1.0), (0.0, 0.8, 0.0), (1.0, 1.0, 0.0), (1.0, 0.0, 0.0)])
OTHER_FACES = (0.75, 0.75, 0.75)  # faces of the object the map was not asked for
# The automatic range: these percentiles of the vertex values, so that a few extreme
# values (a fillet's corner, a near-singular point) do not wash out the rest.
AUTO_PERCENTILES = (2.0, 98.0)
LEGEND_TICKS = 5


def quantity_label(quantity):
    """'Mean curvature (1/mm)', translated."""
    words, unit = QUANTITY_TEXT[quantity]
    return f"{translate('FairSplines', words)} ({unit})"


def colours(values, lower, upper):
    """RGB (n, 3) of values through the colour bar from lower (blue) to upper (red);
    values outside the range take the end colours."""
    values = np.asarray(values, dtype=float)
    span = upper - lower
    t = np.clip((values - lower) / span, 0.0, 1.0) if span > 0 else np.full(values.shape, 0.5)
    x = t * (len(STOPS) - 1)
    stop = np.arange(len(STOPS))
    return np.column_stack([np.interp(x, stop, STOPS[:, c]) for c in range(3)])


def auto_range(values):
    """(lower, upper): the AUTO_PERCENTILES of the values; widened around the value where
    they are all (nearly) equal, as on a sphere or a plane."""
    values = np.asarray(values, dtype=float)
    if values.size == 0:
        return -1.0, 1.0
    lower, upper = (float(v) for v in np.percentile(values, AUTO_PERCENTILES))
    size = max(abs(lower), abs(upper))
    if upper - lower <= 1e-6 * size or upper - lower <= 1e-12:
        centre = 0.5 * (lower + upper)
        half = max(0.5 * abs(centre), 1e-6)
        return centre - half, centre + half
    return lower, upper


def tick_values(lower, upper, count=LEGEND_TICKS):
    return [lower + (upper - lower) * k / (count - 1) for k in range(count)]


def format_value(value):
    return f"{value:.4g}"


def _global_shape(obj, sub=""):
    """The object's shape (or one face) in global coordinates."""
    import Part

    if sub:
        return Part.getShape(obj, sub, needSubElement=True)
    return Part.getShape(obj)


def _element(sub):
    return sub.rsplit(".", 1)[-1] if sub else ""


def _string(text):
    """The first line of a SoText2's string."""
    value = text.string[0]
    return value.getString() if hasattr(value, "getString") else str(value)


class _Legend:
    """A colour bar with LEGEND_TICKS values and the quantity's name, drawn over the 3D view
    (SoAnnotation, in the view's normalised coordinates, unpickable)."""

    LEFT, RIGHT, BOTTOM, TOP = 0.78, 0.83, -0.6, 0.6  # of the view, from -1 to 1

    def __init__(self):
        from pivy import coin

        self.root = coin.SoAnnotation()
        camera = coin.SoOrthographicCamera()
        camera.viewportMapping = coin.SoCamera.LEAVE_ALONE
        camera.position = (0.0, 0.0, 5.0)
        camera.height = 2.0
        camera.nearDistance = 1.0
        camera.farDistance = 10.0
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        light = coin.SoLightModel()
        light.model = coin.SoLightModel.BASE_COLOR
        self.root.addChild(camera)
        self.root.addChild(pick)
        self.root.addChild(light)
        bar = coin.SoSeparator()
        n = 64
        ys = np.linspace(self.BOTTOM, self.TOP, n + 1)
        points = [(x, float(y), 0.0) for y in ys for x in (self.LEFT, self.RIGHT)]
        rgb = colours(np.linspace(0.0, 1.0, n + 1), 0.0, 1.0)
        material = coin.SoMaterial()
        per_vertex = [tuple(map(float, c)) for c in np.repeat(rgb, 2, axis=0)]  # both ends of each row
        material.diffuseColor.setValues(0, len(per_vertex), per_vertex)
        binding = coin.SoMaterialBinding()
        binding.value = coin.SoMaterialBinding.PER_VERTEX
        coords = coin.SoCoordinate3()
        coords.point.setValues(0, len(points), points)
        strip = coin.SoQuadMesh()
        strip.verticesPerRow = 2
        strip.verticesPerColumn = n + 1
        frame_colour = coin.SoBaseColor()
        frame_colour.rgb = (0.1, 0.1, 0.1)
        frame_coords = coin.SoCoordinate3()
        frame_coords.point.setValues(0, 5, [(self.LEFT, self.BOTTOM, 0.01), (self.RIGHT, self.BOTTOM, 0.01),
                                            (self.RIGHT, self.TOP, 0.01), (self.LEFT, self.TOP, 0.01),
                                            (self.LEFT, self.BOTTOM, 0.01)])
        frame = coin.SoLineSet()
        for node in (material, binding, coords, strip, frame_colour, frame_coords, frame):
            bar.addChild(node)
        self.root.addChild(bar)
        text_colour = coin.SoBaseColor()
        text_colour.rgb = (0.05, 0.05, 0.05)
        self.root.addChild(text_colour)
        font = coin.SoFont()
        font.size = 14
        self.root.addChild(font)
        self.ticks = []
        for k in range(LEGEND_TICKS):
            y = self.BOTTOM + (self.TOP - self.BOTTOM) * k / (LEGEND_TICKS - 1)
            self.ticks.append(self._text(coin, (self.LEFT - 0.01, y - 0.015, 0.0), coin.SoText2.RIGHT))
        self.title = self._text(coin, (self.RIGHT, self.TOP + 0.06, 0.0), coin.SoText2.RIGHT)

    def _text(self, coin, position, justification):
        node = coin.SoSeparator()
        move = coin.SoTranslation()
        move.translation = position
        text = coin.SoText2()
        text.justification = justification
        node.addChild(move)
        node.addChild(text)
        self.root.addChild(node)
        return text

    def set(self, title, lower, upper):
        self.title.string = title
        for text, value in zip(self.ticks, tick_values(lower, upper)):
            text.string = format_value(value)

    def texts(self):
        """(title, [tick texts from the bottom]) as drawn."""
        return _string(self.title), [_string(t) for t in self.ticks]


class CurvatureMapNode(ViewAttached):
    """The coloured triangulation of one object's faces (global coordinates, unpickable)."""

    def __init__(self, obj, faces=()):
        from pivy import coin

        self.obj, self.faces = obj, tuple(faces)  # faces: element names, () for all
        self.quantity = "mean"
        self.manual = None  # (lower, upper) or None for the automatic range
        self.deflection = None  # fw.curvature_map's: None for its default
        self.data = None  # fw.CurvatureMap
        self.error = ""
        self.mask = None  # vertices of the faces asked for (None: all)
        self.root = coin.SoSwitch()
        self.root.setName("FairSplinesCurvatureMap")
        self.root.whichChild = coin.SO_SWITCH_ALL
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        hints = coin.SoShapeHints()
        hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE
        hints.shapeType = coin.SoShapeHints.UNKNOWN_SHAPE_TYPE  # two-sided lighting
        hints.creaseAngle = 0.6
        self.material = coin.SoMaterial()
        self.material.specularColor = (0.15, 0.15, 0.15)
        self.material.shininess = 0.3
        binding = coin.SoMaterialBinding()
        binding.value = coin.SoMaterialBinding.PER_VERTEX_INDEXED
        self.coords = coin.SoCoordinate3()
        self.mesh = coin.SoIndexedFaceSet()
        for node in (pick, hints, self.material, binding, self.coords, self.mesh):
            self.root.addChild(node)
        self.views = []

    @property
    def range(self):
        if self.manual is not None:
            return self.manual
        if self.data is None:
            return (-1.0, 1.0)
        return auto_range(self._shown_values())

    def _shown_values(self):
        return self.data.values[self.mask] if self.mask is not None and self.mask.any() else self.data.values

    def update(self):
        """Mesh and evaluate the object's shape again (after a recompute)."""
        import freecad_workbench as fw

        self.error = ""
        try:
            self.data = fw.curvature_map(_global_shape(self.obj), self.quantity, deflection=self.deflection)
        except (ValueError, RuntimeError, AttributeError) as exc:  # fw.InputError is a ValueError
            self.error = str(exc)
            self.data = None
            self.coords.point.deleteValues(0)
            self.mesh.coordIndex.deleteValues(0)
            return
        self.mask = None  # vertices of the faces asked for
        if self.faces:
            wanted = [int(name[4:]) for name in self.faces if name.startswith("Face")]
            on_triangle = np.isin(self.data.face, wanted)
            self.mask = np.zeros(len(self.data.points), dtype=bool)
            self.mask[self.data.triangles[on_triangle].ravel()] = True
        index = np.c_[self.data.triangles, -np.ones(len(self.data.triangles), dtype=int)].ravel()
        set_values(self.coords.point, self.data.points)
        set_values(self.mesh.coordIndex, index, np.int32)
        set_values(self.mesh.materialIndex, index, np.int32)
        self.recolour()

    def recolour(self):
        """Colours from the values and the range: no re-meshing."""
        if self.data is None:
            return
        lower, upper = self.range
        rgb = colours(self.data.values, lower, upper)
        if self.mask is not None:
            rgb[~self.mask] = OTHER_FACES
        set_values(self.material.diffuseColor, rgb)

    def vertex_colours(self):
        """(points (n, 3), colours (n, 3)) as the coin nodes hold them."""
        points = np.array([tuple(p.getValue()) for p in self.coords.point])
        rgb = np.array([tuple(c.getValue()) for c in self.material.diffuseColor])
        return points, rgb

    def probe(self, origin, direction):
        """The value where the ray origin + t direction first meets the mesh, as
        (value, point) or None: barycentric interpolation in the hit triangle."""
        if self.data is None or not len(self.data.triangles):
            return None
        p = self.data.points
        tri = self.data.triangles
        a, b, c = p[tri[:, 0]], p[tri[:, 1]], p[tri[:, 2]]
        d = np.asarray(direction, dtype=float)
        d = d / np.linalg.norm(d)
        o = np.asarray(origin, dtype=float)
        e1, e2 = b - a, c - a  # Moeller-Trumbore, all triangles at once
        h = np.cross(d, e2)
        det = np.einsum("ij,ij->i", e1, h)
        ok = np.abs(det) > 1e-14
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        s = o - a
        u = inv * np.einsum("ij,ij->i", s, h)
        q = np.cross(s, e1)
        v = inv * (q @ d)
        t = inv * np.einsum("ij,ij->i", e2, q)
        hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1)
        if self.mask is not None:
            hit &= self.mask[tri[:, 0]]
        if not hit.any():
            return None
        k = np.flatnonzero(hit)[np.argmin(t[hit])]
        values = self.data.values[tri[k]]
        value = (1 - u[k] - v[k]) * values[0] + u[k] * values[1] + v[k] * values[2]
        return float(value), o + t[k] * d

    def set_visible(self, visible):
        from pivy import coin

        self.root.whichChild = coin.SO_SWITCH_ALL if visible else coin.SO_SWITCH_NONE


# One map per object, keyed (document name, object name); one legend per document view.
_maps = {}
_legends = {}
_saved_modes = {}  # key: the object's DisplayMode before its map
_observers = []
_callbacks = {}  # document name: (view, event type, callback)
_pending = set()
_listeners = []  # callables(text) told the value under the cursor (the panel)


def _key(obj):
    return (obj.Document.Name, obj.Name)


def _view(doc):
    from .overlay import active_view

    return active_view(doc)


def shown():
    """The objects with a map."""
    result = []
    for doc_name, name in _maps:
        doc = FreeCAD.listDocuments().get(doc_name)
        obj = doc.getObject(name) if doc is not None else None
        if obj is not None:
            result.append(obj)
    return result


def map_of(obj):
    return _maps.get(_key(obj))


def legend_of(doc):
    return _legends.get(doc.Name)


def show(links, quantity=None, lower=None, upper=None):
    """Map the faces of selection-style links [(obj, subname)]: a whole object (subname '')
    or some of its faces ('Face3'). quantity: one of QUANTITIES (None: keep the map's, else
    mean curvature); lower and upper: a manual range (None: automatic). Returns the nodes."""
    _install()
    grouped = {}
    for obj, sub in links:
        if getattr(obj, "Shape", None) is None or obj.Shape.isNull() or not obj.Shape.Faces:
            continue
        name = _element(sub)
        faces = grouped.setdefault(_key(obj), (obj, set()))[1]
        if name.startswith("Face"):
            faces.add(name)
        elif not name:
            faces.add("*")
    nodes = []
    for key, (obj, faces) in grouped.items():
        faces = () if "*" in faces else tuple(sorted(faces))
        node = _maps.get(key)
        if node is None:
            node = CurvatureMapNode(obj, faces)
            _maps[key] = node
            vobj = getattr(obj, "ViewObject", None)
            if vobj is not None and "Wireframe" in vobj.listDisplayModes():
                _saved_modes[key] = vobj.DisplayMode
                vobj.DisplayMode = "Wireframe"
        else:
            node.faces = faces
        if quantity is not None:
            node.quantity = quantity
        node.manual = None if lower is None or upper is None else (float(lower), float(upper))
        node.update()
        node.attach(_view(obj.Document))
        _sync_visibility(obj)
        nodes.append(node)
    _refresh_legends()
    return nodes


def set_quantity(obj, quantity):
    """Another quantity: evaluates again (the range goes back to automatic)."""
    node = _maps.get(_key(obj))
    if node is not None and node.quantity != quantity:
        node.quantity = quantity
        node.manual = None
        node.update()
        _refresh_legends()


def set_range(obj, lower=None, upper=None):
    """A manual range, or the automatic one for None: recolours without re-meshing."""
    node = _maps.get(_key(obj))
    if node is None:
        return
    node.manual = None if lower is None or upper is None else (float(lower), float(upper))
    node.recolour()
    _refresh_legends()


def hide(obj=None):
    """Turn the map of obj off (None: every map), restoring the object's display mode."""
    keys = list(_maps) if obj is None else [_key(obj)]
    for key in keys:
        node = _maps.pop(key, None)
        if node is None:
            continue
        node.detach()
        restore_display_mode(_saved_modes, key)
    _refresh_legends()


def toggle(links):
    """Turn off the maps of the linked objects that have one; map the others. With no
    links, turn every map off."""
    if not links:
        hide()
        return
    on = [(obj, sub) for obj, sub in links if _key(obj) not in _maps]
    for obj in {_key(o): o for o, _ in links if _key(o) in _maps}.values():
        hide(obj)
    if on:
        show(on)


def _refresh_legends():
    """One legend per document with maps: the range of its first map (the panel's)."""
    wanted = {}
    for (doc_name, _), node in _maps.items():
        wanted.setdefault(doc_name, node)
    for doc_name in list(_legends):
        if doc_name not in wanted:
            legend, view = _legends.pop(doc_name)
            try:
                view.getSceneGraph().removeChild(legend.root)
            except Exception:  # the view was closed
                pass
            _remove_callback(doc_name)
    for doc_name, node in wanted.items():
        doc = FreeCAD.listDocuments().get(doc_name)
        view = _view(doc)
        if view is None:
            continue
        if doc_name not in _legends:
            legend = _Legend()
            view.getSceneGraph().addChild(legend.root)
            _legends[doc_name] = (legend, view)
            _add_callback(doc_name, view)
        lower, upper = node.range
        _legends[doc_name][0].set(quantity_label(node.quantity), lower, upper)


def legend_texts(doc):
    entry = _legends.get(doc.Name)
    return entry[0].texts() if entry else None


# --- the value under the cursor ---------------------------------------------------------

def probe_at(doc, position):
    """(object, value, point) under the view's pixel `position` (x, y from the bottom left,
    as coin's events give it), or None."""
    view = _view(doc)
    if view is None:
        return None
    near = view.getPoint(int(position[0]), int(position[1]))
    camera = view.getCameraNode()
    if camera.getTypeId().getName().getString() == "PerspectiveCamera":
        origin = np.array(camera.position.getValue().getValue())
        direction = np.array(tuple(near)) - origin
    else:
        direction = np.array(tuple(view.getViewDirection()))
        origin = np.array(tuple(near)) - direction * 1e6
    best = None
    for (doc_name, _), node in _maps.items():
        if doc_name != doc.Name:
            continue
        hit = node.probe(origin, direction)
        if hit is not None:
            distance = float(np.dot(hit[1] - origin, direction))
            if best is None or distance < best[0]:
                best = (distance, node.obj, hit[0], hit[1])
    return None if best is None else best[1:]


def describe(obj, value, point, quantity):
    words, unit = QUANTITY_TEXT[quantity]
    return translate("FairSplines", "{label}: {quantity} {value} {unit} at ({x}, {y}, {z}) mm").format(
        label=obj.Label, quantity=translate("FairSplines", words), value=format_value(value), unit=unit,
        x=f"{point[0]:.2f}", y=f"{point[1]:.2f}", z=f"{point[2]:.2f}")


def _on_move(doc_name, info):
    doc = FreeCAD.listDocuments().get(doc_name)
    if doc is None:
        return
    event = info.getEvent()
    hit = probe_at(doc, event_position(event))
    text = "" if hit is None else describe(hit[0], hit[1], hit[2], _maps[_key(hit[0])].quantity)
    from .qt import main_window

    main = main_window()
    if main is not None and text:
        main.statusBar().showMessage(text, 5000)
    for listener in list(_listeners):
        listener(text)


def _add_callback(doc_name, view):
    from pivy import coin

    def callback(info):
        try:
            _on_move(doc_name, info)
        except Exception as exc:  # never let a mouse move raise into coin
            FreeCAD.Console.PrintLog(f"FairSplines curvature map probe: {exc}\n")

    kind = coin.SoLocation2Event.getClassTypeId()
    try:
        handle = view.addEventCallbackPivy(kind, callback)
    except Exception:  # a view without coin events
        return
    _callbacks[doc_name] = (view, kind, handle)


def _remove_callback(doc_name):
    entry = _callbacks.pop(doc_name, None)
    if entry is None:
        return
    view, kind, handle = entry
    try:
        view.removeEventCallbackPivy(kind, handle)
    except Exception:  # the view was closed
        pass


# --- following the document ---------------------------------------------------------------

def _sync_visibility(obj):
    node = _maps.get(_key(obj))
    vobj = getattr(obj, "ViewObject", None)
    if node is not None and vobj is not None:
        node.set_visible(bool(vobj.Visibility))


def _flush():
    keys = list(_pending)
    _pending.clear()
    for key in keys:
        node = _maps.get(key)
        if node is not None:
            node.update()
    _refresh_legends()


class _Observer:
    def slotChangedObject(self, obj, prop):
        key = (obj.Document.Name, obj.Name)
        if key in _maps and prop in ("Shape", "Placement"):
            if not _pending:
                from .qt import QtCore

                QtCore.QTimer.singleShot(0, _flush)  # once per recompute, however many changes
            _pending.add(key)

    def slotDeletedObject(self, obj):
        key = (obj.Document.Name, obj.Name)
        if key in _maps:
            _maps.pop(key).detach()
            _saved_modes.pop(key, None)
            _refresh_legends()

    def slotDeletedDocument(self, doc):
        for key in [k for k in _maps if k[0] == doc.Name]:
            _maps.pop(key).detach()
            _saved_modes.pop(key, None)
        _legends.pop(doc.Name, None)
        _callbacks.pop(doc.Name, None)


class _GuiObserver:
    def slotChangedObject(self, vobj, prop):
        if prop == "Visibility":
            _sync_visibility(vobj.Object)


def _install():
    if _observers:
        return
    import FreeCADGui

    _observers.extend((_Observer(), _GuiObserver()))
    FreeCAD.addDocumentObserver(_observers[0])
    FreeCADGui.addDocumentObserver(_observers[1])
