"""The Blend basic shape command in a real FreeCAD GUI under Xvfb: the command creates the
feature in one undo step and opens its panel, the panel drives the feature live (kind,
dimensions, uniform counts or typed lists, method, naive), Cancel restores, the shell is
shown with zebra stripes; screenshots in out/test-artifacts/."""
import math
import os

import numpy as np
import pytest

import FreeCAD

NAME = "FairSplines_BlendBasicShape"


def gui():
    import FreeCADGui

    return FreeCADGui


def run(name):
    """Run a command and let the panel it opens afterwards (a zero-delay timer) appear."""
    g = gui()
    g.runCommand(name)
    for _ in range(3):
        g.updateGui()


def panel_of(obj):
    return getattr(obj.ViewObject.Proxy, "panel", None)


def screenshot(doc, path):
    from PIL import Image

    g = gui()
    view = g.getDocument(doc.Name).ActiveView
    view.viewIsometric()
    view.fitAll()
    g.updateGui()
    if os.path.exists(path):
        os.remove(path)
    view.saveImage(path, 800, 600, "White")
    return np.asarray(Image.open(path).convert("RGB"))


def stripe_pixels(image):
    """(dark, white) pixel counts: the zebra stripes on the white background."""
    dark = int((image.max(axis=-1) < 60).sum())
    white = int((image.min(axis=-1) > 215).sum())
    return dark, white


def c2_jump(shell, samples=5):
    """Largest relative jump of the derivatives across the shared edges of a shell of patches
    over [0,1]^2, by OCCT's evaluation (getDN on both sides): C2 across a joint means that the
    first and second derivatives across it agree up to the ratio beta of the two patches'
    parameter lengths (beta and beta^2), one beta all along the joint."""
    import Part

    worst = 0.0

    def side(surface, point):  # (across u or v, at its end 1 or its start 0), and (u, v)
        u, v = surface.parameter(point)
        for across, t in ((0, u), (1, v)):
            for end in (0, 1):
                if abs(t - end) < 1e-7:
                    return across, end, (u, v)
        raise AssertionError(f"{point} is on no side of its face ({u}, {v})")

    for edge in shell.Edges:
        if edge.Degenerated:
            continue
        owners = shell.ancestorsOfType(edge, Part.Face)
        if len(owners) != 2:
            continue
        a, b = (f.Surface for f in owners)
        first, last = edge.ParameterRange
        joint = []
        for t in np.linspace(first, last, samples + 2)[1:-1]:
            point = edge.valueAt(t)
            (ax, aend, auv), (bx, bend, buv) = side(a, point), side(b, point)
            sign = 1.0 if aend != bend else -1.0  # the parameters across run the same way, or not
            da = [a.getDN(*auv, *((k, 0) if ax == 0 else (0, k))) for k in (1, 2)]
            db = [b.getDN(*buv, *((k, 0) if bx == 0 else (0, k))) for k in (1, 2)]
            joint.append((da, db, sign))
        da, db, sign = joint[len(joint) // 2]
        beta = sign * db[0].dot(da[0]) / da[0].dot(da[0])
        for da, db, sign in joint:
            scale = max(da[0].Length, da[1].Length)
            worst = max(worst, (db[0] - da[0] * (sign * beta)).Length / scale,
                        (db[1] - da[1] * beta ** 2).Length / scale)
    return worst


@pytest.fixture
def scene(doc):
    """An active document with undo; afterwards no dialog."""
    g = gui()
    doc.UndoMode = 1
    FreeCAD.setActiveDocument(doc.Name)
    g.ActiveDocument = g.getDocument(doc.Name)
    g.Selection.clearSelection()
    yield doc
    if g.Control.activeDialog():
        gui_doc = g.getDocument(doc.Name)
        vp = gui_doc.getInEdit() if gui_doc is not None else None
        panel = getattr(getattr(vp, "Proxy", None), "panel", None) if vp is not None else None
        if panel is not None:
            panel.reject()
        else:
            g.Control.closeDialog()
    g.updateGui()


def new_blend(doc):
    before = {o.Name for o in doc.Objects}
    assert gui().Command.get(NAME).isActive()
    run(NAME)
    created = [o for o in doc.Objects if o.Name not in before]
    assert len(created) == 1
    return created[0]


def test_command_creates_a_blend_in_one_undo_step_and_opens_its_panel(scene):
    from freecad_workbench.gui.panels.blend_shape import BlendShapePanel
    from freecad_workbench.gui.view_providers import ViewProviderBlendShape

    doc = scene
    blend = new_blend(doc)
    assert blend.Status == "ok" and blend.Kind == "Sphere zone" and blend.Shape.isValid()
    vp = blend.ViewObject.Proxy
    assert isinstance(vp, ViewProviderBlendShape)
    assert blend.ViewObject.DisplayMode == "Zebra" and vp.zebra.vertex_count > 1000
    assert isinstance(panel_of(blend), BlendShapePanel) and gui().Control.activeDialog()
    assert doc.UndoNames[0] == "Create blend basic shape"
    panel_of(blend).accept()
    gui().updateGui()
    assert not gui().Control.activeDialog()
    name = blend.Name
    doc.undo()
    assert doc.getObject(name) is None


def test_panel_drives_the_blend_live_and_shows_zebra_seams(scene, artifacts):
    doc = scene
    blend = new_blend(doc)
    panel = panel_of(blend)
    undo_count = len(doc.UndoNames)

    # kind and a dimension, through the widgets
    panel.kind.setCurrentIndex(3)  # Torus
    assert blend.Kind == "Torus" and blend.Status == "ok" and blend.MajorRadius == 20
    panel.widgets["MinorRadius"].setValue(7.0)
    assert blend.MinorRadius == 7.0 and blend.Status == "ok"
    # uniform counts
    panel.widgets["AroundCount"].setValue(8)
    assert blend.Patches == "basic 24, transition 8, freeform 8"
    # the lists, typed as comma-separated degrees (spelled out from the counts first)
    panel.uniform.setChecked(False)
    assert not blend.Uniform and len(blend.AnglesU) == 9 and "AnglesV" in panel.widgets
    assert panel.widgets["AnglesU"].text().startswith("0, 45, 90")
    panel.widgets["AnglesU"].setText("0, 30, 100, 170, 250, 360")
    panel.widgets["AnglesU"].editingFinished.emit()
    assert list(blend.AnglesU) == [0, 30, 100, 170, 250, 360] and blend.Status == "ok"
    panel.method.setCurrentIndex(1)  # sigma
    assert blend.Method == "sigma" and blend.Status == "ok"
    gui().updateGui()
    c2 = screenshot(doc, os.path.join(artifacts, "blend_torus_sigma_zebra.png"))
    dark, white = stripe_pixels(c2)
    assert dark > 5000 and white > 5000, (dark, white)  # not blank: stripes on the shell
    assert blend.ViewObject.Proxy.zebra.vertex_count > 1000

    panel.continuity.setCurrentIndex(1)  # C1: Section 5, (4,2) double strip
    assert blend.Continuity == "C1" and blend.Status == "ok", blend.Status
    assert "transition 20" in blend.Patches  # five arcs, two quartics each, two strip rows
    gui().updateGui()
    c1 = screenshot(doc, os.path.join(artifacts, "blend_torus_c1_zebra.png"))
    assert stripe_pixels(c1)[0] > 5000
    panel.continuity.setCurrentIndex(0)
    assert blend.Continuity == "C2"

    panel.naive.setChecked(True)
    assert blend.Naive and blend.Status == "ok"
    gui().updateGui()
    naive = screenshot(doc, os.path.join(artifacts, "blend_torus_naive_zebra.png"))
    assert not np.array_equal(naive, c2)

    # bad input: the message in the panel, the last good shape kept
    points = [tuple(v.Point) for v in blend.Shape.Vertexes]
    panel.set_list_text("AnglesU", "0, 100, 90, 360")
    expected = "AnglesU: value 2 (90°) must be greater than value 1 (100°)"  # in the degrees typed
    assert blend.Status == expected and expected in panel.status_label.text()
    assert [tuple(v.Point) for v in blend.Shape.Vertexes] == points
    panel.set_list_text("AnglesU", "0, x, 360")
    assert "not a number" in panel.status_label.text()
    panel.set_list_text("AnglesU", "0, 120, 240, 360")
    assert blend.Status == "ok"

    panel.accept()
    gui().updateGui()
    assert not gui().Control.activeDialog()
    assert len(doc.UndoNames) == undo_count + 1 and doc.UndoNames[0] == "Edit blend basic shape"


def test_panel_cancel_restores_the_blend(scene):
    doc = scene
    blend = new_blend(doc)
    panel = panel_of(blend)
    points = [tuple(v.Point) for v in blend.Shape.Vertexes]
    panel.set_kind("Cone")
    panel.set_dimension("Slope", -0.2)
    panel.set_uniform(False)
    assert blend.Kind == "Cone" and not blend.Uniform
    panel.reject()
    gui().updateGui()
    assert blend.Kind == "Sphere zone" and blend.Uniform and blend.Status == "ok"
    assert [tuple(v.Point) for v in blend.Shape.Vertexes] == points
    assert not gui().Control.activeDialog()


def test_panel_switches_to_a_revolution_and_edits_its_profile_fractions(scene):
    # Issue 32: the Revolution kind (its default parabola profile while none is linked) in
    # the panel: uniform rows, then the fractions as a list; Cancel restores the sphere.
    doc = scene
    blend = new_blend(doc)
    panel = panel_of(blend)
    panel.set_kind("Revolution")
    assert blend.Kind == "Revolution" and blend.Status == "ok", blend.Status
    assert "basic 18" in blend.Patches
    panel.set_uniform(False)
    assert "ProfileFractions" in panel.widgets
    panel.set_list_text("ProfileFractions", "0, 0.5, 1")
    assert blend.Status == "ok" and "basic 12" in blend.Patches
    panel.reject()
    gui().updateGui()
    assert blend.Kind == "Sphere zone" and blend.Status == "ok"


def test_double_click_opens_the_panel_and_error_shows_the_error_icon(scene):
    from freecad_workbench.gui import icon_path
    from freecad_workbench.gui.panels.blend_shape import BlendShapePanel

    doc = scene
    blend = new_blend(doc)
    panel_of(blend).accept()
    gui().updateGui()
    vp = blend.ViewObject.Proxy
    assert vp.getIcon() == icon_path(NAME)
    blend.Radius = 0
    doc.recompute()
    assert blend.Status != "ok" and vp.getIcon() == icon_path(NAME + "Error")
    blend.Radius = 10
    doc.recompute()
    assert vp.doubleClicked(blend.ViewObject)
    gui().updateGui()
    assert isinstance(panel_of(blend), BlendShapePanel) and gui().Control.activeDialog()
    panel_of(blend).reject()
    gui().updateGui()


def test_saved_blend_reopens_with_its_zebra_view(scene, tmp_path):
    from freecad_workbench.gui.view_providers import ViewProviderBlendShape

    doc = scene
    blend = new_blend(doc)
    panel_of(blend).accept()
    gui().updateGui()
    path = str(tmp_path / "blend.FCStd")
    doc.saveAs(path)
    name = blend.Name
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        gui().updateGui()
        again = reopened.getObject(name)
        assert isinstance(again.ViewObject.Proxy, ViewProviderBlendShape)
        assert again.ViewObject.DisplayMode == "Zebra" and again.Status == "ok"
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_panel_takes_a_selected_bspline_face_as_the_free_form_side(scene, artifacts):
    import math

    import Part

    doc = scene
    rows = [[FreeCAD.Vector(6 * math.cos(a), 6 * math.sin(a), 8.5 + 0.6 * j) for j in range(4)]
            for a in np.linspace(0, 2 * math.pi, 9, endpoint=False)]
    surface = Part.BSplineSurface()
    surface.buildFromPolesMultsKnots(rows, [1] * 10, [4, 4], [float(k) for k in range(10)], [0.0, 1.0],
                                     True, False, 3, 3)
    ring = doc.addObject("Part::Feature", "Ring")
    ring.Shape = Part.Face(surface)
    doc.recompute()
    blend = new_blend(doc)
    panel = panel_of(blend)
    default = blend.Patches
    assert "Default ring" in panel.freeform_label.text()
    panel.use_selected_face()  # nothing selected: a message, nothing changed
    assert "select a B-spline face" in panel.status_label.text() and blend.FreeForm is None
    gui().Selection.addSelection(ring, "Face1")
    panel.use_selected_face()
    assert blend.FreeForm[0] == ring and blend.Status == "ok", blend.Status
    assert blend.Patches != default and "Ring.Face1" in panel.freeform_label.text()
    ring.ViewObject.Visibility = False
    gui().updateGui()
    image = screenshot(doc, os.path.join(artifacts, "blend_user_ring_zebra.png"))
    dark, white = stripe_pixels(image)
    assert dark > 5000 and white > 5000, (dark, white)
    assert c2_jump(blend.Shape) < 1e-8
    panel.interface.setCurrentIndex(2)  # Start: the ring is then far from the interface, still C2
    assert blend.Interface == "Start" and blend.Status == "ok", blend.Status
    assert c2_jump(blend.Shape) < 1e-8
    panel.interface.setCurrentIndex(0)
    panel.default_ring.click()
    assert blend.FreeForm is None and blend.Patches == default
    blend.Naive = True  # the referee sees a joint that is not C2: the naive strip's
    doc.recompute()
    assert blend.Status == "ok" and c2_jump(blend.Shape) > 1e-3, blend.Status
    blend.Naive = False
    doc.recompute()
    panel.reject()
    gui().updateGui()
    assert blend.FreeForm is None


def test_panel_offers_free_form_at_both_ends(scene, artifacts):
    # The second interface: a sphere band (-40..45 degrees) with free-form above and below.
    from freecad_workbench.features.blend_shape import INTERFACES

    doc = scene
    blend = new_blend(doc)
    panel = panel_of(blend)
    default = blend.Patches
    assert panel.start_box.isHidden()  # one interface: no second free-form side offered
    panel.interface.setCurrentIndex(INTERFACES.index("Both ends"))
    assert blend.Interface == "Both ends" and blend.Status == "ok", blend.Status
    counts = dict(item.rsplit(" ", 1) for item in blend.Patches.split(", "))
    single = dict(item.rsplit(" ", 1) for item in default.split(", "))
    assert int(counts["freeform"]) == 2 * int(single["freeform"])
    assert int(counts["transition"]) == 2 * int(single["transition"])
    assert not panel.start_box.isHidden()
    assert panel.freeform_label.text().startswith("At the end: Default ring")
    assert panel.start_label.text().startswith("At the start: Default ring")
    z = np.array([v.Point.z for v in blend.Shape.Vertexes])
    assert z.min() < 10 * math.sin(math.radians(-40)) - 1 and z.max() > 10 * math.sin(math.radians(45)) + 1
    panel.use_selected_face("FreeFormStart")  # nothing selected: a message, nothing changed
    assert "select a B-spline face" in panel.status_label.text() and blend.FreeFormStart is None
    gui().updateGui()
    image = screenshot(doc, os.path.join(artifacts, "blend_both_ends_zebra.png"))
    dark, white = stripe_pixels(image)
    assert dark > 5000 and white > 5000, (dark, white)
    panel.reject()
    gui().updateGui()
    assert blend.Interface == "Auto" and blend.Patches == default


def test_panel_joins_another_blend_shape_and_cancel_restores(scene, artifacts):
    from freecad_workbench.features.blend_shape import make_blend_shape

    doc = scene
    dome = make_blend_shape(doc, "Sphere zone", name="Dome", Uniform=True, ProfileStart=15.0, ProfileEnd=90.0,
                            ProfileCount=2, placement=FreeCAD.Placement(FreeCAD.Vector(0, 0, 22), FreeCAD.Rotation()))
    blend = new_blend(doc)
    panel = panel_of(blend)
    panel.kind.setCurrentIndex(1)  # Cylinder
    assert blend.Kind == "Cylinder" and blend.Status == "ok"
    labels = [panel.join_to.itemText(i) for i in range(panel.join_to.count())]
    assert labels[1:] == [dome.Label]
    panel.join_to.setCurrentIndex(1)
    assert blend.JoinTo == dome and blend.Status == "ok", blend.Status
    assert blend.Patches.endswith("freeform 0") and not dome.ViewObject.Visibility
    assert "Joined to" in panel.freeform_label.text()
    gui().updateGui()
    image = screenshot(doc, os.path.join(artifacts, "blend_join_post_dome_zebra.png"))
    dark, white = stripe_pixels(image)
    assert dark > 5000 and white > 5000, (dark, white)
    panel.reject()
    gui().updateGui()
    assert blend.JoinTo is None and blend.Kind == "Sphere zone" and blend.Status == "ok"


def surface_points(shape, n=4):
    """A few points of every face's surface, face by face (OCCT's evaluation)."""
    points = []
    for face in shape.Faces:
        u0, u1, v0, v1 = face.ParameterRange
        for u in np.linspace(u0, u1, n):
            for v in np.linspace(v0, v1, n):
                p = face.valueAt(float(u), float(v))
                points.append((p.x, p.y, p.z))
    return np.array(points)


def profile_sketch(doc):
    """A sketch in the XZ plane: a line up from r = 4 and a tangent quarter circle outwards."""
    import Part

    V = FreeCAD.Vector
    sketch = doc.addObject("Sketcher::SketchObject", "ProfileSketch")
    sketch.Placement = FreeCAD.Placement(V(), FreeCAD.Rotation(V(1, 0, 0), 90))  # sketch (x, y) -> (x, 0, y)
    sketch.addGeometry(Part.LineSegment(V(4, 0, 0), V(4, 3, 0)))
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(5, 3, 0), V(0, 0, 1), 1.0), math.pi / 2, math.pi))
    doc.recompute()
    return sketch


def test_panel_takes_the_selected_sketch_as_the_revolution_profile(scene):
    # Issue 32: the Revolution's profile picked as designers pick things: select a sketch in
    # the tree or the 3D view, press the button. A face or a curve crossing the axis is refused
    # with the reason, the last good shape stays; Cancel restores the default parabola.
    import Part

    import freecad_workbench as fw

    doc = scene
    sketch = profile_sketch(doc)
    box = doc.addObject("Part::Box", "Box")
    crossing = doc.addObject("Part::Feature", "Crossing")
    crossing.Shape = Part.LineSegment(FreeCAD.Vector(1, 0, 0), FreeCAD.Vector(-1, 0, 1)).toShape()
    doc.recompute()
    blend = new_blend(doc)
    panel = panel_of(blend)
    assert panel.profile_box.isHidden()  # a sphere zone has no profile to pick
    panel.set_kind("Revolution")
    assert not panel.profile_box.isHidden() and "Default parabola" in panel.profile_label.text()
    assert panel.widgets["ProfileEnd"].text() == "1"  # a fraction of the profile's range, not "1 mm"
    sel = gui().Selection
    sel.clearSelection()
    panel.use_profile.click()  # nothing selected: a message, nothing changed
    assert "Select a sketch" in panel.status_label.text() and blend.Profile is None
    sel.addSelection(sketch)
    panel.use_profile.click()
    assert blend.Profile[0] == sketch and blend.Status == "ok", blend.Status
    assert panel.profile_label.text() == sketch.Label
    # the macro API's blend of the sketch's edges joined, split at thirds of their range
    curve = fw.shapes.joined_profile(sketch.Shape)
    a, b = curve.FirstParameter, curve.LastParameter
    shape = fw.shapes.Revolution(curve, (0, 0, 0), (0, 0, 1), np.radians(np.linspace(0, 360, 7)),
                                 [a + (b - a) / 3, a + 2 * (b - a) / 3])
    expected = fw.blend_basic_shape(shape).shell
    good = surface_points(blend.Shape)
    np.testing.assert_allclose(good, surface_points(expected), atol=1e-9)
    for obj, sub, reason in ((box, "Face1", "Box.Face1 is a face"), (box, "", "Box has faces"),
                             (crossing, "", "axis")):
        sel.clearSelection()
        sel.addSelection(obj, sub) if sub else sel.addSelection(obj)
        panel.use_profile.click()
        text = panel.status_label.text()
        assert text.startswith("Profile not taken") and reason in text, text
        assert blend.Profile[0] == sketch and blend.Status == "ok"
        np.testing.assert_array_equal(surface_points(blend.Shape), good)
    sel.clearSelection()
    sel.addSelection(sketch, "Edge2")  # one edge of it: the arc alone
    panel.use_profile.click()
    assert blend.Profile == (sketch, ["Edge2"]) and blend.Status == "ok", blend.Status
    assert panel.profile_label.text() == f"{sketch.Label}.Edge2"
    panel.default_profile.click()
    assert blend.Profile is None and "Default parabola" in panel.profile_label.text()
    panel.set_profile((sketch, []))
    panel.reject()
    gui().updateGui()
    assert blend.Kind == "Sphere zone" and blend.Profile is None and blend.Status == "ok"
