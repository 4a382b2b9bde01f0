"""Curvature combs in the FreeCAD GUI (issue 12, point 5): the default scale keeps every
tooth short of its centre of curvature, one scale for all combs on request, a comb hides
with its object, and the view property CurvatureComb toggles a whole object's comb and is
saved with the document.

The referee is OCCT, not the comb code: the curvature and centre of curvature at a
tooth's base come from the Part curve of the object's edge there (`curvature(u)`,
`centerOfCurvature(u)`). The teeth are read back from the coin nodes the comb draws."""
import math
import os

import numpy as np
import pytest

import FreeCAD
import Part
import Sketcher  # noqa: F401

from freecad_workbench import preferences
from freecad_workbench.gui import comb

V = FreeCAD.Vector
STYLE_KEYS = ("CombScale", "CombSamples", "CombCommonScale", "CombTorsion")


def run(name):
    import FreeCADGui

    FreeCADGui.runCommand(name)
    FreeCADGui.updateGui()


def select(doc, *objs):
    import FreeCADGui

    FreeCADGui.Selection.clearSelection()
    for obj in objs:
        FreeCADGui.Selection.addSelection(obj)


@pytest.fixture
def scene(doc):
    """An active document, the comb preferences at their defaults; afterwards no comb, no
    selection, no dialog and the preferences as they were."""
    import FreeCADGui

    saved = {key: (preferences.is_set(key), preferences.get(key)) for key in STYLE_KEYS}
    for key in STYLE_KEYS:
        preferences.reset(key)
    FreeCAD.setActiveDocument(doc.Name)
    FreeCADGui.Selection.clearSelection()
    yield doc
    FreeCADGui.Selection.clearSelection()
    comb.hide()  # before the document closes: the comb's nodes live in its view
    if FreeCADGui.Control.activeDialog():
        FreeCADGui.Control.closeDialog()
    for key, (was_set, value) in saved.items():
        if was_set:
            preferences.set_value(key, value)
        else:
            preferences.reset(key)
    comb.refresh()


def feature(doc, name, edges, color=(0.85, 0.1, 0.1)):
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = Part.Wire(edges) if len(edges) > 1 else edges[0]
    obj.ViewObject.LineWidth = 3
    obj.ViewObject.LineColor = color
    return obj


def half_circle(doc, name, r, centre):
    return feature(doc, name, [Part.Edge(Part.Circle(V(*centre), V(0, 0, 1), r), 0.0, math.pi)])


def fillet_sketch(doc):
    """Two 20 mm lines joined by a circle arc of radius 5: a whole-object comb sized to the
    sketch's 35 mm box alone (the old default) has 8.8 mm teeth, past the arc's centre."""
    sketch = doc.addObject("Sketcher::SketchObject", "Fillet")
    arc = Part.ArcOfCircle(Part.Circle(V(5, 5, 0), V(0, 0, 1), 5.0), math.pi, 1.5 * math.pi)
    sketch.addGeometry(Part.LineSegment(V(0, 25, 0), V(0, 5, 0)))
    sketch.addGeometry(arc)
    sketch.addGeometry(Part.LineSegment(V(5, 0, 0), V(25, 0, 0)))
    doc.recompute()
    sketch.ViewObject.LineWidth = 3
    sketch.ViewObject.LineColor = (0.85, 0.1, 0.1)
    return sketch


def ellipse_arc(doc, name="EllipseArc", centre=(55, 2, 0)):
    """Half an ellipse with semi-axes 20 and 10: radius of curvature 5 at the ends of the
    major axis, where a quarter of the 41 mm box (the old default) is a 10 mm tooth."""
    ellipse = Part.Ellipse(V(*centre), 20.0, 10.0)
    return feature(doc, name, [Part.Edge(Part.ArcOfEllipse(ellipse, 0.0, math.pi))])


def teeth(node):
    """(base, tip) arrays of the teeth a comb node draws, from its coin line set."""
    coords = np.array([tuple(p.getValue()) for p in node.coords.point])
    index = np.array(node.teeth.coordIndex.getValues()).reshape(-1, 3)
    return coords[index[:, 0]], coords[index[:, 1]]


def referee(obj, point):
    """OCCT's [(curvature, centre of curvature or None)] at point of each edge of obj
    through it (two where edges meet)."""
    found = []
    for edge in obj.Shape.Edges:
        curve = edge.Curve
        u = curve.parameter(V(*point))
        if (curve.value(u) - V(*point)).Length > 1e-3 or edge.distToShape(Part.Vertex(V(*point)))[0] > 1e-3:
            continue
        kappa = curve.curvature(u)
        found.append((kappa, None) if kappa < 1e-9 else (kappa, np.array(tuple(curve.centerOfCurvature(u)))))
    assert found, f"{point} is on no edge of {obj.Name}"
    return found


def drawn(doc, node):
    """Whether the 3D view renders node's teeth: found by a search that, like rendering,
    enters only the switch children that are on."""
    import FreeCADGui
    from pivy import coin

    root = FreeCADGui.getDocument(doc.Name).ActiveView.getSceneGraph()
    search = coin.SoSearchAction()
    search.setNode(node.coords)
    search.setSearchingAll(False)
    search.apply(root)
    return search.getPath() is not None


def scale_ratios(obj, node):
    """Tooth length / OCCT curvature of each curved tooth: the comb's absolute scale."""
    ratios = []
    for b, t in zip(*teeth(node)):
        (kappa, _), = referee(obj, b)  # one edge
        if kappa > 1e-6:
            ratios.append(np.linalg.norm(t - b) / kappa)
    return np.array(ratios)


def assert_teeth_short_of_centres(obj, node):
    """Every tooth ends strictly between its base and OCCT's centre of curvature, pointing
    at it (at a vertex where edges meet: for one of them)."""
    base, tip = teeth(node)
    curved = 0
    for b, t in zip(base, tip):
        tooth = t - b
        length = np.linalg.norm(tooth)
        verdicts = []
        for kappa, centre in referee(obj, b):
            if centre is None:  # straight: no tooth
                verdicts.append(length < 1e-4)
                continue
            to_centre = centre - b
            radius = np.linalg.norm(to_centre)
            assert radius == pytest.approx(1 / kappa, rel=1e-6)
            verdicts.append(0 < length < radius and np.dot(tooth, to_centre) > 0.999 * length * radius)
        assert any(verdicts), (obj.Name, b, t, referee(obj, b))
        curved += length > 0
    assert curved > 100, curved


def assert_teeth_do_not_cross(node):
    """No two teeth of a planar comb (z = 0) cross each other (touching at a shared base
    does not count)."""
    base, tip = teeth(node)
    assert np.abs(base[:, 2]).max() < 1e-6 and np.abs(tip[:, 2]).max() < 1e-6
    keep = np.linalg.norm(tip - base, axis=1) > 1e-4
    b, d = base[keep, :2], (tip - base)[keep, :2]

    def side(d, p):  # z of d x p, pairwise: [i, j] for tooth i's direction and point j
        return d[:, None, 0] * p[..., 1] - d[:, None, 1] * p[..., 0]

    eps = 1e-6 * float(np.abs(d).max()) ** 2
    o1 = side(d, b[None, :, :] - b[:, None, :])  # j's base against tooth i
    o2 = side(d, (b + d)[None, :, :] - b[:, None, :])  # j's tip against tooth i
    straddles = (o1 * o2) < -eps * eps
    crossing = straddles & straddles.T
    i, j = np.nonzero(np.triu(crossing, 1))
    assert len(i) == 0, f"{len(i)} pairs of teeth cross, e.g. {b[i[0]]} and {b[j[0]]}"


def test_default_teeth_end_short_of_the_centre_of_curvature_on_arcs(scene, artifacts):
    import FreeCADGui
    from PIL import Image

    doc = scene
    sketch = fillet_sketch(doc)
    ellipse = ellipse_arc(doc)
    doc.recompute()
    select(doc, sketch, ellipse)
    run("FairSplines_CurvatureComb")
    assert sorted(comb.shown()) == sorted([(doc.Name, sketch.Name, ""), (doc.Name, ellipse.Name, "")])
    for obj in (sketch, ellipse):
        node = comb._combs[(doc.Name, obj.Name, "")]
        assert_teeth_short_of_centres(obj, node)
        assert_teeth_do_not_cross(node)

    FreeCADGui.Selection.clearSelection()
    if FreeCADGui.Control.activeDialog():
        FreeCADGui.Control.closeDialog()
    view = FreeCADGui.getDocument(doc.Name).ActiveView
    view.viewTop()
    view.fitAll()
    FreeCADGui.updateGui()
    path = os.path.join(artifacts, "combs_default.png")
    if os.path.exists(path):
        os.remove(path)
    view.saveImage(path, 800, 600, "White")
    image = np.asarray(Image.open(path).convert("RGB"))
    teeth_pixels = int((np.abs(image.astype(int) - np.array([int(255 * c) for c in comb.TOOTH_COLOR]))
                        .max(axis=-1) <= 40).sum())
    assert teeth_pixels > 500, teeth_pixels


def test_a_scale_factor_above_one_may_reach_past_the_centre(scene):
    """'Unless the user chooses otherwise': the factor multiplies the automatic scale, and
    at 2 the teeth of a half circle reach past its centre."""
    doc = scene
    arc = half_circle(doc, "Arc", 5.0, (0, 0, 0))
    doc.recompute()
    node = comb.show(arc)
    base, tip = teeth(node)
    default = np.linalg.norm(tip - base, axis=1)
    assert (default < 5.0).all()
    comb.set_style(scale=2.0)
    base, tip = teeth(node)
    lengths = np.linalg.norm(tip - base, axis=1)
    np.testing.assert_allclose(lengths, 2 * default, rtol=1e-5)
    assert (lengths > 5.0).all()


def test_same_scale_for_all_combs_makes_teeth_comparable(scene):
    from freecad_workbench.gui.panels.comb import active_comb_panel

    doc = scene
    small = half_circle(doc, "Small", 2.0, (0, 0, 0))
    large = half_circle(doc, "Large", 20.0, (40, 0, 0))
    doc.recompute()
    select(doc, small, large)
    run("FairSplines_CurvatureComb")
    nodes = [comb._combs[(doc.Name, obj.Name, "")] for obj in (small, large)]

    def ratios():
        found = [scale_ratios(obj, node) for obj, node in zip((small, large), nodes)]
        for r in found:  # one absolute scale per comb
            assert len(r) > 100
            np.testing.assert_allclose(r, np.median(r), rtol=1e-3)
        return [float(np.median(r)) for r in found]

    own = ratios()  # off (the default): each comb sized to its own arc, 100 times apart
    assert own[1] / own[0] == pytest.approx(100, rel=1e-2)

    panel = active_comb_panel()
    assert not panel.common.isChecked()
    panel.common.setChecked(True)  # "One scale for all"
    assert preferences.get("CombCommonScale") is True
    common = ratios()
    assert common[0] == pytest.approx(common[1], rel=1e-3)
    assert common[0] == pytest.approx(min(own), rel=1e-3)  # the smaller of the two automatic scales
    for obj, node in zip((small, large), nodes):
        assert_teeth_short_of_centres(obj, node)

    small.ViewObject.Visibility = False  # a hidden comb does not count
    np.testing.assert_allclose(np.median(scale_ratios(large, nodes[1])), own[1], rtol=1e-3)
    small.ViewObject.Visibility = True
    np.testing.assert_allclose(ratios(), common, rtol=1e-3)

    panel.reject()  # Cancel: each comb to its own scale again
    assert preferences.get("CombCommonScale") is False
    np.testing.assert_allclose(ratios(), own, rtol=1e-3)


def test_a_comb_hides_and_shows_with_its_object(scene):
    doc = scene
    arc = ellipse_arc(doc, centre=(0, 0, 0))
    doc.recompute()
    select(doc, arc)
    run("FairSplines_CurvatureComb")
    key = (doc.Name, arc.Name, "")
    node = comb._combs[key]
    assert drawn(doc, node)

    arc.ViewObject.Visibility = False
    assert not drawn(doc, node)
    assert comb.shown() == [key] and not comb.is_drawn(arc)  # still on: it comes back with the object
    arc.ViewObject.Visibility = True
    assert drawn(doc, node) and comb.is_drawn(arc)

    arc.ViewObject.hide()  # the Space bar's way
    assert not drawn(doc, node)
    arc.ViewObject.show()
    assert drawn(doc, node)


def test_a_comb_shown_while_its_object_is_hidden_waits_for_it(scene):
    doc = scene
    arc = half_circle(doc, "Arc", 5.0, (0, 0, 0))
    doc.recompute()
    arc.ViewObject.Visibility = False
    node = comb.show(arc)
    assert not drawn(doc, node)
    arc.ViewObject.Visibility = True
    assert drawn(doc, node)


def test_view_property_toggles_the_comb_and_is_saved_with_the_document(scene, tmp_path):
    from freecad_workbench.features.csr_fit import make_csr_fit

    doc = scene
    sketch = fillet_sketch(doc)  # saved with its comb on
    plain = ellipse_arc(doc)  # saved with its comb off
    vertices = []
    for x, y in ((0, -20), (10, -14), (20, -12), (30, -16), (40, -24)):
        v = doc.addObject("Part::Vertex", "V")
        v.X, v.Y = x, y
        vertices.append(v)
    doc.recompute()
    fit = make_csr_fit(doc, vertices)  # a FairSplines feature, saved with its comb on
    doc.recompute()
    assert "CurvatureComb" not in sketch.ViewObject.PropertiesList

    select(doc, sketch)
    run("FairSplines_CurvatureComb")  # the command adds the property and sets it
    vobj = sketch.ViewObject
    assert vobj.CurvatureComb is True
    assert vobj.getGroupOfProperty("CurvatureComb") == "FairSplines"
    assert vobj.getDocumentationOfProperty("CurvatureComb") == "Show the curvature comb of this object's edges"
    key = (doc.Name, sketch.Name, "")
    assert comb.shown() == [key] and drawn(doc, comb._combs[key])

    vobj.CurvatureComb = False  # as in the property editor
    assert comb.shown() == []
    vobj.CurvatureComb = True
    assert comb.shown() == [key] and drawn(doc, comb._combs[key])
    select(doc, sketch)
    run("FairSplines_CurvatureComb")  # the command toggles the property
    assert vobj.CurvatureComb is False and comb.shown() == []
    select(doc, sketch)
    run("FairSplines_CurvatureComb")
    assert vobj.CurvatureComb is True and comb.shown() == [key]

    comb.show(plain)
    comb.show(fit)
    plain.ViewObject.CurvatureComb = False
    assert not comb.is_shown(plain) and comb.is_shown(fit) and fit.ViewObject.CurvatureComb
    comb.show(plain, "Edge1")  # a single edge's comb: the session's only
    assert plain.ViewObject.CurvatureComb is False

    path = str(tmp_path / "combs.FCStd")
    doc.saveAs(path)
    names = (sketch.Name, plain.Name, fit.Name)
    comb.hide()
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        sketch, plain, fit = (reopened.getObject(name) for name in names)
        assert sketch.ViewObject.CurvatureComb is True and fit.ViewObject.CurvatureComb is True
        assert plain.ViewObject.CurvatureComb is False
        assert sorted(comb.shown()) == sorted((reopened.Name, obj.Name, "") for obj in (sketch, fit))
        for obj in (sketch, fit):
            node = comb._combs[(reopened.Name, obj.Name, "")]
            assert drawn(reopened, node)
            base, tip = teeth(node)
            assert len(base) > 100 and np.linalg.norm(tip - base, axis=1).max() > 0.1
        assert_teeth_short_of_centres(sketch, comb._combs[(reopened.Name, sketch.Name, "")])
    finally:
        comb.hide()
        FreeCAD.closeDocument(reopened.Name)


def torsion_teeth(node):
    """(base, tip) arrays of the torsion teeth a comb node draws."""
    coords = np.array([tuple(p.getValue()) for p in node.coords.point])
    index = np.array(node.torsion_teeth.coordIndex.getValues(), dtype=int).reshape(-1, 3)
    return coords[index[:, 0]], coords[index[:, 1]]


def occt_binormal(edge, point):
    """OCCT's binormal tangent x principal normal at the edge's point nearest to point."""
    curve = edge.Curve
    u = curve.parameter(V(*point))
    t, n = curve.tangent(u)[0], curve.normal(u)
    return np.array(tuple(t.cross(n)))


def test_torsion_comb_of_a_helix_stands_on_the_binormal_at_the_helix_torsion(scene):
    """Issue 28: the comb shows torsion when asked. A helix of radius r and pitch 2 pi c
    has torsion c / (r^2 + c^2) everywhere, positive when it turns right-handed: every
    torsion tooth lies along OCCT's binormal, on its side for the right-handed helix and
    on the other for the left-handed one, all the same length (the longest is a quarter
    of the comb's box diagonal)."""
    from freecad_workbench.gui.panels.comb import active_comb_panel

    doc = scene
    r, c = 10.0, 3.0
    right = feature(doc, "Right", [Part.makeHelix(2 * math.pi * c, 4 * math.pi * c, r).Edges[0]])
    left = feature(doc, "Left", [Part.makeHelix(2 * math.pi * c, 4 * math.pi * c, r, 0, True).Edges[0]])
    left.Placement.Base = V(40, 0, 0)
    arc = half_circle(doc, "Arc", 5.0, (0, -30, 0))
    doc.recompute()
    select(doc, right, left, arc)
    run("FairSplines_CurvatureComb")
    nodes = {obj.Name: comb._combs[(doc.Name, obj.Name, "")] for obj in (right, left, arc)}
    for node in nodes.values():  # off by default
        assert len(node.torsion_teeth.coordIndex.getValues()) == 0

    panel = active_comb_panel()
    assert not panel.torsion.isChecked()
    panel.torsion.setChecked(True)
    assert preferences.get("CombTorsion") is True
    tau = c / (r * r + c * c)
    for obj, sign in ((right, 1.0), (left, -1.0)):
        base, tip = torsion_teeth(nodes[obj.Name])
        assert len(base) > 100
        tooth = tip - base
        length = np.linalg.norm(tooth, axis=1)
        # Constant torsion, to the accuracy of OCCT's B-spline approximation of the helix
        # (Part.makeHelix: its torsion varies by 6.5e-4 relatively).
        np.testing.assert_allclose(length, length.max(), rtol=2e-3)
        diagonal = np.linalg.norm(base.max(axis=0) - base.min(axis=0))
        assert length.max() == pytest.approx(comb.AUTO_LENGTH * diagonal, rel=1e-6)  # coin keeps floats
        edge = obj.Shape.Edges[0]
        for b, d in zip(base, tooth):
            binormal = occt_binormal(edge, b)
            assert np.dot(d, binormal) == pytest.approx(sign * np.linalg.norm(d), rel=1e-6)
        assert tau > 0
    base, _ = torsion_teeth(nodes[arc.Name])  # planar: no torsion teeth
    assert len(base) == 0

    panel.reject()  # Cancel: off again
    assert preferences.get("CombTorsion") is False
    assert len(nodes[right.Name].torsion_teeth.coordIndex.getValues()) == 0


def test_torsion_comb_changes_sides_where_the_torsion_changes_sign(scene):
    """The quartic c(t) = (t, t^2, t^4), t in [-1, 1], has det(c', c'', c''') = 48 t: its
    torsion is negative for t < 0 and positive for t > 0. Built as an exact Bezier curve
    (the degree-4 polynomial interpolated at 5 points), its torsion teeth point against
    OCCT's binormal before x = 0 and along it after."""
    doc = scene
    t = np.linspace(-1.0, 1.0, 5)
    points = np.column_stack([t, t**2, t**4]) * 20.0
    bernstein = np.array([[math.comb(4, k) * ((s + 1) / 2) ** k * ((1 - s) / 2) ** (4 - k) for k in range(5)]
                          for s in t])
    poles = np.linalg.solve(bernstein, points)
    bezier = Part.BezierCurve()
    bezier.setPoles([V(*p) for p in poles])
    assert (bezier.value(0.75) - V(10, 5, 1.25)).Length < 1e-9  # t = 0.5
    quartic = feature(doc, "Quartic", [bezier.toShape()])
    doc.recompute()
    comb.set_style(torsion=True)
    node = comb.show(quartic)
    base, tip = torsion_teeth(node)
    edge = quartic.Shape.Edges[0]
    signs = np.array([np.sign(np.dot(d, occt_binormal(edge, b))) for b, d in zip(base, tip - base)])
    x = base[:, 0]
    assert (signs[x < -1.0] == -1).all() and (signs[x > 1.0] == 1).all()
    assert (x < -1.0).sum() > 50 and (x > 1.0).sum() > 50
