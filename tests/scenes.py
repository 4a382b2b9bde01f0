"""Document scenes shared by the headless and the GUI tests."""
import math

import numpy as np

import FreeCAD
import Part

V = FreeCAD.Vector


def line_into_arc(doc):
    """A straight lead-in ending at the origin along +x, and a circle arc (radius 10) where the
    clothoid kappa(s) = s / 200 from the origin ends after s = 20 (turning 1 rad), continuing
    it with curvature 1/10: a monotone-curvature G2 blend of the two exists, that clothoid
    (integrated here by Simpson's rule). Returns (lead, arc) document objects."""
    s = np.linspace(0.0, 20.0, 40001)
    theta = s**2 / 400.0
    w = np.ones_like(s)
    w[1:-1:2], w[2:-1:2] = 4.0, 2.0
    h = (s[1] - s[0]) / 3.0
    end = V(h * np.sum(w * np.cos(theta)), h * np.sum(w * np.sin(theta)), 0)
    centre = end + V(-math.sin(1.0), math.cos(1.0), 0) * 10.0
    lead = doc.addObject("Part::Feature", "Lead")
    lead.Shape = Part.LineSegment(V(-20, 0, 0), V(0, 0, 0)).toShape()
    arc = doc.addObject("Part::Feature", "Arc")
    start = 1.0 - math.pi / 2
    arc.Shape = Part.ArcOfCircle(Part.Circle(centre, V(0, 0, 1), 10), start, start + math.radians(120)).toShape()
    doc.recompute()
    return lead, arc


def rim_edge(obj, z):
    """The name ('EdgeN') of obj's circular edge at height z (a cylinder's rim)."""
    for i, e in enumerate(obj.Shape.Edges):
        if e.Curve.__class__.__name__ == "Circle" and abs(e.CenterOfMass.z - z) < 1e-9:
            return f"Edge{i + 1}"
    raise AssertionError(f"{obj.Name} has no circular edge at z = {z}")


def wavy_floor_and_wall(doc):
    """A wavy floor and a wavy wall, one bicubic C2 face each (four knot spans each way, simple
    interior knots), 40 mm apart: (floor, the floor's edge facing the wall, wall, the wall's
    bottom edge). (Knots of multiplicity 3 made them C0 along their middle lines: zebra showed
    those creases as a cross on the floor.)"""
    def sheet(name, point):
        poles = [[point(i / 6.0, j / 6.0) for j in range(7)] for i in range(7)]
        surface = Part.BSplineSurface()
        knots, mults = [0, 0.25, 0.5, 0.75, 1], [4, 1, 1, 1, 4]
        surface.buildFromPolesMultsKnots(poles, mults, mults, knots, knots, False, False, 3, 3)
        obj = doc.addObject("Part::Feature", name)
        obj.Shape = surface.toShape()
        return obj

    floor = sheet("Floor", lambda s, t: V(60 * s - 30, 40 * t - 40, 3 * math.sin(3 * s) * math.sin(2 * t)))
    wall = sheet("Wall", lambda s, t: V(60 * s - 30, 20 + 3 * math.sin(4 * s) * t, 20 + 40 * t))
    doc.recompute()
    edge_f = next(f"Edge{i + 1}" for i, e in enumerate(floor.Shape.Edges) if abs(e.CenterOfMass.y) < 1e-6)
    edge_w = next(f"Edge{i + 1}" for i, e in enumerate(wall.Shape.Edges) if abs(e.CenterOfMass.z - 20) < 1e-6)
    return floor, edge_f, wall, edge_w


def assert_failed_like_freecad(obj, message):
    """A feature that could not be built fails as FreeCAD's own do: invalid (the error mark
    in the tree), FreeCAD's status string and the Status property name the reason. (That
    the last good shape is kept, each test checks itself.)"""
    assert message in obj.Status, obj.Status
    assert not obj.isValid() and "Invalid" in obj.State, obj.State
    assert message in obj.getStatusString(), obj.getStatusString()
