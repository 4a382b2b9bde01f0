"""Design with basic curves in freecadcmd, in a fresh process: basic curve, design spline,
edit polygon and profile test compute, save and report errors with no GUI module loaded."""
import json
import os
import shutil
import subprocess
import textwrap

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GUI_MODULES = ("FreeCADGui", "PySide", "PySide2", "PySide6", "pivy", "matplotlib.pyplot")

SCRIPT = textwrap.dedent(
    """
    import json, sys
    sys.path.insert(0, {repo!r})
    import FreeCAD, Part, Sketcher
    from freecad_workbench.features.basic_curve import make_basic_curve
    from freecad_workbench.features.design_spline import make_design_spline, set_marks
    from freecad_workbench.features.edit_polygon import make_edit_polygon, set_pole
    from freecad_workbench.features.profile_test import make_profile_test
    V = FreeCAD.Vector
    doc = FreeCAD.newDocument("Cmd")
    sketch = doc.addObject("Sketcher::SketchObject", "Sketch")
    sketch.Placement = FreeCAD.Placement(V(), FreeCAD.Rotation(V(1, 0, 0), 90))
    sketch.addGeometry(Part.LineSegment(V(20, 0, 0), V(20, 10, 0)))
    doc.recompute()
    arc = make_basic_curve(doc, "Circle arc", placement=FreeCAD.Placement(V(15, 0, 10), sketch.Placement.Rotation),
                           Radius=5, StartAngle=0, EndAngle=90)
    design = make_design_spline(doc, [((sketch, "Edge1"), [0.3, 0.6, 0.9]), (arc, [0.2, 0.5, 0.8])])
    edited = make_edit_polygon(doc, design)
    set_pole(edited, 3, edited.Poles[3] + V(1, 0, 0))
    test = make_profile_test(doc, edited)
    doc.recompute()
    ok = [o.Status for o in (arc, design, edited, test)]
    set_marks(design, [[0.6, 0.3], [0.5]])
    doc.recompute()
    broken = design.Status
    doc.saveAs({path!r})
    loaded = sorted(m for m in {gui!r} if m in sys.modules)
    print("RESULT " + json.dumps(dict(ok=ok, broken=broken, joins=list(design.Joins), faces=len(test.Shape.Faces),
                                      gui_up=bool(FreeCAD.GuiUp), loaded=loaded)))
    """
)


@pytest.mark.skipif(shutil.which("freecadcmd") is None, reason="freecadcmd is not installed")
def test_design_features_work_in_freecadcmd(tmp_path):
    script = tmp_path / "fairsplines_design_check.py"
    saved = tmp_path / "design.FCStd"
    script.write_text(SCRIPT.format(repo=REPO, path=str(saved), gui=GUI_MODULES))
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    result = subprocess.run(["freecadcmd", str(script)], capture_output=True, text=True, timeout=120, env=env, cwd=REPO)
    output = result.stdout + "\n" + result.stderr
    assert result.returncode == 0, output
    assert "RESULT " in output, output[-3000:]
    out = json.loads(output.rsplit("RESULT ", 1)[1].splitlines()[0])
    assert out["ok"] == ["ok"] * 4
    assert out["broken"].startswith("piece 1: marks must increase: mark 2 ") and "Sketch.Edge1" in out["broken"]
    assert out["joins"] == [] and out["faces"] == 1  # no verdict left about a design that failed
    assert out["gui_up"] is False and out["loaded"] == []
    assert "DesignSpline: piece 1: marks must increase" in output  # reported on the console
    assert saved.stat().st_size > 0
