"""Task panel of a Blend basic shape: kind, a Revolution's profile (taken from the selection:
a sketch, a Design spline or edges), dimensions, the partitions (uniform counts and
range, or the lists as comma-separated values), how the strip is parametrised, the
continuity and the free-form side. Every change recomputes at once; OK keeps the changes
as one undo step, Cancel restores."""
import FreeCAD
import FreeCADGui

from ...errors import InputError
from ...features.blend_shape import (
    CONTINUITIES,
    INTERFACES,
    KIND_DEFAULTS,
    KIND_LENGTHS,
    KIND_LISTS,
    KIND_PROPERTIES,
    KINDS,
    METHODS,
    PROFILE_IN_DEGREES,
    angle_lists,
    basic_shape,
    is_blend_shape,
    profile_link,
)
from .. import icon_path
from .form import LiveEdit, LiveEditPanel, button_column, compact, form_rows, show_status, wrapped_label

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

NAME = "FairSplines_BlendBasicShape"

# What the choices mean for the shape; the paper's names are in the tooltips.
METHOD_LABELS = {
    "rho": QT_TRANSLATE_NOOP("FairSplines", "3 pieces per arc (\u03c1)"),
    "sigma": QT_TRANSLATE_NOOP("FairSplines", "1 piece per arc (\u03c3)"),
    "mixed": QT_TRANSLATE_NOOP("FairSplines", "Mixed (\u03c1 where arcs differ)"),
}
CONTINUITY_LABELS = {
    "C2": QT_TRANSLATE_NOOP("FairSplines", "Curvature (C2)"),
    "C1": QT_TRANSLATE_NOOP("FairSplines", "Tangent (C1)"),
}

_LABELS = {
    "Radius": QT_TRANSLATE_NOOP("FairSplines", "Radius"),
    "Radius0": QT_TRANSLATE_NOOP("FairSplines", "Radius at height 0"),
    "Slope": QT_TRANSLATE_NOOP("FairSplines", "Slope"),
    "MajorRadius": QT_TRANSLATE_NOOP("FairSplines", "Major radius"),
    "MinorRadius": QT_TRANSLATE_NOOP("FairSplines", "Minor radius"),
    "Longitudes": QT_TRANSLATE_NOOP("FairSplines", "Longitudes (°)"),
    "Latitudes": QT_TRANSLATE_NOOP("FairSplines", "Latitudes (°)"),
    "Angles": QT_TRANSLATE_NOOP("FairSplines", "Angles (°)"),
    "Heights": QT_TRANSLATE_NOOP("FairSplines", "Heights"),
    "AnglesU": QT_TRANSLATE_NOOP("FairSplines", "Around the axis (°)"),
    "AnglesV": QT_TRANSLATE_NOOP("FairSplines", "Around the tube (°)"),
    "AroundCount": QT_TRANSLATE_NOOP("FairSplines", "Arcs around"),
    "ProfileCount": QT_TRANSLATE_NOOP("FairSplines", "Profile pieces"),
    "ProfileStart": QT_TRANSLATE_NOOP("FairSplines", "Profile from"),
    "ProfileEnd": QT_TRANSLATE_NOOP("FairSplines", "Profile to"),
    "ProfileFractions": QT_TRANSLATE_NOOP("FairSplines", "Profile fractions"),
}

# The long words of the short labels above.
_TOOLTIPS = {
    "Slope": QT_TRANSLATE_NOOP("FairSplines", "How much the radius grows per unit of height"),
    "AnglesU": QT_TRANSLATE_NOOP("FairSplines", "Angles around the torus' axis, in degrees, where the arcs meet"),
    "AnglesV": QT_TRANSLATE_NOOP("FairSplines", "Angles around the tube, in degrees, where the profile's arcs meet"),
    "ProfileCount": QT_TRANSLATE_NOOP("FairSplines", "Pieces along the profile (its arcs or segments)"),
}


def format_list(values):
    return ", ".join(f"{v:g}" for v in values)


def parse_list(text):
    """Comma- (or space-) separated numbers -> [float]; InputError names a bad entry."""
    values = []
    for item in text.replace(";", ",").replace(" ", ",").split(","):
        if item.strip():
            try:
                values.append(float(item))
            except ValueError:
                raise InputError(f"not a number: {item.strip()!r}") from None
    return values


class BlendShapePanel(LiveEditPanel):
    """Task panel of a Blend basic shape: kind, dimensions, the partitions (uniform counts
    and range, or the lists as comma-separated values), method and the naive variant. Every
    change recomputes at once; OK keeps the changes as one undo step, Cancel restores."""

    def __init__(self, obj):
        from ..qt import QtGui, QtWidgets

        self.obj = obj
        self.doc = obj.Document
        dimensions = sorted({p for props in KIND_PROPERTIES.values() for p in props})
        self.session = LiveEdit(obj, translate("FairSplines", "Edit blend basic shape"),
                                ["Kind", "Uniform", "Method", "Naive", "FreeForm", "FreeFormStart", "Interface",
                                 "JoinTo", "Continuity", "Profile"] + dimensions)
        self._updating = False
        self.widgets = {}

        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("FairSplines", "Blend basic shape"))
        self.form.setWindowIcon(QtGui.QIcon(icon_path(NAME)))
        layout = QtWidgets.QVBoxLayout(self.form)
        top = form_rows()
        self.kind = compact(QtWidgets.QComboBox(), 120)
        self.kind.addItems([translate("FairSplines", k) for k in KINDS])
        self.kind.setCurrentIndex(KINDS.index(obj.Kind))
        self.kind.currentIndexChanged.connect(lambda i: self.set_kind(KINDS[i]))
        top.addRow(translate("FairSplines", "Kind"), self.kind)
        self.uniform = QtWidgets.QCheckBox(translate("FairSplines", "Uniform partitions"))
        self.uniform.setChecked(bool(obj.Uniform))
        self.uniform.toggled.connect(self.set_uniform)
        top.addRow(self.uniform)
        layout.addLayout(top)
        # A Revolution's profile: what is selected in the 3D view or the tree.
        self.profile_box = QtWidgets.QGroupBox(translate("FairSplines", "Profile"))
        profile_layout = QtWidgets.QVBoxLayout(self.profile_box)
        self.profile_label = wrapped_label()
        profile_layout.addWidget(self.profile_label)
        self.use_profile = QtWidgets.QPushButton(translate("FairSplines", "Use selected profile"))
        self.use_profile.setToolTip(translate(
            "FairSplines", "A sketch, a Design spline or edges, in a plane through the shape's axis and off "
                           "the axis; revolved around the axis"))
        self.use_profile.clicked.connect(self.use_selected_profile)
        self.default_profile = QtWidgets.QPushButton(translate("FairSplines", "Default parabola"))
        self.default_profile.clicked.connect(lambda: self.set_profile(None))
        profile_layout.addLayout(button_column(self.use_profile, self.default_profile))
        layout.addWidget(self.profile_box)
        self.dimensions_box = QtWidgets.QGroupBox(translate("FairSplines", "Dimensions"))
        self.dimensions = form_rows(box=self.dimensions_box)
        layout.addWidget(self.dimensions_box)
        join_box = QtWidgets.QGroupBox(translate("FairSplines", "Join"))
        bottom = form_rows(box=join_box)
        self.method = compact(QtWidgets.QComboBox(), 120)
        self.method.addItems([translate("FairSplines", METHOD_LABELS[m]) for m in METHODS])
        self.method.setToolTip(translate(
            "FairSplines", "How the circles of the shape are reparametrised so that they join C2 (Section 3): "
                           "\u03c1, three rational pieces per arc (Appendix 7.1); \u03c3, one sextic per arc "
                           "(eqs. (7)-(8)); mixed, \u03c1 only where neighbouring arcs differ"))
        self.method.setCurrentIndex(METHODS.index(obj.Method))
        self.method.currentIndexChanged.connect(lambda i: self.set_method(METHODS[i]))
        bottom.addRow(translate("FairSplines", "Circles as"), self.method)
        self.continuity = compact(QtWidgets.QComboBox(), 120)
        self.continuity.addItems([translate("FairSplines", CONTINUITY_LABELS[c]) for c in CONTINUITIES])
        self.continuity.setCurrentIndex(CONTINUITIES.index(obj.Continuity))
        self.continuity.setToolTip(translate("FairSplines", "C2: (6,5) strip to bicubic NURBS (Section 4.2); "
                                                            "C1: (4,2) double strip to biquadratic NURBS (Section 5)"))
        self.continuity.currentIndexChanged.connect(lambda i: self.set_continuity(CONTINUITIES[i]))
        bottom.addRow(translate("FairSplines", "Continuous in"), self.continuity)
        self.naive = QtWidgets.QCheckBox(translate("FairSplines", "Plain join"))
        self.naive.setToolTip(translate("FairSplines", "To compare: the paper's naive blend (Fig. 2a), the shape and "
                                                       "the ring joined without the transition strip; its seams show"))
        self.naive.setChecked(bool(obj.Naive))
        self.naive.toggled.connect(self.set_naive)
        bottom.addRow(self.naive)
        self.interface = compact(QtWidgets.QComboBox(), 120)
        self.interface.addItems([translate("FairSplines", i) for i in INTERFACES])
        self.interface.setCurrentIndex(INTERFACES.index(obj.Interface))
        self.interface.setToolTip(translate("FairSplines", "Which end of the profile joins the free-form side; "
                                                           "Auto: the end, or the start where the end is a pole; "
                                                           "Both ends: free-form on both sides, as for a ball "
                                                           "joint's band. Joined to another shape: Start adds "
                                                           "free-form below this shape, End beyond the other one"))
        self.interface.currentIndexChanged.connect(lambda i: self.set_interface(INTERFACES[i]))
        bottom.addRow(translate("FairSplines", "Join at"), self.interface)
        layout.addWidget(join_box)
        freeform_box = QtWidgets.QGroupBox(translate("FairSplines", "Free-form side"))
        freeform_layout = QtWidgets.QVBoxLayout(freeform_box)
        self.freeform_label = wrapped_label()
        freeform_layout.addWidget(self.freeform_label)
        buttons = QtWidgets.QVBoxLayout()
        self.use_face = QtWidgets.QPushButton(translate("FairSplines", "Use selected face"))
        self.use_face.setToolTip(translate("FairSplines", "A B-spline face, bicubic and periodic around the axis "
                                                          "(any knots), its first row near the interface"))
        self.use_face.clicked.connect(self.use_selected_face)
        self.default_ring = QtWidgets.QPushButton(translate("FairSplines", "Default ring"))
        self.default_ring.clicked.connect(lambda: self.set_freeform(None))
        buttons.addWidget(self.use_face)
        buttons.addWidget(self.default_ring)
        freeform_layout.addLayout(buttons)
        # The second interface (Both ends): the free-form side at the start of the profile.
        self.start_box = QtWidgets.QWidget()
        start_layout = QtWidgets.QVBoxLayout(self.start_box)
        start_layout.setContentsMargins(0, 0, 0, 0)
        self.start_label = wrapped_label()
        start_layout.addWidget(self.start_label)
        self.use_face_start = QtWidgets.QPushButton(translate("FairSplines", "Use selected face at the start"))
        self.use_face_start.setToolTip(translate("FairSplines", "A B-spline face, bicubic and periodic around the "
                                                                "axis, its first row near the start of the profile"))
        self.use_face_start.clicked.connect(lambda: self.use_selected_face("FreeFormStart"))
        self.default_ring_start = QtWidgets.QPushButton(translate("FairSplines", "Default ring at the start"))
        self.default_ring_start.clicked.connect(lambda: self.set_freeform(None, "FreeFormStart"))
        start_layout.addWidget(self.use_face_start)
        start_layout.addWidget(self.default_ring_start)
        freeform_layout.addWidget(self.start_box)
        join_row = form_rows()
        self.join_to = compact(QtWidgets.QComboBox(), 120)
        self.join_to.setToolTip(translate("FairSplines", "Join another Blend basic shape instead of a ring (Figs. "
                                                         "9-12): this profile's end to the start of its profile"))
        self._join_choices = []
        self._fill_join_choices()
        self.join_to.currentIndexChanged.connect(lambda i: self.set_join_to(self._join_choices[i]))
        join_row.addRow(translate("FairSplines", "Or join to"), self.join_to)
        freeform_layout.addLayout(join_row)
        layout.addWidget(freeform_box)
        self.patches_label = wrapped_label()
        layout.addWidget(self.patches_label)
        self.status_label = wrapped_label()
        layout.addWidget(self.status_label)
        layout.addStretch(1)
        self._build_dimensions()
        self.refresh()

    # --- widgets ---------------------------------------------------------------------

    def _build_dimensions(self):
        """Rows for the lengths of the kind, then the counts and range (uniform) or the lists."""
        from ..qt import QtWidgets

        while self.dimensions.rowCount():
            self.dimensions.removeRow(0)
        self.widgets = {}
        kind = self.obj.Kind
        # degrees, lengths, or (Revolution) fractions of the profile's range: no unit
        profile_suffix = " °" if PROFILE_IN_DEGREES[kind] else "" if kind == "Revolution" else " mm"
        names = list(KIND_LENGTHS[kind])
        names += ["AroundCount", "ProfileCount", "ProfileStart", "ProfileEnd"] if self.obj.Uniform else list(
            KIND_LISTS[kind])
        self._updating = True
        try:
            for name in names:
                label = translate("FairSplines", _LABELS.get(name, name))
                value = getattr(self.obj, name)
                if name in KIND_LISTS[kind]:
                    edit = QtWidgets.QLineEdit(format_list(value))
                    edit.editingFinished.connect(lambda n=name: self.set_list_text(n, self.widgets[n].text()))
                    widget = edit
                elif name in ("AroundCount", "ProfileCount"):
                    widget = QtWidgets.QSpinBox()
                    widget.setRange(1, 64)
                    widget.setKeyboardTracking(False)
                    widget.setValue(int(value))
                    widget.valueChanged.connect(lambda v, n=name: self.set_dimension(n, int(v)))
                else:
                    if name == "Slope":
                        widget = self._spin(-1e3, 1e3)
                    elif name in ("ProfileStart", "ProfileEnd"):
                        widget = self._spin(-1e9, 1e9, profile_suffix)
                    else:
                        widget = self._spin(0.0, 1e9, " mm")
                    widget.setValue(float(getattr(value, "Value", value)))
                    widget.valueChanged.connect(lambda v, n=name: self.set_dimension(n, v))
                if name in _TOOLTIPS:
                    widget.setToolTip(translate("FairSplines", _TOOLTIPS[name]))
                self.dimensions.addRow(label, widget)
                self.widgets[name] = widget
        finally:
            self._updating = False

    # --- edits -----------------------------------------------------------------------

    def set_dimension(self, name, value):
        """Set one dimension (a length, a count, a list) and recompute."""
        if not self._updating:
            self._apply([(name, value)])

    def set_list_text(self, name, text):
        """Set one of the kind's lists from comma-separated values (degrees, or heights)."""
        if self._updating:
            return
        try:
            values = parse_list(text)
        except InputError as exc:
            self.show_status(str(exc))
            return
        if values != list(getattr(self.obj, name)):
            self._apply([(name, values)])
        else:
            self.refresh()

    def set_kind(self, kind):
        """Switch to another kind, with that kind's default dimensions (partitions as they are
        now: uniform or not)."""
        if self._updating or kind == self.obj.Kind:
            return
        self._apply([("Kind", kind)] + list(KIND_DEFAULTS[kind].items()))
        self._build_dimensions()
        self._select(self.kind, KINDS.index(kind))

    def set_uniform(self, on):
        """Uniform on: counts and range taken from the lists; off: the lists spelled out
        from the counts and range, to edit one by one."""
        on = bool(on)
        if self._updating or on == bool(self.obj.Uniform):
            return
        around_name, profile_name = KIND_LISTS[self.obj.Kind]
        changes = [("Uniform", on)]
        try:
            around, profile = angle_lists(self.obj)
        except InputError:
            around = profile = None
        if around is not None and len(around) > 1 and len(profile) > 1:
            if on:
                changes += [("AroundCount", len(around) - 1), ("ProfileCount", len(profile) - 1),
                            ("ProfileStart", profile[0]), ("ProfileEnd", profile[-1])]
            else:
                changes += [(around_name, around), (profile_name, profile)]
        self._apply(changes)
        self._build_dimensions()
        if self.uniform.isChecked() != on:
            self._updating = True
            self.uniform.setChecked(on)
            self._updating = False

    def _set_choice(self, prop, value, combo, choices):
        """Set an enumeration property from its combo box and recompute."""
        if not self._updating and value != getattr(self.obj, prop):
            self._apply([(prop, value)])
            self._select(combo, choices.index(value))

    def set_method(self, method):
        self._set_choice("Method", method, self.method, METHODS)

    def set_naive(self, on):
        if not self._updating and bool(on) != bool(self.obj.Naive):
            self._apply([("Naive", bool(on))])
            if self.naive.isChecked() != bool(on):
                self._updating = True
                self.naive.setChecked(bool(on))
                self._updating = False

    def set_continuity(self, continuity):
        self._set_choice("Continuity", continuity, self.continuity, CONTINUITIES)

    def set_interface(self, interface):
        self._set_choice("Interface", interface, self.interface, INTERFACES)

    def set_freeform(self, link, prop="FreeForm"):
        """Join the linked B-spline face ((object, ["FaceN"])), or the default ring (None), at
        the interface (FreeForm) or at the start for Both ends (FreeFormStart)."""
        current = getattr(self.obj, prop)
        if link is None and (current is None or current[0] is None):
            return
        self._apply([(prop, link)])

    def _fill_join_choices(self):
        """(none) and every other Blend basic shape of the document."""
        self._updating = True
        try:
            self._join_choices = [None] + [o for o in self.doc.Objects if is_blend_shape(o) and o != self.obj]
            self.join_to.clear()
            self.join_to.addItems([translate("FairSplines", "(a ring)")] + [o.Label for o in self._join_choices[1:]])
            current = self.obj.JoinTo
            self.join_to.setCurrentIndex(self._join_choices.index(current) if current in self._join_choices else 0)
        finally:
            self._updating = False

    def set_join_to(self, other):
        """Join the basic shape of `other` (a Blend basic shape), or a ring again (None); the
        other object's own blend is hidden."""
        if self._updating or other == self.obj.JoinTo:
            return
        self._apply([("JoinTo", other)])
        if other is not None:
            other.ViewObject.Visibility = False

    def use_selected_face(self, prop="FreeForm"):
        """The face selected in the 3D view (not one of this object's own) as the free-form side
        (prop FreeFormStart: the one at the start, for Both ends)."""
        for sel in FreeCADGui.Selection.getSelectionEx(self.doc.Name):
            if sel.Object == self.obj:
                continue
            faces = [n for n in sel.SubElementNames if n.startswith("Face")]
            if faces:
                self.set_freeform((sel.Object, [faces[0]]), prop)
                return
            if len(getattr(sel.Object, "Shape", None) and sel.Object.Shape.Faces or []) == 1:
                self.set_freeform((sel.Object, ["Face1"]), prop)
                return
        self.show_status(translate("FairSplines", "select a B-spline face of another object first"))

    def set_profile(self, link):
        """Revolve the linked profile ((object, [edge names])), or the default parabola (None)."""
        current = self.obj.Profile
        if link is None and (current is None or current[0] is None):
            return
        self._apply([("Profile", link)])

    def use_selected_profile(self):
        """The object selected in the 3D view or the tree (a sketch, a Design spline, any
        object's edges) as the Revolution's profile. A selection that is no profile (a face, a
        solid, a curve crossing the axis) is refused with the reason; the shape stays."""
        selection = [s for s in FreeCADGui.Selection.getSelectionEx(self.doc.Name) if s.Object != self.obj]
        if not selection:
            self.show_message(translate("FairSplines", "Select a sketch, a Design spline or edges first"))
            return
        try:
            link = profile_link(selection[0].Object, selection[0].SubElementNames)
            basic_shape(self.obj, trial_profile=link)  # the revolution of it, before taking it
        except InputError as exc:
            self.show_message(translate("FairSplines", "Profile not taken: {}").format(exc))
            return
        self._apply([("Profile", link)])

    def show_message(self, text):
        """A refusal in the status line (red), until the next change."""
        from .form import ERROR_STYLE

        self.status_label.setText(text)
        self.status_label.setStyleSheet(ERROR_STYLE)
        self.status_label.setVisible(True)

    def _select(self, combo, index):
        if combo.currentIndex() != index:
            self._updating = True
            combo.setCurrentIndex(index)
            self._updating = False

    def show_status(self, message):
        show_status(self.status_label, message)

    def refresh(self):
        self.patches_label.setText(translate("FairSplines", "Patches: {}").format(self.obj.Patches))
        self.profile_box.setVisible(self.obj.Kind == "Revolution")
        self.profile_label.setText(_profile_text(self.obj.Profile))
        both = self.obj.Interface == "Both ends"
        text = _link_text(self.obj.FreeForm)
        if self.obj.JoinTo is not None:
            text = translate("FairSplines", "Joined to {}").format(self.obj.JoinTo.Label)
        elif both:
            text = translate("FairSplines", "At the end: {}").format(text)
        self.freeform_label.setText(text)
        self.start_box.setVisible(both and self.obj.JoinTo is None)
        self.start_label.setText(translate("FairSplines", "At the start: {}").format(
            _link_text(self.obj.FreeFormStart)))
        self.show_status(self.obj.Status)


def _profile_text(link):
    """A Revolution's profile as the panel shows it: the object's label (and its edges), or
    the default parabola."""
    if link is None or link[0] is None:
        return translate("FairSplines", "Default parabola (no profile picked)")
    subs = [s for s in link[1] if s]
    return f"{link[0].Label}.{', '.join(subs)}" if subs else link[0].Label


def _link_text(link):
    """A free-form link as the panel shows it: the face's object and name, or the default ring."""
    if link is None or link[0] is None:
        return translate("FairSplines", "Default ring (continues the shape)")
    subs = ", ".join(link[1]) if link[1] else ""
    return f"{link[0].Label}.{subs}" if subs else link[0].Label
