"""The blending command (GUI only): a Blend basic shape, its task panel and its view provider.
The command records a replayable macro line.

FairSplines_BlendBasicShape   a sphere zone, cylinder, cone or torus joined C2 (Section 4.2) or
                              C1 (Section 5) to a free-form ring, a selected B-spline face or
                              another Blend basic shape (blending paper); its panel opens and
                              previews live; the shell is shown with zebra shading
"""
import FreeCAD
import FreeCADGui

from ..features.blend_shape import (
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
    is_blend_shape,
)
from ..errors import InputError
from . import icon_path
from .design_commands import _edit_later, _new_object
from .design_view_providers import ViewProviderProfileTest, _ViewProvider, _local_shape
from .live_edit import LiveEdit, LiveEditPanel

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

NAME = "FairSplines_BlendBasicShape"
COMMANDS = (NAME,)

# Zebra mesh of each face (a patch of the shell): samples per face, at least 4 per knot span.
FACE_SAMPLES = 12

_LABELS = {
    "Radius": "Radius",
    "Radius0": "Radius at height 0",
    "Slope": "Slope (radius per height)",
    "MajorRadius": "Major radius",
    "MinorRadius": "Minor radius",
    "Longitudes": "Longitudes (°)",
    "Latitudes": "Latitudes (°)",
    "Angles": "Angles (°)",
    "Heights": "Heights",
    "AnglesU": "Angles around the axis (°)",
    "AnglesV": "Angles around the tube (°)",
    "AroundCount": "Arcs around",
    "ProfileCount": "Pieces along the profile",
    "ProfileStart": "Profile from",
    "ProfileEnd": "Profile to",
}


# --- view provider ---------------------------------------------------------------------------


def update_zebra_faces(node, faces, samples=FACE_SAMPLES):
    """Mesh every face's surface into one ZebraNode (gui/zebra.py), or clear it."""
    import numpy as np

    from .zebra import zebra_mesh

    if not faces:
        node.update(None)
        return
    points, normals, index, offset = [], [], [], 0
    for face in faces:
        p, n, quads, _ = zebra_mesh(face.Surface, samples, samples)
        if face.Orientation == "Reversed":
            n = -n
        points.append(p)
        normals.append(n)
        index.append(np.c_[quads + offset, -np.ones(len(quads), dtype=int)].ravel())
        offset += len(p)
    points, normals = np.concatenate(points), np.concatenate(normals)
    index = np.concatenate(index).tolist()
    node.clear()
    node.coords.point.setValues(0, len(points), points.tolist())
    node.normals.vector.setValues(0, len(normals), normals.tolist())
    node.faces.coordIndex.setValues(0, len(index), index)
    node.faces.normalIndex.setValues(0, len(index), index)
    node.vertex_count = len(points)


class ViewProviderBlendShape(ViewProviderProfileTest):
    """The blended shell in the 'Zebra' display mode (the default; gui/zebra.py), every patch
    meshed, so that the stripes show how the basic shape, the transition and the ring join.
    Double-click opens the task panel."""

    ICON = "FairSplines_BlendBasicShape"
    ERROR_ICON = "FairSplines_BlendBasicShapeError"

    def update_zebra(self, force=False):
        obj = getattr(self, "Object", None)
        if obj is None or not hasattr(self, "zebra"):
            return
        shape = obj.Shape
        if not force and self.meshed is not None and self.meshed.isEqual(shape):
            return
        update_zebra_faces(self.zebra, [] if shape.isNull() else _local_shape(obj).Faces)
        self.meshed = shape

    def make_panel(self, obj):
        return BlendShapePanel(obj)

    doubleClicked = _ViewProvider.doubleClicked
    setupContextMenu = _ViewProvider.setupContextMenu


# --- command ---------------------------------------------------------------------------------


class BlendBasicShapeCommand:
    def GetResources(self):
        return {
            "Pixmap": icon_path(NAME),
            "MenuText": QT_TRANSLATE_NOOP(NAME, "Blend basic shape"),
            "ToolTip": QT_TRANSLATE_NOOP(
                NAME,
                "A sphere zone, cylinder, cone or torus kept exact and joined C2 (or C1) to a free-form\n"
                "ring, a selected B-spline face or another basic shape (non-uniform partitions allowed).\n"
                "Set it up in the panel; zebra stripes show the seams.",
            ),
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        doc = FreeCAD.ActiveDocument
        before = {o.Name for o in doc.Objects}
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("from freecad_workbench.features.blend_shape import make_blend_shape")
        FreeCADGui.doCommand(f"make_blend_shape(FreeCAD.getDocument({doc.Name!r}), 'Sphere zone')")
        obj = _new_object(doc, before)
        if obj is not None:
            _edit_later(obj)


# --- task panel ------------------------------------------------------------------------------


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
        from .qt import QtGui, QtWidgets

        self.obj = obj
        self.doc = obj.Document
        dimensions = sorted({p for props in KIND_PROPERTIES.values() for p in props})
        self.session = LiveEdit(obj, translate("FairSplines", "Edit blend basic shape"),
                                ["Kind", "Uniform", "Method", "Naive", "FreeForm", "Interface", "JoinTo",
                                 "Continuity"] + dimensions)
        self._updating = False
        self.widgets = {}

        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("FairSplines", "Blend basic shape"))
        self.form.setWindowIcon(QtGui.QIcon(icon_path(NAME)))
        layout = QtWidgets.QVBoxLayout(self.form)
        top = QtWidgets.QFormLayout()
        self.kind = QtWidgets.QComboBox()
        self.kind.addItems([translate("FairSplines", k) for k in KINDS])
        self.kind.setCurrentIndex(KINDS.index(obj.Kind))
        self.kind.currentIndexChanged.connect(lambda i: self.set_kind(KINDS[i]))
        top.addRow(translate("FairSplines", "Kind"), self.kind)
        self.uniform = QtWidgets.QCheckBox(translate("FairSplines", "Uniform partitions"))
        self.uniform.setChecked(bool(obj.Uniform))
        self.uniform.toggled.connect(self.set_uniform)
        top.addRow(self.uniform)
        layout.addLayout(top)
        self.dimensions_box = QtWidgets.QGroupBox(translate("FairSplines", "Dimensions"))
        self.dimensions = QtWidgets.QFormLayout(self.dimensions_box)
        layout.addWidget(self.dimensions_box)
        bottom = QtWidgets.QFormLayout()
        self.method = QtWidgets.QComboBox()
        self.method.addItems(list(METHODS))
        self.method.setCurrentIndex(METHODS.index(obj.Method))
        self.method.currentIndexChanged.connect(lambda i: self.set_method(METHODS[i]))
        bottom.addRow(translate("FairSplines", "Method"), self.method)
        self.continuity = QtWidgets.QComboBox()
        self.continuity.addItems(list(CONTINUITIES))
        self.continuity.setCurrentIndex(CONTINUITIES.index(obj.Continuity))
        self.continuity.setToolTip(translate("FairSplines", "C2: (6,5) strip to bicubic NURBS (Section 4.2); "
                                                            "C1: (4,2) double strip to biquadratic NURBS (Section 5)"))
        self.continuity.currentIndexChanged.connect(lambda i: self.set_continuity(CONTINUITIES[i]))
        bottom.addRow(translate("FairSplines", "Continuity"), self.continuity)
        self.naive = QtWidgets.QCheckBox(translate("FairSplines", "Naive blend (Fig. 2a, not C2)"))
        self.naive.setChecked(bool(obj.Naive))
        self.naive.toggled.connect(self.set_naive)
        bottom.addRow(self.naive)
        self.interface = QtWidgets.QComboBox()
        self.interface.addItems([translate("FairSplines", i) for i in INTERFACES])
        self.interface.setCurrentIndex(INTERFACES.index(obj.Interface))
        self.interface.setToolTip(translate("FairSplines", "Which end of the profile joins the free-form side; "
                                                           "Auto: the end, or the start where the end is a pole"))
        self.interface.currentIndexChanged.connect(lambda i: self.set_interface(INTERFACES[i]))
        bottom.addRow(translate("FairSplines", "Join at"), self.interface)
        layout.addLayout(bottom)
        freeform_box = QtWidgets.QGroupBox(translate("FairSplines", "Free-form side"))
        freeform_layout = QtWidgets.QVBoxLayout(freeform_box)
        self.freeform_label = QtWidgets.QLabel()
        self.freeform_label.setWordWrap(True)
        freeform_layout.addWidget(self.freeform_label)
        buttons = QtWidgets.QHBoxLayout()
        self.use_face = QtWidgets.QPushButton(translate("FairSplines", "Use selected face"))
        self.use_face.setToolTip(translate("FairSplines", "A B-spline face, bicubic and periodic around the axis "
                                                          "(any knots), its first row near the interface"))
        self.use_face.clicked.connect(self.use_selected_face)
        self.default_ring = QtWidgets.QPushButton(translate("FairSplines", "Default ring"))
        self.default_ring.clicked.connect(lambda: self.set_freeform(None))
        buttons.addWidget(self.use_face)
        buttons.addWidget(self.default_ring)
        freeform_layout.addLayout(buttons)
        join_row = QtWidgets.QFormLayout()
        self.join_to = QtWidgets.QComboBox()
        self.join_to.setToolTip(translate("FairSplines", "Join another Blend basic shape instead of a ring "
                                                         "(Figs. 9-12): this profile's end to the start of its"))
        self._join_choices = []
        self._fill_join_choices()
        self.join_to.currentIndexChanged.connect(lambda i: self.set_join_to(self._join_choices[i]))
        join_row.addRow(translate("FairSplines", "Or join to"), self.join_to)
        freeform_layout.addLayout(join_row)
        layout.addWidget(freeform_box)
        self.patches_label = QtWidgets.QLabel()
        layout.addWidget(self.patches_label)
        self.status_label = QtWidgets.QLabel()
        self.status_label.setWordWrap(True)
        layout.addWidget(self.status_label)
        layout.addStretch(1)
        self._build_dimensions()
        self.refresh()

    # --- widgets ---------------------------------------------------------------------

    def _build_dimensions(self):
        """Rows for the lengths of the kind, then the counts and range (uniform) or the lists."""
        from .qt import QtWidgets

        while self.dimensions.rowCount():
            self.dimensions.removeRow(0)
        self.widgets = {}
        kind = self.obj.Kind
        profile_suffix = " °" if PROFILE_IN_DEGREES[kind] else " mm"
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
                self.dimensions.addRow(label, widget)
                self.widgets[name] = widget
        finally:
            self._updating = False

    # --- edits -----------------------------------------------------------------------

    def _apply(self, changes):
        self.session.begin()
        for name, value in changes:
            setattr(self.obj, name, value)
        self.doc.recompute()
        self.refresh()

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

    def set_freeform(self, link):
        """Join the linked B-spline face ((object, ["FaceN"])), or the default ring (None)."""
        current = self.obj.FreeForm
        if link is None and (current is None or current[0] is None):
            return
        self._apply([("FreeForm", link)])

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

    def use_selected_face(self):
        """The face selected in the 3D view (not one of this object's own) as the free-form side."""
        for sel in FreeCADGui.Selection.getSelectionEx(self.doc.Name):
            if sel.Object == self.obj:
                continue
            faces = [n for n in sel.SubElementNames if n.startswith("Face")]
            if faces:
                self.set_freeform((sel.Object, [faces[0]]))
                return
            if len(getattr(sel.Object, "Shape", None) and sel.Object.Shape.Faces or []) == 1:
                self.set_freeform((sel.Object, ["Face1"]))
                return
        self.show_status(translate("FairSplines", "select a B-spline face of another object first"))

    def _select(self, combo, index):
        if combo.currentIndex() != index:
            self._updating = True
            combo.setCurrentIndex(index)
            self._updating = False

    def show_status(self, message):
        self.status_label.setText(translate("FairSplines", "Status: {}").format(message))
        self.status_label.setStyleSheet("" if message == "ok" else "color: #c00000;")

    def refresh(self):
        self.patches_label.setText(translate("FairSplines", "Patches: {}").format(self.obj.Patches))
        link = self.obj.FreeForm
        if self.obj.JoinTo is not None:
            self.freeform_label.setText(translate("FairSplines", "Joined to {}").format(self.obj.JoinTo.Label))
        elif link is None or link[0] is None:
            self.freeform_label.setText(translate("FairSplines", "Default ring (continues the shape)"))
        else:
            subs = ", ".join(link[1]) if link[1] else ""
            self.freeform_label.setText(f"{link[0].Label}.{subs}" if subs else link[0].Label)
        self.show_status(self.obj.Status)


def register():
    """Add the command to FreeCADGui (once)."""
    if NAME not in FreeCADGui.listCommands():
        FreeCADGui.addCommand(NAME, BlendBasicShapeCommand())


register()
