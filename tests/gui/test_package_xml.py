"""package.xml tells the Addon Manager what the workbench does: every command the workbench
registers belongs to one capability the description names, and every capability named has
its commands registered (a new command, or a removed one, fails here until package.xml says so)."""
import os

import FreeCAD

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# The capability's words in package.xml's description -> the commands that provide it.
CAPABILITIES = {
    "Fit points: csr-splines": ["FairSplines_FitGroup", "FairSplines_CsrFit"],
    "a fair fit within a tolerance": ["FairSplines_FairFit"],
    "Design with basic curves": [
        "FairSplines_BasicCurves", "FairSplines_LineSegment", "FairSplines_CircleArc", "FairSplines_EllipseArc",
        "FairSplines_ParabolaArc", "FairSplines_HyperbolaArc", "FairSplines_RationalCubic",
        "FairSplines_ArchimedeanSpiral", "FairSplines_CircleInvolute", "FairSplines_DesignSpline",
        "FairSplines_ProfileTest"],
    "with marked points and an editable control polygon": ["FairSplines_MarkPoints", "FairSplines_EditPolygon"],
    "Basic shapes blended C2 into NURBS": ["FairSplines_BlendBasicShape"],
    "Monotone-curvature B-splines": ["FairSplines_MonotoneDesign"],
    "Fair blends between two curves, G1 or G2, in the plane and in space": [
        "FairSplines_BlendGroup", "FairSplines_MonotoneBlend"],
    "Curve analysis: curvature combs, curvature plots, monotonicity check": [
        "FairSplines_AnalysisGroup", "FairSplines_CurvatureComb", "FairSplines_CurvaturePlot",
        "FairSplines_CheckMonotone"],
    "Surface analysis: curvature map, continuity check across edges, zebra stripes, iso-curve combs": [
        "FairSplines_CurvatureMap", "FairSplines_CheckContinuity", "FairSplines_Zebra", "FairSplines_IsoCombs"],
    "Face blends: a G1 or G2 surface joining two faces along two edges": ["FairSplines_BlendFaces"],
    "the workbench builds it on first use": ["FairSplines_BuildKernel"],
}


def test_package_xml_names_every_capability_the_workbench_registers(gui):
    gui.activateWorkbench("FairSplinesWorkbench")
    registered = {name for name in gui.listCommands() if name.startswith("FairSplines_")}
    description = FreeCAD.Metadata(os.path.join(REPO, "package.xml")).Description
    described = [name for names in CAPABILITIES.values() for name in names]
    assert len(described) == len(set(described))
    assert registered == set(described), (
        f"commands without a capability in package.xml: {sorted(registered - set(described))}; "
        f"described but not registered: {sorted(set(described) - registered)}")
    for words in CAPABILITIES:
        assert words in description, f"package.xml does not say: {words}"
    assert "Tested on FreeCAD 0.20, 1.0 and 1.1" in description


def test_package_xml_has_what_the_addon_manager_shows():
    meta = FreeCAD.Metadata(os.path.join(REPO, "package.xml"))
    assert os.path.isfile(os.path.join(REPO, meta.Icon)) and meta.FreeCADMin.startswith("0.20")
    assert {"curves", "splines", "curvature", "surfaces", "blend"} <= set(meta.Tag)
    assert [lic["name"] for lic in meta.License] == ["LGPL-2.1-or-later"]
