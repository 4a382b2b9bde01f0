"""Zebra (reflection-line) shading of a surface, for the profile test (csr paper, Figs. 13d
and 14d-e): the surface reflects an environment of black and white stripes. Where the
surface is curvature continuous the stripes run smooth; a jump in curvature (a G1 join of
a line and an arc) kinks them, and a curvature wiggle of the profile makes them wobble.

How: coin's SoTextureCoordinateEnvironment (sphere mapping) on a striped SoTexture2,
applied to a mesh of the exact surface with exact normals (`Surface.normal`). The stripes
follow the view, as reflections do. `zebra_mesh` and `stripe_image` are headless numpy;
`ZebraNode` needs pivy.
"""
import math

import numpy as np

from .. import preferences

U_SAMPLES = 400  # along the profile, split over the knot spans
V_SAMPLES = 128  # around the axis
MIN_PER_SPAN = 4


def _span_samples(knots, total):
    """Parameters covering [knots[0], knots[-1]]: every knot, and each span cut into steps
    in proportion to its length (at least MIN_PER_SPAN)."""
    knots = sorted(set(float(k) for k in knots))
    length = knots[-1] - knots[0]
    values = [knots[0]]
    for a, b in zip(knots[:-1], knots[1:]):
        steps = max(MIN_PER_SPAN, int(math.ceil(total * (b - a) / length - 1e-9)))
        values.extend(a + (b - a) * np.arange(1, steps + 1) / steps)
    values[-1] = knots[-1]
    return np.array(values)


def zebra_mesh(surface, u_samples=U_SAMPLES, v_samples=V_SAMPLES):
    """Grid mesh of a Part surface: (points (n,3), normals (n,3), quads (k,4) vertex
    indices, shape (nu, nv)). u follows the surface's knot spans; normals are the
    surface's own, taken from a neighbour where it has none (a pole on the axis)."""
    u0, u1, v0, v1 = surface.bounds()
    u_knots = surface.getUKnots() if hasattr(surface, "getUKnots") else (u0, u1)
    v_knots = surface.getVKnots() if hasattr(surface, "getVKnots") else (v0, v1)
    us = _span_samples(u_knots, u_samples)
    vs = _span_samples(v_knots, v_samples)
    nu, nv = len(us), len(vs)
    points = np.empty((nu, nv, 3))
    normals = np.full((nu, nv, 3), np.nan)
    for i, u in enumerate(us):
        for j, v in enumerate(vs):
            p = surface.value(float(u), float(v))
            points[i, j] = (p.x, p.y, p.z)
            try:
                n = surface.normal(float(u), float(v))
                if n.Length > 0.5:
                    normals[i, j] = (n.x, n.y, n.z)
            except Exception:  # degenerate point (on the axis): no normal there
                pass
    _fill_missing(normals)
    index = np.arange(nu * nv).reshape(nu, nv)
    quads = np.stack([index[:-1, :-1], index[1:, :-1], index[1:, 1:], index[:-1, 1:]], axis=-1).reshape(-1, 4)
    return points.reshape(-1, 3), normals.reshape(-1, 3), quads, (nu, nv)


def _fill_missing(normals):
    """Replace NaN normals by the nearest valid one along u at the same v (0 if none)."""
    nu = normals.shape[0]
    bad = np.isnan(normals).any(axis=-1)
    for i, j in zip(*np.nonzero(bad)):
        for k in sorted(range(nu), key=lambda k: abs(k - i)):
            if not bad[k, j]:
                normals[i, j] = normals[k, j]
                break
    normals[np.isnan(normals)] = 0.0


def __getattr__(name):
    # DEFAULT_STRIPES is the ZebraStripes preference, read each time it is asked for.
    if name == "DEFAULT_STRIPES":
        return preferences.get("ZebraStripes")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def stripe_image(stripes=None, size=256):
    """A size x size grey image (bytes, one byte per texel) of `stripes` vertical black and
    white stripes: the environment the surface reflects (None: the ZebraStripes preference)."""
    stripes = max(1, int(preferences.get("ZebraStripes") if stripes is None else stripes))
    x = np.arange(size)
    row = np.where((x * 2 * stripes // size) % 2 == 0, 255, 0).astype(np.uint8)
    return np.tile(row, (size, 1)).tobytes(), size


class ZebraNode:
    """A coin separator drawing a surface with zebra shading; `update` re-meshes it."""

    def __init__(self, stripes=None):
        from pivy import coin

        self.coin = coin
        self.root = coin.SoSeparator()
        self.root.setName("FairSplinesZebra")
        hints = coin.SoShapeHints()
        hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE
        hints.shapeType = coin.SoShapeHints.UNKNOWN_SHAPE_TYPE  # two-sided lighting
        material = coin.SoMaterial()
        material.diffuseColor = (1.0, 1.0, 1.0)
        material.ambientColor = (0.6, 0.6, 0.6)
        material.specularColor = (0.0, 0.0, 0.0)
        self.texture = coin.SoTexture2()
        self.texture.model = coin.SoTexture2.MODULATE
        self.environment = coin.SoTextureCoordinateEnvironment()
        self.coords = coin.SoCoordinate3()
        self.normals = coin.SoNormal()
        binding = coin.SoNormalBinding()
        binding.value = coin.SoNormalBinding.PER_VERTEX_INDEXED
        self.faces = coin.SoIndexedFaceSet()
        for node in (hints, material, self.texture, self.environment, self.coords, self.normals, binding, self.faces):
            self.root.addChild(node)
        self.set_stripes(preferences.get("ZebraStripes") if stripes is None else stripes)
        self.vertex_count = 0

    def set_stripes(self, stripes):
        image, size = stripe_image(stripes)
        self.texture.image.setValue(self.coin.SbVec2s(size, size), 1, image)
        self.stripes = int(stripes)

    def clear(self):
        self.coords.point.deleteValues(0)
        self.normals.vector.deleteValues(0)
        self.faces.coordIndex.deleteValues(0)
        self.faces.normalIndex.deleteValues(0)
        self.vertex_count = 0

    def set_mesh(self, points, normals, index):
        """Draw this mesh: points and normals (n, 3), faces as coin's index list (-1 ends one)."""
        from .scene import set_values

        set_values(self.coords.point, points)
        set_values(self.normals.vector, normals)
        set_values(self.faces.coordIndex, index, np.int32)
        set_values(self.faces.normalIndex, index, np.int32)
        self.vertex_count = len(points)

    def update(self, surface):
        """Mesh `surface` (a Part surface), or clear the node for None."""
        if surface is None:
            self.clear()
            return
        points, normals, quads, _ = zebra_mesh(surface)
        self.set_mesh(points, normals, np.c_[quads, -np.ones(len(quads), dtype=int)].ravel())


# Zebra mesh of each face of a shell (a patch): samples per face, at least 4 per knot span.
FACE_SAMPLES = 12


def update_zebra_faces(node, faces, samples=FACE_SAMPLES):
    """Mesh every face's surface into one ZebraNode, or clear it."""
    if not faces:
        node.update(None)
        return
    points, normals, index, offset = [], [], [], 0
    for face in faces:
        p, n, quads, _ = zebra_mesh(face.Surface, samples, samples)
        if face.Orientation == "Reversed":
            n = -n
        points.append(p)
        normals.append(n)
        index.append(np.c_[quads + offset, -np.ones(len(quads), dtype=int)].ravel())
        offset += len(p)
    node.set_mesh(np.concatenate(points), np.concatenate(normals), np.concatenate(index))
