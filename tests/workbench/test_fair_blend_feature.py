"""The Fair blend feature, headless: G2 by default between edges (curvatures matched as OCCT
evaluates the edges), the warning state where no monotone curve exists, following sources,
save/reopen/recompute, and the migration of Monotone blend documents (version 1)."""

import numpy as np
import pytest

import FreeCAD
import Part

import freecad_workbench as fw
from freecad_workbench.features.fair_blend import FairBlend, make_fair_blend
from freecad_workbench.features.monotone_blend import MonotoneBlend, make_monotone_blend
from tests.scenes import line_into_arc

V = FreeCAD.Vector


def poles(obj):
    return np.array([tuple(p) for p in obj.Shape.Edges[0].Curve.getPoles()])


def signed_kappa(curve, u):
    d1, d2 = curve.getD2(u)[1:3]
    return d1.cross(d2).z / d1.Length**3


@pytest.fixture
def line_and_arc(doc):
    return line_into_arc(doc)


def test_g2_blend_of_a_line_into_an_arc_matches_both_curvatures_monotonically(doc, line_and_arc):
    lead, arc = line_and_arc
    blend = make_fair_blend(doc, (lead, "Edge1"), (arc, "Edge1"))
    assert isinstance(blend.Proxy, FairBlend) and blend.Proxy.Type == "FairBlend"
    assert (blend.Continuity, blend.Method, blend.Status) == ("G2", "fair", "ok")
    curve = blend.Shape.Edges[0].Curve
    u0, u1 = curve.FirstParameter, curve.LastParameter
    assert curve.value(u0).isEqual(V(0, 0, 0), 1e-12)
    end = arc.Shape.Edges[0].valueAt(arc.Shape.Edges[0].FirstParameter)
    assert curve.value(u1).distanceToPoint(end) <= 1e-12 * end.Length
    # The edges' own curvatures, as OCCT evaluates them: 0 on the line, 1/10 on the arc.
    assert abs(signed_kappa(curve, u0)) <= 1e-12
    assert signed_kappa(curve, u1) == pytest.approx(0.1, rel=1e-9)
    kappa = [signed_kappa(curve, u) for u in np.linspace(u0, u1, 2000)]
    assert np.all(np.diff(kappa) >= -1e-9 * max(kappa))
    assert fw.check_monotone_curvature(curve).monotone
    assert blend.Curvature.startswith("monotone: the curvature increases")


def test_ends_without_a_monotone_curve_show_the_fairest_with_a_warning(doc, line_and_arc):
    lead, arc = line_and_arc
    blend = make_fair_blend(doc, (lead, "Edge1"), (arc, "Edge1"), end_end="first")
    good = poles(blend)
    # Move the arc below the lead-in's line: turning left from a straight start cannot reach it.
    arc.Placement = FreeCAD.Placement(V(0, -40, 0), FreeCAD.Rotation())
    doc.recompute()
    assert blend.Status.startswith("warning: ") and "no monotone-curvature curve meets" in blend.Status
    moved = poles(blend)  # not a stale curve: the fairest for the new ends
    assert moved.shape != good.shape or not np.allclose(moved, good)
    curve = blend.Shape.Edges[0].Curve
    assert signed_kappa(curve, curve.LastParameter) == pytest.approx(0.1, rel=1e-9)
    assert blend.Curvature.startswith("not monotone")
    arc.Placement = FreeCAD.Placement()
    doc.recompute()
    assert blend.Status == "ok"
    np.testing.assert_allclose(poles(blend), good, rtol=0, atol=1e-12)


def test_g1_and_the_papers_method(doc, line_and_arc):
    lead, arc = line_and_arc
    blend = make_fair_blend(doc, (lead, "Edge1"), (arc, "Edge1"), continuity="G1")
    arc_edge = arc.Shape.Edges[0]
    expected, report = fw.fair_blend_solution(
        V(0, 0, 0), V(1, 0, 0), arc_edge.valueAt(arc_edge.FirstParameter), arc_edge.tangentAt(arc_edge.FirstParameter)
    )
    assert blend.Status == "ok" and report.continuity == "G1"
    np.testing.assert_array_equal(poles(blend), np.array([tuple(p) for p in expected.getPoles()]))
    blend.Method = "paper"  # Algorithm 2: one cubic of 5 poles, if the family has one
    doc.recompute()
    assert blend.Status.startswith("no monotone-curvature curve") or len(poles(blend)) == 5
    blend.Continuity = "G2"
    doc.recompute()
    assert "Algorithm 2 is G1 only" in blend.Status


def test_the_property_editor_shows_directions_and_curvatures_only_where_they_are_used(doc, line_and_arc):
    lead, arc = line_and_arc
    blend = make_fair_blend(doc, (lead, "Edge1"), (arc, "Edge1"))
    for name in ("StartDirection", "EndDirection", "StartCurvature", "EndCurvature"):
        assert blend.getEditorMode(name) == ["Hidden"], name  # the edges give their own
    a = doc.addObject("Part::Vertex", "A")
    doc.recompute()
    blend.Start = a
    blend.StartDirection = V(1, 0, 0)
    doc.recompute()
    assert blend.getEditorMode("StartDirection") == [] and blend.getEditorMode("StartCurvature") == []
    assert blend.getEditorMode("EndDirection") == ["Hidden"]
    blend.Continuity = "G1"
    doc.recompute()
    assert blend.getEditorMode("StartCurvature") == ["Hidden"] and blend.getEditorMode("StartDirection") == []


def test_vertex_ends_take_their_directions_and_curvatures_from_properties(doc):
    a = doc.addObject("Part::Vertex", "A")
    b = doc.addObject("Part::Vertex", "B")
    b.X, b.Y = 2.0, 1.0
    doc.recompute()
    blend = make_fair_blend(doc, a, b, start_direction=(1, 0, 0), end_direction=(0, 1, 0),
                            start_curvature=0.2, end_curvature=2.0)
    assert blend.Status == "ok", blend.Status
    curve = blend.Shape.Edges[0].Curve
    assert signed_kappa(curve, curve.FirstParameter) == pytest.approx(0.2, rel=1e-9)
    assert signed_kappa(curve, curve.LastParameter) == pytest.approx(2.0, rel=1e-9)


def test_save_close_reopen_recompute_gives_identical_poles(doc, line_and_arc, tmp_path):
    lead, arc = line_and_arc
    blend = make_fair_blend(doc, (lead, "Edge1"), (arc, "Edge1"))
    before = poles(blend)
    path = str(tmp_path / "fair.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        blend = reopened.getObject("FairBlend")
        assert isinstance(blend.Proxy, FairBlend) and (blend.Version, blend.Continuity) == (FairBlend.VERSION, "G2")
        blend.touch()
        reopened.recompute()
        np.testing.assert_array_equal(poles(blend), before)
        reopened.getObject("Arc").Placement = FreeCAD.Placement(V(1, 0, 0), FreeCAD.Rotation())  # links survived
        reopened.recompute()
        assert blend.Status == "ok" and not np.allclose(poles(blend), before)
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_a_monotone_blend_document_of_version_1_opens_and_recomputes_unchanged(doc, tmp_path):
    """What the Monotone blend saved before fair blends: no Continuity, Method fairest or grid."""
    lead = doc.addObject("Part::Feature", "Lead")
    lead.Shape = Part.LineSegment(V(-20, 0, 0), V(0, 0, 0)).toShape()
    out = doc.addObject("Part::Feature", "Out")
    out.Shape = Part.LineSegment(V(30, 15, 0), V(38, 21, 0)).toShape()
    doc.recompute()
    old = {}
    for method in ("fairest", "grid"):
        blend = make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"), method=method, name=f"Old_{method}")
        old[method] = poles(blend)
        for name in ("Continuity", "StartCurvature", "EndCurvature", "Method"):
            blend.removeProperty(name)
        blend.addProperty("App::PropertyEnumeration", "Method", "Monotone blend", "")
        blend.Method = ["fairest", "grid"]
        blend.Method = method
        blend.Version = 1
    path = str(tmp_path / "monotone_v1.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        for method, expected_method in (("fairest", "paper"), ("grid", "grid")):
            blend = reopened.getObject(f"Old_{method}")
            assert isinstance(blend.Proxy, MonotoneBlend)
            assert (blend.Version, blend.Continuity, blend.Method) == (FairBlend.VERSION, "G1", expected_method)
            blend.touch()
            reopened.recompute()
            assert blend.Status == "ok"
            np.testing.assert_array_equal(poles(blend), old[method])
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_factory_rejects_unknown_continuity(doc, line_and_arc):
    lead, arc = line_and_arc
    with pytest.raises(fw.InputError, match="continuity"):
        make_fair_blend(doc, (lead, "Edge1"), (arc, "Edge1"), continuity="G3")


def test_edges_of_two_solids_in_space_get_a_g2_blend_in_space(doc):
    """Issue 28: two edges of 3D models that share no plane (circles of two skew cylinders)
    are blended in space, G2 to OCCT's curvature vectors of the edges; the feature is ok."""
    a = doc.addObject("Part::Cylinder", "A")
    a.Radius, a.Height = 2.0, 5.0
    b = doc.addObject("Part::Cylinder", "B")
    b.Radius, b.Height = 1.5, 4.0
    b.Placement = FreeCAD.Placement(V(9, 3, 2), FreeCAD.Rotation(V(1, -1, 0.2), 70))
    doc.recompute()

    def circle(obj, top):
        edges = [(i, e) for i, e in enumerate(obj.Shape.Edges) if isinstance(e.Curve, Part.Circle)]
        i, _ = max(edges, key=lambda ie: ie[1].Curve.Center.z) if top else edges[0]
        return f"Edge{i + 1}"

    blend = make_fair_blend(doc, (a, circle(a, True)), (b, circle(b, False)))
    assert blend.Status == "ok" or blend.Status.startswith("warning:")
    curve = blend.Shape.Edges[0].Curve
    edge_a = a.Shape.getElement(circle(a, True))
    u0, u1 = curve.FirstParameter, curve.LastParameter
    nearest = min((edge_a.FirstParameter, edge_a.LastParameter),
                  key=lambda u: (edge_a.valueAt(u) - curve.value(u0)).Length)
    assert (edge_a.valueAt(nearest) - curve.value(u0)).Length <= 1e-9 * 10
    d1, d2 = (np.array(v) for v in curve.getD2(u0)[1:3])
    k_blend = np.cross(np.cross(d1, d2), d1) / np.linalg.norm(d1) ** 4
    e1, e2 = np.array(edge_a.derivative1At(nearest)), np.array(edge_a.derivative2At(nearest))
    k_edge = np.cross(np.cross(e1, e2), e1) / np.linalg.norm(e1) ** 4
    assert np.linalg.norm(k_blend - k_edge) <= 1e-6 * np.linalg.norm(k_edge)
    edge_b = b.Shape.getElement(circle(b, False))
    assert min((edge_b.valueAt(u) - curve.value(u1)).Length for u in (edge_b.FirstParameter, edge_b.LastParameter)) \
        <= 1e-9 * 20
