"""The headless path in fresh processes: no GUI module is imported, and the csr fit works
in freecadcmd."""
import json
import os
import shutil
import subprocess
import sys
import textwrap

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GUI_MODULES = ("FreeCADGui", "PySide", "PySide2", "PySide6", "pivy", "matplotlib.pyplot")


def _run(command, timeout=120):
    env = dict(os.environ)
    env.pop("DISPLAY", None)  # as on a server
    return subprocess.run(command, capture_output=True, text=True, timeout=timeout, env=env, cwd=REPO)


def _result(output):
    """The JSON the script printed after 'RESULT ' (freecadcmd's progress output may precede it)."""
    assert "RESULT " in output, output[-3000:]
    return json.loads(output.rsplit("RESULT ", 1)[1].splitlines()[0])


HEADLESS_SCRIPT = textwrap.dedent(
    """
    import json, sys
    sys.path.insert(0, {repo!r})
    sys.path.append("/usr/lib/freecad-python3/lib")
    import freecad_workbench, freecad_workbench.features
    from freecad_workbench.gui import comb, plot   # the headless halves of the GUI package
    import FreeCAD, Part
    doc = FreeCAD.newDocument("Headless")
    objs = []
    for x, y in [(0, 0), (1, 2), (3, 3), (5, 1)]:
        v = doc.addObject("Part::Vertex", "V"); v.X, v.Y = x, y; objs.append(v)
    fit = freecad_workbench.features.make_csr_fit(doc, objs)
    lines = comb.comb_lines(fit.Shape.Edges[0], 1.0, 32)
    plot.curvature_plot([(fit.Shape.Edges[0], "fit")], path={png!r})
    loaded = sorted(m for m in {gui!r} if m in sys.modules)
    print("RESULT " + json.dumps(dict(status=fit.Status, poles=fit.Shape.Edges[0].Curve.NbPoles,
                                      gui_up=bool(FreeCAD.GuiUp), loaded=loaded, teeth=len(lines.base))))
    """
)


def test_macro_api_features_comb_and_plot_import_no_gui(tmp_path):
    script = tmp_path / "headless.py"
    script.write_text(HEADLESS_SCRIPT.format(repo=REPO, png=str(tmp_path / "p.png"), gui=GUI_MODULES))
    result = _run([sys.executable, str(script)])
    assert result.returncode == 0, result.stderr
    out = _result(result.stdout)
    assert out == dict(status="ok", poles=out["poles"], gui_up=False, loaded=[], teeth=out["teeth"])
    assert out["poles"] >= 4 and out["teeth"] >= 32
    assert (tmp_path / "p.png").stat().st_size > 1000


FREECADCMD_SCRIPT = textwrap.dedent(
    """
    import json, sys
    sys.path.insert(0, {repo!r})
    import FreeCAD, Part
    from freecad_workbench.features.csr_fit import make_csr_fit
    doc = FreeCAD.newDocument("Cmd")
    objs = []
    for x, y in [(0, 0), (1, 2), (3, 3), (5, 1), (7, 2)]:
        v = doc.addObject("Part::Vertex", "V"); v.X, v.Y = x, y; objs.append(v)
    fit = make_csr_fit(doc, objs, parametrization="centripetal")
    good = fit.Shape.Edges[0].Curve.NbPoles
    objs[2].X, objs[2].Y = objs[1].X, objs[1].Y
    doc.recompute()
    broken = fit.Status
    doc.saveAs({path!r})
    loaded = sorted(m for m in {gui!r} if m in sys.modules)
    print("RESULT " + json.dumps(dict(poles=good, broken=broken, kept=fit.Shape.Edges[0].Curve.NbPoles,
                                      gui_up=bool(FreeCAD.GuiUp), loaded=loaded)))
    """
)


@pytest.mark.skipif(shutil.which("freecadcmd") is None, reason="freecadcmd is not installed")
def test_csr_fit_works_in_freecadcmd(tmp_path):
    # not a stdlib module name: freecadcmd runs a .py file by importing it by name
    script = tmp_path / "fairsplines_freecadcmd_check.py"
    saved = tmp_path / "cmd.FCStd"
    script.write_text(FREECADCMD_SCRIPT.format(repo=REPO, path=str(saved), gui=GUI_MODULES))
    result = _run(["freecadcmd", str(script)])
    assert result.returncode == 0, result.stdout + result.stderr
    out = _result(result.stdout + "\n" + result.stderr)
    assert out["poles"] == 7 and out["kept"] == 7
    assert out["broken"] == "points 1 and 2 coincide (from V001 and V002)"
    assert out["gui_up"] is False and out["loaded"] == []
    assert "CsrFit: points 1 and 2 coincide" in result.stdout + result.stderr  # reported on the console
    assert saved.stat().st_size > 0
