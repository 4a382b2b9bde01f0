"""FairSplines preferences, headless (freecad_workbench/preferences.py): a new csr fit and a
new design spline take their defaults from the preferences, objects that exist keep their
values, and `get` always gives a valid value. The page itself: tests/gui/test_preferences_gui.py."""
import os
import subprocess
import sys

import pytest

import FreeCAD

from freecad_workbench import preferences
from freecad_workbench.features.basic_curve import make_basic_curve
from freecad_workbench.features.csr_fit import make_csr_fit
from freecad_workbench.features.design_spline import make_design_spline

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = [(0, 0, 0), (10, 8, 0), (20, 11, 0), (30, 9, 0), (40, 2, 0), (50, 0, 0)]
V = FreeCAD.Vector
# ParamGet(...).GetContents() names the types so; the setters are Set<these>.
SETTERS = {"String": "SetString", "Integer": "SetInt", "Float": "SetFloat", "Boolean": "SetBool",
           "Unsigned Long": "SetUnsigned"}


@pytest.fixture(autouse=True)
def kept_preferences():
    """The user's FairSplines parameters as they were before the test, afterwards."""
    params = FreeCAD.ParamGet(preferences.PARAM_PATH)
    before = params.GetContents() or []
    yield
    for key, pref in preferences.PREFERENCES.items():
        preferences.reset(key)
        if pref.stored_as != "Float":
            params.RemFloat(key)  # one a test set by hand
    for kind, name, value in before:
        getattr(params, SETTERS[kind])(name, value)


def vertices(doc):
    objs = []
    for x, y, z in DATA:
        v = doc.addObject("Part::Vertex", "V")
        v.X, v.Y, v.Z = x, y, z
        objs.append(v)
    doc.recompute()
    return objs


def two_arcs(doc):
    first = make_basic_curve(doc, "Circle arc", Radius=10, StartAngle=0, EndAngle=90)  # ends at (0, 10)
    second = make_basic_curve(doc, "Line segment", Start=V(0, 10, 0), End=V(-10, 10, 0))
    return [(first, None), (second, None)]


def test_new_csr_fit_takes_the_epsilon_preference(doc):
    points = vertices(doc)
    preferences.set_value("CsrEpsilon", 2.5e-12)
    fit = make_csr_fit(doc, points)
    assert fit.Epsilon == 2.5e-12 and fit.Status == "ok"
    assert make_csr_fit(doc, points, epsilon=1e-6).Epsilon == 1e-6  # an explicit value wins
    preferences.reset("CsrEpsilon")
    assert make_csr_fit(doc, points).Epsilon == 1e-9


def test_new_design_spline_takes_the_join_tolerance_preference(doc):
    pieces = two_arcs(doc)
    preferences.set_value("JoinTolerance", 0.02)
    design = make_design_spline(doc, pieces, reversed=[False, False])
    assert design.JoinTolerance.Value == pytest.approx(0.02) and design.Status == "ok"
    assert make_design_spline(doc, pieces, join_tolerance=1e-3).JoinTolerance.Value == pytest.approx(1e-3)
    preferences.reset("JoinTolerance")
    assert make_design_spline(doc, pieces).JoinTolerance.Value == pytest.approx(1e-6)


def test_objects_keep_their_values_when_the_preferences_change(doc, tmp_path):
    fit = make_csr_fit(doc, vertices(doc))
    design = make_design_spline(doc, two_arcs(doc))
    preferences.set_value("CsrEpsilon", 1e-5)
    preferences.set_value("JoinTolerance", 0.5)
    doc.recompute()
    assert fit.Epsilon == 1e-9 and design.JoinTolerance.Value == pytest.approx(1e-6)
    names = fit.Name, design.Name
    path = str(tmp_path / "kept.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        reopened.recompute()
        assert reopened.getObject(names[0]).Epsilon == 1e-9
        assert reopened.getObject(names[1]).JoinTolerance.Value == pytest.approx(1e-6)
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_defaults_are_the_ones_the_modules_used_before():
    for key in preferences.PREFERENCES:
        preferences.reset(key)
    assert preferences.values() == {
        "CombScale": 1.0, "CombSamples": 256, "CombCommonScale": False, "CombTorsion": False,
        "ZebraStripes": 16,
        "CsrEpsilon": 1e-9, "JoinTolerance": 1e-6, "PlotSamples": 1024,
    }
    assert not any(preferences.is_set(key) for key in preferences.PREFERENCES)


def test_values_round_trip_exactly_through_the_parameter_group():
    # CsrEpsilon is kept as a string: FreeCAD 0.20 stores a Float with 12 decimals.
    for key, value in (("CsrEpsilon", 2.5e-14), ("CsrEpsilon", 1.2345678e-9), ("JoinTolerance", 0.0123),
                       ("CombScale", -2.5), ("CombSamples", 777), ("CombCommonScale", True), ("PlotSamples", 64)):
        assert preferences.set_value(key, value) == value
        assert preferences.get(key) == value and type(preferences.get(key)) is type(value)
        assert preferences.is_set(key)


def test_get_gives_a_valid_value_whatever_is_stored():
    params = FreeCAD.ParamGet(preferences.PARAM_PATH)
    params.SetInt("CombSamples", 2)
    params.SetFloat("CombScale", 1e9)
    params.SetString("CsrEpsilon", "tiny")
    assert preferences.get("CombSamples") == 8
    assert preferences.get("CombScale") == 1000.0
    assert preferences.get("CsrEpsilon") == 1e-9
    params.RemString("CsrEpsilon")
    params.SetFloat("CsrEpsilon", 1e-7)  # set by hand as a Float in the parameter editor
    assert preferences.get("CsrEpsilon") == pytest.approx(1e-7)
    assert preferences.set_value("ZebraStripes", 0) == 1
    with pytest.raises(KeyError, match="CombScale"):
        preferences.get("CombScal")


def test_preferences_module_imports_no_qt():
    code = (
        "import sys; sys.path.insert(0, sys.argv[1]); import freecad_workbench.preferences as p; p.values(); "
        "bad = [m for m in sys.modules if m.split('.')[0] in ('PySide2', 'PySide6', 'PySide', 'shiboken2', "
        "'shiboken6', 'FreeCADGui')]; print(bad); sys.exit(1 if bad else 0)"
    )
    run = subprocess.run([sys.executable, "-c", code, REPO], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
