"""The README's main job: `make demo` runs demo/demo.py under freecadcmd. Here it runs the
same way into a temporary folder, and its document and pictures are judged independently:
the document is reopened and its curves are evaluated by OCCT."""
import os
import shutil
import subprocess
import sys

import pytest

import freecad_workbench as fw  # noqa: F401  (makes FreeCAD importable)
import FreeCAD  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PICTURES = ("fig2_curvature.png", "fig2_curves.png", "design_curvature.png", "monotone_curvature.png",
            "fair_blend_curvature.png",
            "blend_patches.png", "blend_join.png")


@pytest.fixture(scope="module")
def demo_out(tmp_path_factory):
    if shutil.which("freecadcmd") is None:
        pytest.fail("freecadcmd is not installed (make deps installs it)")
    out = tmp_path_factory.mktemp("demo")
    env = dict(os.environ, FAIRSPLINES_OUT=str(out))
    # The demo imports the workbench from FreeCAD's Mod folder or, failing that, from the
    # repository it lives in; the repository on sys.path makes the run independent of both.
    env["PYTHONPATH"] = REPO + os.pathsep + env.get("PYTHONPATH", "")
    run = subprocess.run(["freecadcmd", os.path.join(REPO, "demo", "demo.py")], cwd=REPO, env=env,
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    return out


def test_demo_writes_the_document_and_every_picture(demo_out):
    for name in PICTURES + ("fairsplines_demo.FCStd", "summary.txt"):
        assert (demo_out / name).is_file(), name
    for name in PICTURES:
        data = (demo_out / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n", name
        assert len(data) > 20000, f"{name} is nearly empty ({len(data)} bytes)"


def test_demo_document_shows_fig2_csr_without_and_classic_with_sign_changes(demo_out):
    doc = FreeCAD.openDocument(str(demo_out / "fairsplines_demo.FCStd"))
    try:
        csr = doc.getObject("CsrSpline").Shape.Edges[0].Curve
        classic = doc.getObject("ClassicInterpolation").Shape.Edges[0].Curve
        samples = [FreeCAD.Vector(*p) for p in doc.getObject("Fig2Samples").Points.Points]
        assert fw.curvature_sign_changes(csr) == 0
        assert fw.curvature_sign_changes(classic) >= 1
        assert csr.Continuity == "C2"
        assert (csr.value(csr.FirstParameter) - samples[0]).Length < 1e-12
        assert (csr.value(csr.LastParameter) - samples[-1]).Length < 1e-12
        # Every object the demo builds reopens with a valid shape.
        shapes = [o for o in doc.Objects if hasattr(o, "Shape") and o.TypeId.startswith("Part::")]
        assert len(shapes) >= 15
        for o in shapes:
            assert not o.Shape.isNull() and o.Shape.isValid(), o.Name
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_demo_summary_reports_the_figures(demo_out):
    summary = (demo_out / "summary.txt").read_text()
    rows = {line[:30].strip(): line[30:].split() for line in summary.splitlines() if line[:30].strip()}
    assert rows["csr-spline"][0] == "0"
    assert int(rows["classic C2 interpolation"][0]) >= 1
    assert "shell valid: True, single surface: C2" in summary
    assert "monotone=True" in summary
    fair = summary.split("Fair blend, G2", 1)[1].splitlines()
    assert fair[1].strip().startswith("certificate: monotone=True, increasing=True")
    assert fair[1].endswith("curvature extrema inside: 0") and fair[2].strip() == "end curvatures: 0 and 0.1"


if __name__ == "__main__":
    sys.exit(pytest.main([__file__, "-v"]))
