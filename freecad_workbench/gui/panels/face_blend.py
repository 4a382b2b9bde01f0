"""Task panel of a face blend (issue 29): continuity, flip, the covered part of the edges, and
how far the blend runs along each face (the cross-boundary derivative magnitude alpha, as a
multiple of the default; "Fair (automatic)": chosen for fair cross sections). Every change
recomputes at once; OK keeps the changes as one undo step, Cancel restores. The report says
how each side was matched, the measured gap, angle and curvature jump, and how many cross
sections have certified monotone curvature. Zebra on the faces and the continuity check of
the blend with its faces are a click away."""
import math

import FreeCAD

from ...features.face_blend import FaceBlend
from .. import icon_path
from .form import (
    ERROR_STYLE,
    LiveEdit,
    LiveEditPanel,
    button_column,
    compact,
    form_rows,
    new_form,
    show_status,
    wrapped_label,
)

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

NAME = "FairSplines_BlendFaces"
CONTINUITIES = ("G2", "G1")
CONTINUITY_LABELS = {
    "G2": QT_TRANSLATE_NOOP("FairSplines", "Curvature (G2)"),
    "G1": QT_TRANSLATE_NOOP("FairSplines", "Tangent (G1)"),
}
# The depth slider: multiples of the default magnitude on a log scale, SCALE_MIN to SCALE_MAX.
SCALE_MIN, SCALE_MAX, SCALE_STEPS = 0.2, 5.0, 100
SIDES = ("A", "B")
# The continuity check joins the blend and its faces in one shell; sharing a circle with the
# B-spline blend puts the shared edge's pcurves a few 1e-6 of the size off (fw.blend_errors
# measures 1e-16 on the surfaces themselves): gaps are judged against this part of the size.
SEWN_GAP = 1e-5


def scale_to_step(scale):
    """Slider position of a multiple of the default magnitude (log scale, clamped)."""
    t = math.log(max(SCALE_MIN, min(SCALE_MAX, scale)) / SCALE_MIN) / math.log(SCALE_MAX / SCALE_MIN)
    return int(round(t * SCALE_STEPS))


def step_to_scale(step):
    return SCALE_MIN * (SCALE_MAX / SCALE_MIN) ** (step / SCALE_STEPS)


def _number(value):
    return "0" if value == 0 else f"{value:.1e}" if abs(value) < 1e-3 else f"{value:.3g}"


def report_lines(report):
    """The report of the last good build in designers' words: each side's match and depth, the
    measured errors, the cross sections' certificates."""
    lines = []
    for k, (side, errors) in enumerate(zip(report.sides, report.errors or (None, None))):
        if side["method"] == "exact":
            kind = translate("FairSplines", "exact (face's poles)")
        else:
            kind = translate("FairSplines", "fitted ({} spans)").format(side["spans"])
        lines.append(translate("FairSplines", "Side {}: {}").format(SIDES[k], kind))
        if errors is not None:
            lines.append(translate("FairSplines", "  gap {} mm, angle {}\u00b0, jump {} %").format(
                _number(errors["gap_abs"]), _number(errors["angle"]), _number(100.0 * errors["curvature_jump"])))
    sections = report.sections
    monotone = sum(bool(s["monotone"]) for s in sections)
    most = max((s["curvature_extrema"] for s in sections), default=0)
    lines.append(translate("FairSplines", "Sections with monotone curvature (certified): {} of {}").format(
        monotone, len(sections)))
    if monotone < len(sections):
        worst = [i + 1 for i, s in enumerate(sections) if s["curvature_extrema"] == most]
        lines.append(translate("FairSplines", "Most curvature extrema: {} (section {})").format(
            most, ", ".join(map(str, worst[:3]))))
    return lines


class _DepthRow:
    """One side's depth: "Fair (automatic)" (the property 0), or a slider of multiples of
    the default magnitude."""

    def __init__(self, panel, rows, prop, title):
        from ..qt import QtCore, QtWidgets

        self.panel, self.prop = panel, prop
        self.fair = QtWidgets.QCheckBox(translate("FairSplines", "Fair (automatic)"))
        self.fair.setToolTip(translate(
            "FairSplines", "The derivative magnitude alpha across the edge chosen for fair cross sections: "
                           "fewest curvature extrema, then least scale-free curvature variation L\u00b3\u222b"
                           "(d\u03ba/ds)\u00b2ds, by a grid and pattern search over the 13 sections"))
        self.slider = QtWidgets.QSlider(QtCore.Qt.Horizontal)
        self.slider.setRange(0, SCALE_STEPS)
        self.slider.setTracking(False)  # recompute on release, not per pixel dragged
        self.slider.setMinimumWidth(80)
        self.slider.setToolTip(translate(
            "FairSplines", "How far the blend runs along this face before turning: the cross-boundary "
                           "derivative magnitude alpha, {} to {} times the default (mean chord over mean "
                           "cross-boundary speed)").format(SCALE_MIN, SCALE_MAX))
        self.value = QtWidgets.QLabel()
        self.row = QtWidgets.QHBoxLayout()
        self.row.addWidget(self.slider, 1)
        self.row.addWidget(self.value)
        rows.addRow(title, self.fair)
        rows.addRow(self.row)
        self.fair.toggled.connect(self.set_fair)
        self.slider.valueChanged.connect(self.set_step)

    def set_fair(self, on):
        if self.panel.updating:
            return
        if on:
            self.panel.apply([(self.prop, 0.0)])
        else:  # start the slider where the fair choice is, so the shape does not jump
            self.panel.apply([(self.prop, step_to_scale(self.slider.value()))])

    def set_step(self, step):
        if not self.panel.updating and not self.fair.isChecked():
            self.panel.apply([(self.prop, step_to_scale(step))])

    def show(self, value, chosen):
        """value: the property (0: fair); chosen: the scale the last build used, or None."""
        fair = value <= 0
        self.fair.setChecked(fair)
        self.slider.setEnabled(not fair)
        scale = chosen if fair and chosen is not None else value if not fair else 1.0
        self.slider.setValue(scale_to_step(scale))
        self.value.setText(f"\u00d7 {scale:.2f}")


class FaceBlendPanel(LiveEditPanel):
    """Continuity, flip, covered part, depth per side, report; zebra on the faces and the
    continuity check of the blend with its faces."""

    PROPERTIES = ("ContinuityA", "ContinuityB", "Flip", "Start", "End", "ScaleA", "ScaleB")

    def __init__(self, obj):
        from ..qt import QtWidgets

        self.obj = obj
        self.doc = obj.Document
        self.session = LiveEdit(obj, translate("FairSplines", "Edit face blend"), self.PROPERTIES)
        self.updating = False
        self.zebra_objects = []
        self.form, layout = new_form(translate("FairSplines", "Blend faces"), icon_path(NAME))
        self.sources = wrapped_label()
        layout.addWidget(self.sources)
        rows = form_rows(layout)
        # One choice per side: the blend's degree across is the two sides' rows less one (5 for
        # G2 at both, 4 for G2 at one and G1 at the other, 3 for G1 at both).
        self.continuities = []
        for prop, title in (("ContinuityA", translate("FairSplines", "At face A")),
                            ("ContinuityB", translate("FairSplines", "At face B"))):
            combo = compact(QtWidgets.QComboBox(), 110)
            combo.addItems([translate("FairSplines", CONTINUITY_LABELS[c]) for c in CONTINUITIES])
            combo.setToolTip(translate(
                "FairSplines", "G2: the blend meets this face in position, tangent plane and normal curvature "
                               "in every direction; G1: in position and tangent plane only. Exact where the edge "
                               "is an isoparametric boundary (the face's homogeneous poles), else fitted within "
                               "the tolerances. Across, the blend is a quintic (G2 at both faces), a quartic (G2 "
                               "at one) or a cubic (G1 at both)"))
            combo.currentIndexChanged.connect(lambda i, p=prop: self.apply([(p, CONTINUITIES[i])]))
            rows.addRow(title, combo)
            self.continuities.append(combo)
        self.flip = QtWidgets.QCheckBox(translate("FairSplines", "Flip direction"))
        self.flip.setToolTip(translate("FairSplines", "Pair the start of the first edge with the end of the second "
                                                      "(for a twisted blend, try this)"))
        self.flip.toggled.connect(lambda on: self.apply([("Flip", bool(on))]))
        rows.addRow(self.flip)
        self.start = self._spin(0.0, 100.0, " %", 1)
        self.start.setToolTip(translate("FairSplines", "Where the blend starts along each edge, in % of its length "
                                                       "in parameter"))
        self.end = self._spin(0.0, 100.0, " %", 1)
        self.end.setToolTip(translate("FairSplines", "Where the blend ends along each edge, in % of its length "
                                                     "in parameter"))
        self.start.valueChanged.connect(lambda v: self.apply([("Start", v / 100.0)]))
        self.end.valueChanged.connect(lambda v: self.apply([("End", v / 100.0)]))
        rows.addRow(translate("FairSplines", "From"), self.start)
        rows.addRow(translate("FairSplines", "To"), self.end)
        self.depths = [_DepthRow(self, rows, "ScaleA", translate("FairSplines", "Depth A")),
                       _DepthRow(self, rows, "ScaleB", translate("FairSplines", "Depth B"))]
        self.zebra = QtWidgets.QPushButton(translate("FairSplines", "Zebra on the faces"))
        self.zebra.setCheckable(True)
        self.zebra.setToolTip(translate("FairSplines", "Reflected stripes on the two faces too: across a G2 join "
                                                       "they run on smoothly, across G1 they bend, across G0 they "
                                                       "break"))
        self.zebra.toggled.connect(self.show_zebra)
        self.check = QtWidgets.QPushButton(translate("FairSplines", "Check continuity"))
        self.check.setCheckable(True)
        self.check.setToolTip(translate("FairSplines", "The edges of the blend and its two faces, in one shell, "
                                                       "coloured by their measured continuity (gap, G0, G1, G2; "
                                                       "fw.edge_continuity)"))
        self.check.toggled.connect(self.show_check)
        self.report = wrapped_label()
        self.report.setToolTip(translate(
            "FairSplines", "Exact: the blend's boundary rows from the face's homogeneous poles. Gap, angle and "
                           "curvature jump (across the edge and at 45\u00b0, in % of the curvature scale): "
                           "measured by OCCT at 101 points of each edge (fw.blend_errors). Monotone: the exact "
                           "certificate of monotone curvature of each cross section (rational Bezier)"))
        layout.addWidget(self.report)
        self.status = wrapped_label()
        layout.addWidget(self.status)
        layout.addLayout(button_column(self.zebra, self.check))
        self.joins = wrapped_label()
        layout.addWidget(self.joins)
        layout.addStretch(1)
        self.refresh()

    def apply(self, changes):
        """Set [(property, value)] that differ, recompute (FreeCAD's error state on failure)."""
        if self.updating:
            return
        changes = [(p, v) for p, v in changes if getattr(self.obj, p) != v]
        if changes:
            self._apply(changes)

    # --- views -----------------------------------------------------------------------

    def source_objects(self):
        return [link[0] for link in (self.obj.FaceA, self.obj.FaceB) if link]

    def show_zebra(self, on):
        from .. import zebra_shape

        for obj in self.zebra_objects:
            zebra_shape.hide(obj)
        self.zebra_objects = []
        if on:  # the blend's own stripes, so that they run on across a G2 join
            stripes = getattr(self.obj.ViewObject, "Stripes", None) if self.obj.ViewObject is not None else None
            for obj in dict.fromkeys(self.source_objects()):
                zebra_shape.show(obj, stripes=stripes, vertical=True)
                self.zebra_objects.append(obj)

    def check_links(self):
        """The blend's face and its two faces, for the continuity check."""
        links = [(self.obj, "Face1")]
        for link in (self.obj.FaceA, self.obj.FaceB):
            if link:
                links.append((link[0], link[1][0]))
        return links

    def show_check(self, on):
        from .. import continuity

        continuity.hide()
        self.joins.setText("")
        if not on or self.obj.Shape.isNull():
            return
        size = self.obj.Shape.BoundBox.DiagonalLength
        check = continuity.show(self.check_links(), gap_tolerance=SEWN_GAP * size)
        shared = [r for r in check.records if r.kind == "shared"] if check is not None else []
        counts = {}
        for r in shared:
            counts[r.continuity] = counts.get(r.continuity, 0) + 1
        words = {v: translate("FairSplines", continuity.VERDICTS.get(v, continuity.OTHER)[1]) for v in counts}
        self.joins.setText(translate("FairSplines", "Joins: {}").format(
            ", ".join(f"{n} \u00d7 {words[v]}" for v, n in counts.items()) or translate("FairSplines", "none found")))

    def refresh(self):
        obj = self.obj
        self.updating = True
        try:
            texts = []
            for side, face, edge in (("A", obj.FaceA, obj.EdgeA), ("B", obj.FaceB, obj.EdgeB)):
                if face and edge:
                    texts.append(translate("FairSplines", "{}: {}, {} of {}").format(
                        side, face[0].Label, edge[1][0], face[1][0]))
            self.sources.setText("\n".join(texts))
            for combo, value in zip(self.continuities, (obj.ContinuityA, obj.ContinuityB)):
                combo.setCurrentIndex(CONTINUITIES.index(value))
            self.flip.setChecked(bool(obj.Flip))
            self.start.setValue(100.0 * obj.Start)
            self.end.setValue(100.0 * obj.End)
            report = getattr(obj.Proxy, "report", None) if isinstance(obj.Proxy, FaceBlend) else None
            for k, depth in enumerate(self.depths):
                depth.show(getattr(obj, depth.prop), report.sides[k]["scale"] if report is not None else None)
        finally:
            self.updating = False
        self.report.setText("\n".join(report_lines(report)) if report is not None else "")
        status = obj.Status
        show_status(self.status, "ok" if status.startswith("ok") else status)
        if status.startswith("ok") or report is None:
            self.report.setStyleSheet("")
        else:  # the shape shown is the last good one: say so
            self.report.setStyleSheet(ERROR_STYLE)
        if self.check.isChecked():
            self.show_check(True)

    def finish(self):
        from .. import continuity

        continuity.hide()
        self.show_zebra(False)
