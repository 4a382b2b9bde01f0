"""The FairSplines page of Edit > Preferences: the defaults of curvature combs, zebra
shading, fitting and curvature plots (freecad_workbench/preferences.py holds the keys,
defaults and ranges; this is only the page).

    from freecad_workbench.gui.preferences import register_preferences
    register_preferences()      # once, from InitGui.py

FreeCAD makes a PreferencePage each time the dialog opens: it shows `form`, calls
loadSettings() and, on OK or Apply, saveSettings(). The page fits a narrow dialog: one
value per row, compact spin boxes with their units; when the dialog is too narrow for a
label and its field side by side, the field goes below the label.
"""
import sys

import FreeCAD

from .. import preferences
from . import icon_path
from . import comb as comb_texts

translate = FreeCAD.Qt.translate

GROUP = "FairSplines"  # the group of pages in the dialog's list
# FreeCAD looks the group's icon up by this name ("preferences-" + group in lower case).
GROUP_ICON = "preferences-fairsplines"
SPIN_WIDTH = 96  # px: spin boxes are at least this wide, and as wide as their widest value needs

GROUP_ICON_SIZE = 96  # px: what FreeCAD 0.20 draws (1.x scales it to 24)

_registered = False


def _icon_png(svg_path, size):
    """An SVG drawn at size x size px, as PNG bytes. (FreeCAD's own SVG loading of
    addIcon needs Qt's svg image plugin, which a FreeCAD 1.1 may lack.)"""
    from .qt import QtCore, QtGui, qt_module

    image = QtGui.QImage(size, size, QtGui.QImage.Format_ARGB32)
    image.fill(0)
    painter = QtGui.QPainter(image)
    qt_module("QtSvg").QSvgRenderer(svg_path).render(painter)
    painter.end()
    data = QtCore.QByteArray()
    buffer = QtCore.QBuffer(data)
    buffer.open(QtCore.QIODevice.WriteOnly)
    image.save(buffer, "PNG")
    buffer.close()
    return bytes(data)


def register_preferences():
    """Add the FairSplines page (with the group's icon) to Edit > Preferences, once."""
    global _registered
    import FreeCADGui

    if _registered:
        return
    try:  # the workbench icon under the name the dialog looks for; without it, no icon
        FreeCADGui.addIcon(GROUP_ICON, _icon_png(icon_path("FairSplines"), GROUP_ICON_SIZE), "PNG")
    except Exception as exc:
        FreeCAD.Console.PrintLog(f"FairSplines preferences: no group icon ({exc})\n")
    FreeCADGui.addPreferencePage(PreferencePage, GROUP)
    _registered = True


def format_small(value):
    """A tolerance as a designer writes it: 1e-9, 2.5e-12, 0.001, 10 (up to 12 digits,
    so reading the text back gives the value)."""
    text = repr(float(f"{value:.12g}"))
    if text.endswith(".0"):
        text = text[:-2]
    if "e" in text:
        mantissa, exponent = text.split("e")
        text = f"{mantissa}e{int(exponent)}"
    return text


def _tolerance_spin_box(minimum, maximum, suffix=""):
    """A spin box for small tolerances: shows 1e-9 rather than 0.000000001, and its arrows
    multiply or divide by 10."""
    from .qt import QtGui, QtWidgets

    class ToleranceSpinBox(QtWidgets.QDoubleSpinBox):
        def textFromValue(self, value):
            return format_small(value).replace(".", self.locale().decimalPoint())

        def _number(self, text):
            text = text.strip()
            if self.suffix() and text.endswith(self.suffix().strip()):
                text = text[: -len(self.suffix().strip())]
            return float(text.strip().replace(self.locale().decimalPoint(), ".").replace(",", "."))

        def valueFromText(self, text):
            try:
                return self._number(text)
            except ValueError:
                return self.value()

        def validate(self, text, pos):
            try:
                value = self._number(text)
            except ValueError:
                state = QtGui.QValidator.Intermediate
            else:
                inside = self.minimum() <= value <= self.maximum()
                state = QtGui.QValidator.Acceptable if inside else QtGui.QValidator.Intermediate
            return state, text, pos

        def stepBy(self, steps):
            value = float(f"{self.value() * 10.0 ** steps:.12g}")  # 1e-9 * 10 is 1e-8, not 1.0000000000000001e-8
            self.setValue(min(max(value, self.minimum()), self.maximum()))

    box = ToleranceSpinBox()
    box.setDecimals(323)  # QDoubleSpinBox rounds to its decimals: keep 1e-15 as it is
    box.setRange(minimum, maximum)
    box.setSuffix(suffix)
    box.setKeyboardTracking(False)
    return box


class PreferencePage:
    """The page FreeCAD shows: `form` (a QWidget), loadSettings(), saveSettings()."""

    def __init__(self):
        from .qt import QtGui, QtWidgets

        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("FairSplines", "General"))
        self.form.setWindowIcon(QtGui.QIcon(icon_path("FairSplines")))
        layout = QtWidgets.QVBoxLayout(self.form)
        self.fields = {}  # preference key -> widget

        rows = self._group(layout, translate("FairSplines", "Curvature comb"))
        self._float(rows, "CombScale", translate("FairSplines", "Scale factor"), translate(
            "FairSplines",
            "Length of the teeth. At 1 the longest tooth is at most a quarter of the curve's size and no tooth "
            "reaches its centre of curvature; 2 doubles them. Negative: the comb on the other side of the curve."),
                    decimals=3, step=0.1)
        self._int(rows, "CombSamples", translate("FairSplines", "Teeth per edge"), translate(
            "FairSplines", "How many teeth a comb has on each edge, at least. More show finer detail, "
            "fewer redraw faster."), step=32)
        self._bool(rows, "CombCommonScale", translate("FairSplines", "Same scale for all combs"), translate(
            "FairSplines",
            "On: every comb shown is drawn to one scale, the smallest any of them would get on its own, "
            "so tooth lengths compare between curves. Off: each comb is sized to its own curve."))
        self._bool(rows, "CombTorsion", translate("FairSplines", "Torsion comb too"), comb_texts.torsion_tooltip())

        rows = self._group(layout, translate("FairSplines", "Zebra"))
        self._int(rows, "ZebraStripes", translate("FairSplines", "Stripe pairs"), translate(
            "FairSplines", "Black and white stripe pairs the zebra shading of blends and of new profile tests "
            "reflects. An existing profile test keeps its own: its Stripes view property."))

        rows = self._group(layout, translate("FairSplines", "Fitting"))
        self._tolerance(rows, "CsrEpsilon", translate("FairSplines", "Spline through points: tolerance"), translate(
            "FairSplines", "Curvature below this, relative to one over the size of the data, counts as straight "
            "(eq. (6) of the csr paper). Used by new splines through points (csr fits); an existing one keeps its "
            "CurvatureTolerance."))
        self._tolerance(rows, "JoinTolerance", translate("FairSplines", "Design spline join tolerance"), translate(
            "FairSplines", "End points of consecutive pieces closer than this are averaged into one point; "
            "farther apart they are joined by a line. Used by new design splines."), " mm")

        rows = self._group(layout, translate("FairSplines", "Plots"))
        self._int(rows, "PlotSamples", translate("FairSplines", "Curvature plot samples"), translate(
            "FairSplines", "Points at which a curvature plot evaluates each curve."), step=256)
        layout.addStretch(1)

    # --- building the form ------------------------------------------------------------

    def _group(self, layout, title):
        from .qt import QtWidgets

        box = QtWidgets.QGroupBox(title)
        rows = QtWidgets.QFormLayout(box)
        rows.setRowWrapPolicy(QtWidgets.QFormLayout.WrapLongRows)
        rows.setFieldGrowthPolicy(QtWidgets.QFormLayout.FieldsStayAtSizeHint)
        layout.addWidget(box)
        return rows

    def _row(self, rows, key, label, tooltip, widget):
        from .qt import QtWidgets

        pref = preferences.PREFERENCES[key]
        widget.setToolTip(tooltip)
        widget.setObjectName(key)
        self.fields[key] = widget
        if pref.type is bool:
            rows.addRow(widget)
        else:
            # Room for its widest value (Qt 6 sizes a spin box below its minimumSizeHint).
            widget.setMinimumWidth(max(SPIN_WIDTH, widget.minimumSizeHint().width()))
            widget.setSizePolicy(QtWidgets.QSizePolicy.Fixed, QtWidgets.QSizePolicy.Fixed)
            text = QtWidgets.QLabel(label)
            text.setToolTip(tooltip)
            text.setBuddy(widget)
            rows.addRow(text, widget)
        return widget

    def _float(self, rows, key, label, tooltip, suffix="", decimals=2, step=1.0):
        from .qt import QtWidgets

        pref = preferences.PREFERENCES[key]
        box = QtWidgets.QDoubleSpinBox()
        box.setDecimals(decimals)
        box.setRange(pref.minimum, pref.maximum)
        box.setSingleStep(step)
        box.setSuffix(suffix)
        return self._row(rows, key, label, tooltip, box)

    def _tolerance(self, rows, key, label, tooltip, suffix=""):
        pref = preferences.PREFERENCES[key]
        return self._row(rows, key, label, tooltip, _tolerance_spin_box(pref.minimum, pref.maximum, suffix))

    def _int(self, rows, key, label, tooltip, step=1):
        from .qt import QtWidgets

        pref = preferences.PREFERENCES[key]
        box = QtWidgets.QSpinBox()
        box.setRange(pref.minimum, pref.maximum)
        box.setSingleStep(step)
        return self._row(rows, key, label, tooltip, box)

    def _bool(self, rows, key, label, tooltip):
        from .qt import QtWidgets

        return self._row(rows, key, label, tooltip, QtWidgets.QCheckBox(label))

    # --- what FreeCAD calls -----------------------------------------------------------

    def loadSettings(self):
        """Show the stored preferences (the defaults where none is stored)."""
        for key, widget in self.fields.items():
            value = preferences.get(key)
            if preferences.PREFERENCES[key].type is bool:
                widget.setChecked(value)
            else:
                widget.setValue(value)

    def saveSettings(self):
        """Store what the page shows. A preference never stored and left at its default
        stays unstored, so it follows the default of later versions. Combs shown redraw."""
        for key, widget in self.fields.items():
            value = widget.isChecked() if preferences.PREFERENCES[key].type is bool else widget.value()
            if preferences.is_set(key) or value != preferences.get(key):
                preferences.set_value(key, value)
        comb = sys.modules.get(__package__ + ".comb")
        if comb is not None:
            comb.refresh()
