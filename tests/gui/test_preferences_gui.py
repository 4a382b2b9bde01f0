"""The FairSplines page of Edit > Preferences (freecad_workbench/gui/preferences.py): it
shows the stored preferences, OK stores what it shows, a value the user set survives the
next opening, and it fits a narrow dialog. Headless side (features take their defaults
from the preferences): tests/workbench/test_preferences.py."""
import os

import pytest

import FreeCAD

from freecad_workbench import preferences
from freecad_workbench.gui import icon_path
from freecad_workbench.gui import preferences as page_module

# Values unlike every default, one per preference.
USER_VALUES = {
    "CombScale": -2.5, "CombSamples": 300, "CombCommonScale": True, "CombTorsion": True,
    "ZebraStripes": 24,
    "CsrEpsilon": 2.5e-12, "JoinTolerance": 0.02, "PlotSamples": 2048,
}
# The group icon differs from the workbench icon drawn at the same size by less than this
# (0-255 per channel): 3-4 after FreeCAD's scaling (0.20, 1.1); FreeCAD 1.1's "?" for a
# missing icon is 58 from it, its General group's icon 63.
ICON_DIFFERENCE = 20
SETTERS = {"String": "SetString", "Integer": "SetInt", "Float": "SetFloat", "Boolean": "SetBool",
           "Unsigned Long": "SetUnsigned"}


_dialog_opened = []  # the preferences dialog was opened (its OK writes user.cfg)


@pytest.fixture(autouse=True)
def kept_preferences():
    """The FairSplines parameters as they were before the test, afterwards; in user.cfg
    too if the test opened the preferences dialog."""
    params = FreeCAD.ParamGet(preferences.PARAM_PATH)
    before = params.GetContents() or []
    yield
    for key in preferences.PREFERENCES:
        preferences.reset(key)
    for kind, name, value in before:
        getattr(params, SETTERS[kind])(name, value)
    if _dialog_opened:
        FreeCAD.saveParameter()
        _dialog_opened.clear()


def new_page():
    page = page_module.PreferencePage()
    page.loadSettings()
    return page


def shown(page, key):
    widget = page.fields[key]
    return widget.isChecked() if preferences.PREFERENCES[key].type is bool else widget.value()


def show(page, key, value):
    widget = page.fields[key]
    widget.setChecked(value) if preferences.PREFERENCES[key].type is bool else widget.setValue(value)


def test_page_has_a_field_for_every_preference_in_its_groups():
    from freecad_workbench.gui.qt import QtWidgets

    page = new_page()
    assert set(page.fields) == set(preferences.PREFERENCES)
    titles = [box.title() for box in page.form.findChildren(QtWidgets.QGroupBox)]
    assert titles == ["Curvature comb", "Zebra", "Fitting", "Plots"]
    assert all(widget.toolTip() for widget in page.fields.values())
    assert page.fields["JoinTolerance"].suffix() == " mm"


def test_page_shows_the_stored_values_and_the_defaults_where_none_is_stored():
    for key in preferences.PREFERENCES:
        preferences.reset(key)
    page = new_page()
    assert {key: shown(page, key) for key in page.fields} == {k: p.default for k, p in preferences.PREFERENCES.items()}
    for key, value in USER_VALUES.items():
        preferences.set_value(key, value)
    page = new_page()
    assert {key: shown(page, key) for key in page.fields} == USER_VALUES
    assert page.fields["CsrEpsilon"].text() == "2.5e-12"


def test_save_writes_the_parameter_group():
    page = new_page()
    for key, value in USER_VALUES.items():
        show(page, key, value)
    page.saveSettings()
    params = FreeCAD.ParamGet(preferences.PARAM_PATH)
    assert params.GetFloat("CombScale") == -2.5 and params.GetInt("CombSamples") == 300
    assert params.GetBool("CombCommonScale") is True and params.GetInt("ZebraStripes") == 24
    assert float(params.GetString("CsrEpsilon")) == 2.5e-12
    assert params.GetFloat("JoinTolerance") == pytest.approx(0.02) and params.GetInt("PlotSamples") == 2048
    assert preferences.values() == pytest.approx(USER_VALUES)


def test_saving_untouched_defaults_stores_nothing():
    for key in preferences.PREFERENCES:
        preferences.reset(key)
    new_page().saveSettings()
    assert not any(preferences.is_set(key) for key in preferences.PREFERENCES)


def test_a_value_the_user_set_survives_the_next_opening_and_save():
    page = new_page()
    show(page, "ZebraStripes", 40)
    page.saveSettings()
    again = new_page()  # FreeCAD makes a new page each time the dialog opens
    assert shown(again, "ZebraStripes") == 40
    again.saveSettings()
    assert preferences.get("ZebraStripes") == 40


def test_tolerance_box_reads_scientific_input_and_steps_by_decades():
    page = new_page()
    box = page.fields["CsrEpsilon"]
    box.lineEdit().setText("3.5e-11")
    box.interpretText()
    assert box.value() == 3.5e-11
    box.setValue(1.2345e-9)
    box.interpretText()  # what leaving the field does: the text shown reads back as the value
    assert box.value() == 1.2345e-9 and box.text() == "1.2345e-9"
    box.setValue(1e-9)
    box.stepBy(1)
    assert box.value() == 1e-8 and box.text() == "1e-8"
    box.stepBy(-100)
    assert box.value() == preferences.PREFERENCES["CsrEpsilon"].minimum
    join = page.fields["JoinTolerance"]
    assert join.text() == f"{page_module.format_small(join.value())} mm"


def test_comb_style_and_zebra_read_the_preferences():
    from freecad_workbench.gui import comb, zebra

    comb.set_style(3.0, 512)
    assert preferences.get("CombScale") == 3.0 and preferences.get("CombSamples") == 512
    preferences.set_value("CombScale", 0.5)
    assert comb.get_style() == (0.5, 512)
    preferences.set_value("ZebraStripes", 7)
    assert zebra.DEFAULT_STRIPES == 7 and zebra.ZebraNode().stripes == 7


def test_new_profile_test_reflects_the_stripes_preference(doc):
    from freecad_workbench.features.basic_curve import make_basic_curve
    from freecad_workbench.features.profile_test import make_profile_test

    preferences.set_value("ZebraStripes", 9)
    arc = make_basic_curve(doc, "Circle arc", Radius=5, StartAngle=10, EndAngle=80)
    test = make_profile_test(doc, arc, axis_point=(0, 0, 0), axis_direction=(0, 1, 0))
    assert test.ViewObject.Stripes == 9 and test.ViewObject.Proxy.zebra.stripes == 9
    preferences.set_value("ZebraStripes", 30)
    assert test.ViewObject.Stripes == 9  # an existing object keeps its value


def test_page_fits_a_narrow_dialog():
    """At its minimum size nothing is cut off: labels whole, spin boxes wide enough for their text."""
    from freecad_workbench.gui.qt import QtWidgets

    page = new_page()
    form = page.form
    form.show()
    try:
        hint = form.minimumSizeHint()
        assert hint.width() <= 300, hint.width()
        form.resize(hint)
        QtWidgets.QApplication.processEvents()
        for label in form.findChildren(QtWidgets.QLabel) + form.findChildren(QtWidgets.QCheckBox):
            assert label.width() >= label.sizeHint().width(), label.text()
            assert label.geometry().right() <= label.parentWidget().contentsRect().right(), label.text()
        for box in page.fields.values():
            if isinstance(box, QtWidgets.QAbstractSpinBox):
                assert box.width() >= box.minimumSizeHint().width(), box.objectName()
                assert box.lineEdit().fontMetrics().horizontalAdvance(box.text()) < box.lineEdit().width(), box.text()
    finally:
        form.close()


def _in_preferences_dialog(gui, action):
    """Open Edit > Preferences at the FairSplines group, run action(dialog) in it (while the
    modal dialog runs), and return what it returned."""
    from freecad_workbench.gui.qt import QtCore, QtWidgets

    outcome = {}

    def run(tries=[0]):
        dialog = QtWidgets.QApplication.activeModalWidget()
        if dialog is None and tries[0] < 50:
            tries[0] += 1
            QtCore.QTimer.singleShot(100, run)
            return
        try:
            outcome["value"] = action(dialog)
        except BaseException as exc:  # re-raised outside the dialog's event loop
            outcome["error"] = exc
        finally:
            if dialog is not None and dialog.isVisible():
                dialog.reject()

    QtCore.QTimer.singleShot(300, run)
    _dialog_opened.append(True)
    gui.showPreferences(page_module.GROUP, 0)
    if "error" in outcome:
        raise outcome["error"]
    return outcome["value"]


def _page_widget(dialog, key):
    from freecad_workbench.gui.qt import QtWidgets

    found = [w for w in dialog.findChildren(QtWidgets.QWidget, key) if w.isVisible()]
    assert len(found) == 1, f"{len(found)} visible widgets named {key}"
    return found[0]


def _icon_difference(icon, svg, size=24):
    """Mean absolute difference (0-255 per channel, on white) of an icon drawn at size px
    and the SVG drawn at that size."""
    from freecad_workbench.gui.qt import QtGui

    def on_white(image):
        image = image.convertToFormat(QtGui.QImage.Format_ARGB32)
        white = QtGui.QImage(size, size, QtGui.QImage.Format_ARGB32)
        white.fill(QtGui.QColor("white"))
        painter = QtGui.QPainter(white)
        painter.drawImage(0, 0, image)
        painter.end()
        return white

    got = on_white(icon.pixmap(size, size).toImage().scaled(size, size))
    want = on_white(QtGui.QImage.fromData(page_module._icon_png(svg, size), "PNG"))
    total = 0
    for x in range(size):
        for y in range(size):
            a, b = QtGui.QColor(got.pixel(x, y)), QtGui.QColor(want.pixel(x, y))
            total += abs(a.red() - b.red()) + abs(a.green() - b.green()) + abs(a.blue() - b.blue())
    return total / (3 * size * size)


def _groups(dialog):
    """{group name: icon} of the dialog's list of groups (0.20: a list, 1.x: a tree)."""
    from freecad_workbench.gui.qt import QtCore, QtWidgets

    groups = {}
    for view in dialog.findChildren(QtWidgets.QAbstractItemView):
        model = view.model()
        for row in range(model.rowCount() if model is not None else 0):
            index = model.index(row, 0)
            groups[str(model.data(index))] = model.data(index, QtCore.Qt.DecorationRole)
    return groups


def test_edit_preferences_has_the_fairsplines_page_and_ok_stores_it(gui, artifacts):
    from freecad_workbench.gui.qt import QtGui, QtWidgets

    page_module.register_preferences()
    page_module.register_preferences()  # a second call adds no second page
    for key in preferences.PREFERENCES:
        preferences.reset(key)

    def look_and_change(dialog):
        groups = _groups(dialog)
        assert "FairSplines" in groups, sorted(groups)
        assert isinstance(groups["FairSplines"], QtGui.QIcon)
        difference = _icon_difference(groups["FairSplines"], icon_path("FairSplines"))
        assert difference < ICON_DIFFERENCE, f"the group icon is not the workbench's: {difference:.0f}"
        assert _page_widget(dialog, "PlotSamples").value() == 1024
        QtWidgets.QApplication.processEvents()  # the picture shows the defaults
        dialog.grab().save(os.path.join(artifacts, "preferences.png"))
        _page_widget(dialog, "ZebraStripes").setValue(21)
        dialog.accept()  # OK

    _in_preferences_dialog(gui, look_and_change)
    assert preferences.get("ZebraStripes") == 21 and not preferences.is_set("PlotSamples")
    assert _in_preferences_dialog(gui, lambda dialog: _page_widget(dialog, "ZebraStripes").value()) == 21
    assert os.path.getsize(os.path.join(artifacts, "preferences.png")) > 10000
