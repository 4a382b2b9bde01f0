"""Surface analysis in the FreeCAD GUI (issue 27): the curvature map of any shape.

The referee for the colours is an independent fw.curvature_map of the object's shape and
the closed forms of a filleted box (mean curvature 0 on the walls, 1/(2r) on the edge
fillets, 1/r on the corner balls): the colours are read back from the coin nodes the map
draws, the legend's texts from its SoText2 nodes."""
import numpy as np
import pytest

import FreeCAD
import Part

import freecad_workbench as fw
from freecad_workbench.gui import curvature_map as cm

V = FreeCAD.Vector
RADIUS = 4.0  # of the fillets
BLUE, GREEN, RED = (0.0, 0.0, 1.0), (0.0, 0.8, 0.0), (1.0, 0.0, 0.0)


def gui():
    import FreeCADGui

    return FreeCADGui


def run(name):
    gui().runCommand(name)
    gui().updateGui()


@pytest.fixture
def scene(doc):
    g = gui()
    FreeCAD.setActiveDocument(doc.Name)
    g.ActiveDocument = g.getDocument(doc.Name)
    g.Selection.clearSelection()
    yield doc
    g.Selection.clearSelection()
    cm.hide()
    if g.Control.activeDialog():
        g.Control.closeDialog()
    g.updateGui()


def rounded_box(doc, size=20.0, radius=RADIUS):
    box = Part.makeBox(size, size, size)
    obj = doc.addObject("Part::Feature", "Rounded")
    obj.Shape = box.makeFillet(radius, box.Edges)
    obj.Placement = FreeCAD.Placement(V(30, -5, 2), FreeCAD.Rotation(V(0, 0, 1), 30))
    doc.recompute()
    return obj


def nodes_named(doc, name):
    from pivy import coin

    search = coin.SoSearchAction()
    search.setName(coin.SbName(name))
    search.setInterest(coin.SoSearchAction.ALL)
    search.setSearchingAll(True)
    search.apply(gui().getDocument(doc.Name).ActiveView.getSceneGraph())
    return search.getPaths().getLength()


def test_curvature_map_colours_match_the_values_and_turn_off_restores_the_look(scene):
    from freecad_workbench.gui.panels.curvature_map import active_map_panel

    obj = rounded_box(scene)
    mode = obj.ViewObject.DisplayMode
    gui().Selection.addSelection(obj)
    run("FairSplines_CurvatureMap")
    node = cm.map_of(obj)
    assert node is not None and nodes_named(scene, "FairSplinesCurvatureMap") == 1
    assert obj.ViewObject.DisplayMode == "Wireframe"
    panel = active_map_panel()
    assert panel is not None
    panel.quantity.setCurrentIndex(cm.QUANTITIES.index("mean"))
    mesh = node.data
    panel.set_range(0.0, 1.0 / RADIUS)
    gui().updateGui()
    assert node.data is mesh, "a range change re-meshed"

    points, rgb = node.vertex_colours()
    reference = fw.curvature_map(obj.Shape, "mean")  # placed: the map is drawn where the object is
    np.testing.assert_allclose(points, reference.points, atol=1e-9)
    np.testing.assert_allclose(rgb, cm.colours(reference.values, 0.0, 1.0 / RADIUS), atol=1e-6)
    for value, colour in ((0.0, BLUE), (0.5 / RADIUS, GREEN), (1.0 / RADIUS, RED)):
        at = np.abs(reference.values - value) < 1e-9
        assert at.sum() > 20, f"no vertices with mean curvature {value}"
        np.testing.assert_allclose(rgb[at], np.tile(colour, (at.sum(), 1)), atol=1e-6)
    vertex = Part.Vertex(V(*points[len(points) // 2]))
    assert obj.Shape.distToShape(vertex)[0] < 1e-6

    title, ticks = cm.legend_texts(scene)
    assert title == "Mean curvature (1/mm)"
    assert [float(t) for t in ticks] == pytest.approx(np.linspace(0.0, 1.0 / RADIUS, 5), rel=1e-3)

    # the value under the cursor: the top wall's centre in the top view is flat
    view = gui().ActiveDocument.ActiveView
    view.viewTop()
    view.fitAll()
    gui().updateGui()
    centre = obj.Placement.multVec(V(10, 10, 20))
    hit = cm.probe_at(scene, view.getPointOnScreen(centre))
    assert hit is not None and hit[0] is obj
    assert hit[1] == pytest.approx(0.0, abs=1e-9) and np.allclose(hit[2], tuple(centre), atol=0.2)
    edge = obj.Placement.multVec(V(10, 20 - RADIUS * (1 - np.cos(0.3)), 20 - RADIUS * (1 - np.cos(0.3))))
    hit = cm.probe_at(scene, view.getPointOnScreen(edge))
    assert hit is not None and hit[1] == pytest.approx(0.5 / RADIUS, rel=1e-3)

    # the automatic range stays inside the values, and a recompute re-meshes
    panel.set_range()
    lower, upper = node.range
    assert 0.0 <= lower < upper <= 1.0 / RADIUS + 1e-9
    box = Part.makeBox(20, 20, 20)
    obj.Shape = box.makeFillet(2.0, box.Edges)
    scene.recompute()
    for _ in range(3):
        gui().updateGui()
    assert node.data is not mesh and node.data.values.max() == pytest.approx(0.5, rel=1e-6)

    panel.turn_off()
    gui().updateGui()
    assert cm.map_of(obj) is None and not cm.shown()
    assert nodes_named(scene, "FairSplinesCurvatureMap") == 0
    assert cm.legend_texts(scene) is None
    assert obj.ViewObject.DisplayMode == mode
    assert not gui().Control.activeDialog()


def test_curvature_map_of_one_face_greys_the_others(scene):
    obj = scene.addObject("Part::Feature", "Ball")
    obj.Shape = Part.makeCylinder(5, 10)
    scene.recompute()
    gui().Selection.addSelection(obj, "Face1")  # the cylinder's side
    run("FairSplines_CurvatureMap")
    node = cm.map_of(obj)
    cm.set_quantity(obj, "max")
    _, rgb = node.vertex_colours()
    side = np.zeros(len(node.data.points), dtype=bool)
    side[node.data.triangles[node.data.face == 1].ravel()] = True
    assert np.allclose(rgb[~side], cm.OTHER_FACES)
    assert node.data.values[side] == pytest.approx(0.2)  # 1/r on the side, wherever it is
    assert cm.legend_texts(scene)[0] == "Maximum curvature (1/mm)"
    run("FairSplines_CurvatureMap")  # again on the mapped object: off
    assert cm.map_of(obj) is None


def test_continuity_table_and_edge_colours_match_the_verdicts_and_a_row_selects_its_edge(scene):
    from freecad_workbench.gui import continuity
    from freecad_workbench.gui.panels.continuity import active_continuity_panel

    box = Part.makeBox(20, 20, 20)
    obj = scene.addObject("Part::Feature", "Part")
    obj.Shape = box.makeFillet(3.0, box.Edges[:4])  # filleted edges G1 to the walls, the others G0 at 90 degrees
    scene.recompute()
    gui().Selection.addSelection(obj)
    run("FairSplines_CheckContinuity")
    panel = active_continuity_panel()
    assert panel is not None and nodes_named(scene, "FairSplinesContinuity") == 1
    records = fw.edge_continuity(obj.Shape)
    verdicts = [r.continuity for r in records]
    assert {"G0", "G1"} <= set(verdicts)
    table = panel.table
    assert table.rowCount() == len(records)
    columns = [table.horizontalHeaderItem(k).text() for k in range(table.columnCount())]
    assert columns == ["Edge", "Faces", "Gap", "Angle", "Jump", "Verdict"]
    for row, r in enumerate(records):
        assert table.item(row, 0).text() == r.edge[4:]
        assert table.item(row, 1).text() == ", ".join(f[4:] for f in r.faces)
        assert float(table.item(row, 3).text()) == pytest.approx(r.angle, rel=0.01, abs=1e-3)
        assert table.item(row, 5).text() == r.continuity
    from pivy import coin

    bindings = [panel.check.node.root.getChild(k) for k in range(panel.check.node.root.getNumChildren())]
    bindings = [b for b in bindings if b.isOfType(coin.SoMaterialBinding.getClassTypeId())]
    assert [b.value.getValue() for b in bindings] == [coin.SoMaterialBinding.PER_FACE]  # a colour a polyline
    drawn = panel.check.node.edge_colours()
    assert len(drawn) == len(records)
    for (points, colour), r in zip(drawn, records):
        assert colour == pytest.approx(continuity.VERDICTS[r.continuity][0], abs=1e-6)
        edge = obj.Shape.Edges[int(r.edge[4:]) - 1]
        assert edge.distToShape(Part.Vertex(V(*points[len(points) // 2])))[0] < 1e-6
    kink = verdicts.index("G0")
    panel.choose(kink)
    gui().updateGui()
    selection = gui().Selection.getSelectionEx()
    assert [s.Object.Name for s in selection] == [obj.Name]
    assert list(selection[0].SubElementNames) == [records[kink].edge]
    mark = panel.check.node.mark_points()
    assert len(mark) == 1 and np.allclose(mark[0], tuple(records[kink].angle_point), atol=1e-6)
    panel.angle.setValue(120.0)  # every kink within the tolerance now: no G0 left
    gui().updateGui()
    assert "G0" not in [panel.table.item(k, 5).text() for k in range(panel.table.rowCount())]
    panel.reject()
    gui().updateGui()
    assert nodes_named(scene, "FairSplinesContinuity") == 0


@pytest.mark.parametrize("size", [0.05, 2000.0], ids=["small", "large"])
def test_zebra_on_any_shape_adds_and_removes_its_node(scene, size):
    from freecad_workbench.gui import zebra_shape
    from freecad_workbench.gui.panels.zebra_shape import active_zebra_panel

    obj = scene.addObject("Part::Feature", "Ball")
    obj.Shape = Part.makeSphere(size)
    box = scene.addObject("Part::Feature", "Box")
    box.Shape = Part.makeBox(size, size, size, V(2 * size, 0, 0))
    scene.recompute()
    mode = obj.ViewObject.DisplayMode
    gui().Selection.addSelection(obj)
    gui().Selection.addSelection(box)
    run("FairSplines_Zebra")
    assert nodes_named(scene, "FairSplinesShapeZebra") == 2
    node = zebra_shape.node_of(obj)
    points, normals, _ = node.mesh
    assert len(points) > 500
    # The normals point out of the sphere along the radial directions: evaluated on the face
    # at the mesh's vertices, and at midpoints of split edges the normalised mean of their
    # ends' (radial too on a sphere); 2e-7 rad at the poles (the limit from just inside).
    radial = points / np.linalg.norm(points, axis=1)[:, None]
    assert np.min(np.einsum("ij,ij->i", normals, radial)) > np.cos(1e-6)
    panel = active_zebra_panel()
    panel.mode.setCurrentIndex(1)  # isophotes
    gui().updateGui()
    s = np.array([p[0] for p in node.texcoords.point])  # by index: pivy 0.6.10's getValue() is a pointer
    np.testing.assert_allclose(s, np.degrees(np.arccos(np.clip(normals[:, 2], -1, 1))) / 180.0, atol=1e-9)
    run("FairSplines_Zebra")  # the same selection again: off
    assert nodes_named(scene, "FairSplinesShapeZebra") == 0
    assert obj.ViewObject.DisplayMode == mode and not zebra_shape.shown()


def test_combs_on_isolines_and_sections_of_a_face(scene):
    from freecad_workbench.gui import comb, iso_combs
    from freecad_workbench.gui.panels.iso_combs import active_iso_panel

    obj = scene.addObject("Part::Feature", "Can")
    obj.Shape = Part.makeCylinder(5, 20)
    scene.recompute()
    gui().Selection.addSelection(obj, "Face1")
    run("FairSplines_IsoCombs")
    panel = active_iso_panel()
    assert panel is not None and nodes_named(scene, "FairSplinesIsoCombs") == 1
    panel.lines.setCurrentIndex(1)  # V isolines of a cylinder's side: circles of radius 5
    panel.count.setValue(3)
    gui().updateGui()
    edges = iso_combs.current()[-1]
    assert len(edges) == 3 and all(e.Curve.Radius == pytest.approx(5.0) for e in edges)
    node = iso_combs.current()[0]
    tips = np.array([tuple(p.getValue()) for p in node.coords.point])
    unit = comb.comb_lines(edges[0], 1.0, iso_combs.SAMPLES)
    assert np.allclose(np.abs(unit.kappa), 0.2)
    assert len(tips) == 2 * 3 * len(unit.base)
    panel.lines.setCurrentIndex(5)  # sections across Z: circles too
    gui().updateGui()
    sections = iso_combs.current()[-1]
    assert len(sections) >= 3 and all(e.Curve.Radius == pytest.approx(5.0) for e in sections)
    panel.reject()
    gui().updateGui()
    assert nodes_named(scene, "FairSplinesIsoCombs") == 0
