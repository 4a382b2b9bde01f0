"""Zebra and isophotes on any shape (issue 27): the faces of any object (Part, PartDesign,
imports) drawn with reflected stripes (zebra.ZebraNode's sphere-mapped texture: it follows
the view and does not depend on the model's size) or with isophotes, lines of equal angle
between the exact surface normal and a fixed light direction.

    show(obj, stripes=16, vertical=True)                # zebra
    show(obj, isophotes=(30, 60), light=(0, 0, 1))      # isophotes at 30 and 60 degrees
    hide(obj) / hide()

The mesh is fw.curvature_map's triangulation of the faces (a chordal deflection of 1/5000
of the shape's size, refined where the curvature changes fast), with normals averaged
within each face, and the stripes are mapped from the view: they stay sharp on small and
large models alike (Part's own tessellation that fine takes seconds a face). While shown
the object is drawn as wireframe; its display mode comes back.
"""
import numpy as np

import FreeCAD

from .scene import ViewAttached, restore_display_mode

DEFLECTION = 2e-4  # of the shape's diagonal
SPLIT = 0.02  # no triangle edge longer than this part of the shape's diagonal
ISOPHOTE_TEXELS = 1024  # the isophote texture: one texel a 0.18 degrees
ISOPHOTE_WIDTH = 0.6  # degrees, each line's half width


def subdivide(points, triangles, limit, normals=None, rounds=8):
    """Split triangles with an edge longer than `limit` in four (midpoints shared between
    neighbours), up to `rounds` times. Midpoints lie on the triangle's edges, so a split
    triangle beside one that is not split leaves no crack. The view-relative texture
    coordinates of the stripes are interpolated linearly across a triangle: the large flat
    triangles of a planar face would draw them jagged. normals (n, 3), if given, are carried
    along (a midpoint's is the normalised mean of its edge's ends): (points, triangles, normals)."""
    points, triangles = np.asarray(points, dtype=float), np.asarray(triangles, dtype=int)
    for _ in range(rounds):
        p = points
        lengths = np.stack([np.linalg.norm(p[triangles[:, (k + 1) % 3]] - p[triangles[:, k]], axis=1)
                            for k in range(3)], axis=1)
        long = lengths.max(axis=1) > limit
        if not long.any():
            break
        split = triangles[long]
        edges = np.sort(np.concatenate([split[:, [0, 1]], split[:, [1, 2]], split[:, [2, 0]]]), axis=1)
        unique, inverse = np.unique(edges, axis=0, return_inverse=True)
        inverse = inverse.reshape(-1)
        midpoints = 0.5 * (p[unique[:, 0]] + p[unique[:, 1]])
        index = len(p) + inverse.reshape(3, -1).T  # the midpoints of edges 01, 12, 20 of each split triangle
        m01, m12, m20 = index[:, 0], index[:, 1], index[:, 2]
        v0, v1, v2 = split[:, 0], split[:, 1], split[:, 2]
        new = np.concatenate([np.stack(t, axis=1) for t in
                              ((v0, m01, m20), (m01, v1, m12), (m20, m12, v2), (m01, m12, m20))])
        points = np.concatenate([p, midpoints])
        triangles = np.concatenate([triangles[~long], new])
        if normals is not None:
            mean = normals[unique[:, 0]] + normals[unique[:, 1]]
            length = np.linalg.norm(mean, axis=1)
            mean[length > 0] /= length[length > 0][:, None]
            normals = np.concatenate([normals, mean])
    return points, triangles, normals


def shape_mesh(shape, deflection=None):
    """(points (n, 3), normals (n, 3), triangles (m, 3)) of every face of a shape: the
    triangulation of fw.curvature_map (fine, and finer where the surface bends fast) with
    its normals, each face's own evaluated exactly at the vertex (the faces do not share
    vertices there, so creases between faces stay sharp; the stripes follow the surface,
    not the facets)."""
    import freecad_workbench as fw

    size = shape.BoundBox.DiagonalLength or 1.0
    mesh = fw.curvature_map(shape, "max_abs", deflection or DEFLECTION * size)
    points, triangles, normals = subdivide(mesh.points, mesh.triangles, SPLIT * size, mesh.normals)
    return points, normals, triangles


def isophote_coordinates(normals, light):
    """The texture coordinate of each vertex: the angle between its normal and the light, /180."""
    light = np.asarray(light, dtype=float)
    light = light / np.linalg.norm(light)
    cosine = np.clip(np.asarray(normals) @ light, -1.0, 1.0)
    return np.degrees(np.arccos(cosine)) / 180.0


def isophote_image(angles, size=ISOPHOTE_TEXELS):
    """A size x 1 grey texture, dark lines at the angles (degrees) on white."""
    degrees = (np.arange(size) + 0.5) * 180.0 / size
    row = np.full(size, 255, dtype=np.uint8)
    for angle in angles:
        row[np.abs(degrees - float(angle)) <= ISOPHOTE_WIDTH] = 0
    return row.tobytes(), size


class ShapeZebraNode(ViewAttached):
    """Zebra or isophotes over one object's faces (global coordinates, unpickable)."""

    def __init__(self, obj):
        from pivy import coin

        from .zebra import ZebraNode

        self.coin = coin
        self.obj = obj
        self.stripes, self.vertical = 16, True
        self.isophotes, self.light = (), (0.0, 0.0, 1.0)
        self.root = coin.SoSeparator()
        self.root.setName("FairSplinesShapeZebra")
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        self.root.addChild(pick)
        self.zebra = ZebraNode(self.stripes)
        self.rotation = coin.SoTexture2Transform()
        self.zebra.root.insertChild(self.rotation, 2)
        self.texcoords = coin.SoTextureCoordinate2()
        self.root.addChild(self.zebra.root)
        self.views = []
        self.mesh = None

    def update(self):
        """Mesh the object's shape again (after a recompute)."""
        import Part

        self.mesh = shape_mesh(Part.getShape(self.obj))
        points, normals, triangles = self.mesh
        self.zebra.set_mesh(points, normals, np.c_[triangles, -np.ones(len(triangles), dtype=int)].ravel())
        self.restyle()

    def restyle(self):
        """Stripes or isophotes, without re-meshing."""
        coin, z = self.coin, self.zebra
        environment = z.root.findChild(z.environment)
        coordinates = z.root.findChild(self.texcoords)
        if self.isophotes:
            image, size = isophote_image(self.isophotes)
            z.texture.image.setValue(coin.SbVec2s(size, 1), 1, image)
            if environment >= 0:
                z.root.replaceChild(environment, self.texcoords)
            elif coordinates < 0:
                z.root.insertChild(self.texcoords, 3)
            s = isophote_coordinates(self.mesh[1], self.light) if self.mesh is not None else np.zeros(0)
            self.texcoords.point.deleteValues(0)
            if len(s):
                self.texcoords.point.setValues(0, len(s), [(float(v), 0.5) for v in s])
            self.rotation.rotation = 0.0
        else:
            z.set_stripes(self.stripes)
            if coordinates >= 0:
                z.root.replaceChild(coordinates, z.environment)
            self.rotation.center = (0.5, 0.5)
            self.rotation.rotation = 0.0 if self.vertical else np.pi / 2


_nodes = {}
_saved_modes = {}
_observers = []


def _key(obj):
    return (obj.Document.Name, obj.Name)


def node_of(obj):
    return _nodes.get(_key(obj))


def show(obj, stripes=None, vertical=None, isophotes=None, light=None):
    """Zebra (isophotes empty or None) or isophotes at these angles (degrees) on obj's faces."""
    from .overlay import active_view

    _install()
    key = _key(obj)
    node = _nodes.get(key)
    if node is None:
        node = ShapeZebraNode(obj)
        _nodes[key] = node
        vobj = getattr(obj, "ViewObject", None)
        if vobj is not None and "Wireframe" in vobj.listDisplayModes():
            _saved_modes[key] = vobj.DisplayMode
            vobj.DisplayMode = "Wireframe"
        node.update()
        node.attach(active_view(obj.Document))
    if stripes is not None:
        node.stripes = int(stripes)
    if vertical is not None:
        node.vertical = bool(vertical)
    if isophotes is not None:
        node.isophotes = tuple(float(a) for a in isophotes)
    if light is not None:
        node.light = tuple(float(c) for c in light)
    node.restyle()
    return node


def hide(obj=None):
    keys = list(_nodes) if obj is None else [_key(obj)]
    for key in keys:
        node = _nodes.pop(key, None)
        if node is None:
            continue
        node.detach()
        restore_display_mode(_saved_modes, key)


def shown():
    return [node.obj for node in _nodes.values()]


class _Observer:
    def slotChangedObject(self, obj, prop):
        node = _nodes.get((obj.Document.Name, obj.Name))
        if node is not None and prop in ("Shape", "Placement"):
            node.update()

    def slotDeletedObject(self, obj):
        key = (obj.Document.Name, obj.Name)
        if key in _nodes:
            _nodes.pop(key).detach()
            _saved_modes.pop(key, None)


def _install():
    if not _observers:
        _observers.append(_Observer())
        FreeCAD.addDocumentObserver(_observers[0])
