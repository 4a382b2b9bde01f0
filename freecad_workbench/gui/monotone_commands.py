"""The monotone-curvature commands (GUI only). Each records a replayable macro line.

FairSplines_MonotoneBlend    Fair blend between two selected edges (their picked ends) or vertices (the
                             command kept its name, so toolbars people made keep it)
FairSplines_CheckMonotone    certificate of the selected planar edges: report view + curvature plot
FairSplines_MonotoneDesign   Algorithm 1 in a task panel: control vectors kept in their fair locations
"""
import FreeCAD
import FreeCADGui
import Part

from .. import monotone
from ..errors import InputError
from ..features.fair_blend import element_shape, end_tangent
from ..features.monotone_design import MonotoneDesign
from . import icon_path, plot
from .commands import _edge_links, _links_code, selected_links

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

COMMANDS = ("FairSplines_MonotoneBlend", "FairSplines_CheckMonotone", "FairSplines_MonotoneDesign")

# A new design: turning left, every C^2 already in its fair location (knots 0,0,0,0,1,2,2,2,2).
DEFAULT_DESIGN = ((10.0, 0.0), [(10.0, 5.0), (3.0, 4.5), (-133.0 / 12, -13.0 / 3)])


# --- Monotone blend -------------------------------------------------------------------------


def _side(obj, sub, picked):
    """(shape, end choice) of one selected side: an edge with the end nearest to where it was
    picked ("auto" when the pick is not on it), or a vertex (None)."""
    try:
        shape = element_shape(obj, sub)
    except InputError:
        return None
    if shape.ShapeType == "Vertex":
        return shape, None
    end = "auto"
    if picked is not None:
        first, last = shape.valueAt(shape.FirstParameter), shape.valueAt(shape.LastParameter)
        on_edge = shape.distToShape(Part.Vertex(picked))[0] <= 0.01 * max(shape.BoundBox.DiagonalLength, 1e-12)
        if on_edge:
            end = "first" if (picked - first).Length <= (picked - last).Length else "last"
    return shape, end


def blend_sides():
    """The selection as [(obj, sub, shape, end)] if it is two edges or vertices, else []."""
    sides = []
    doc = FreeCAD.ActiveDocument
    if doc is None:
        return []
    for sel in FreeCADGui.Selection.getSelectionEx(doc.Name):
        subs = list(sel.SubElementNames) or [""]
        picks = list(sel.PickedPoints) if sel.SubElementNames else []
        for k, sub in enumerate(subs):
            side = _side(sel.Object, sub, picks[k] if k < len(picks) else None)
            if side is None:
                return []
            sides.append((sel.Object, sub) + side)
    return sides if len(sides) == 2 else []


def _vertex_direction(obj, vertex, other, outwards):
    """A starting direction at a selected vertex: along an edge of the same object that ends
    there (continuing it), else towards (from) the other side."""
    for edge in Part.getShape(obj).Edges:
        for which, u in (("first", edge.FirstParameter), ("last", edge.LastParameter)):
            if edge.valueAt(u).isEqual(vertex.Point, 1e-7):
                return end_tangent(edge, which, outwards)
    chord = other - vertex.Point
    return chord if outwards else -chord


def _vector_code(v):
    return f"FreeCAD.Vector({v.x!r}, {v.y!r}, {v.z!r})"


class FairBlendCommand:
    def GetResources(self):
        return {
            "Pixmap": icon_path("FairSplines_MonotoneBlend"),
            "MenuText": QT_TRANSLATE_NOOP("FairSplines_MonotoneBlend", "Fair blend"),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FairSplines_MonotoneBlend",
                "Bridge two selected edges, at the ends you clicked near, with a curve whose curvature\n"
                "runs one way, proved exactly. Matches the edges' tangents and curvatures (G2);\n"
                "set Continuity to G1 for tangents only. Or select two vertices and set the\n"
                "directions in the blend's properties.",
            ),
        }

    def IsActive(self):
        return bool(blend_sides())

    def Activated(self):
        sides = blend_sides()
        if not sides:
            return
        (o0, s0, shape0, end0), (o1, s1, shape1, end1) = sides
        doc = o0.Document
        args = [f"FreeCAD.getDocument({doc.Name!r})"]
        for obj, sub in ((o0, s0), (o1, s1)):
            ref = f"FreeCAD.getDocument({obj.Document.Name!r}).getObject({obj.Name!r})"
            args.append(f"({ref}, {sub!r})" if sub else ref)
        if end0:
            args.append(f"start_end={end0!r}")
        else:
            other = shape1.Point if end1 is None else shape1.valueAt(shape1.FirstParameter)
            args.append(f"start_direction={_vector_code(_vertex_direction(o0, shape0, other, True))}")
        if end1:
            args.append(f"end_end={end1!r}")
        else:
            other = shape0.Point if end0 is None else shape0.valueAt(shape0.LastParameter)
            args.append(f"end_direction={_vector_code(_vertex_direction(o1, shape1, other, False))}")
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("from freecad_workbench.features.fair_blend import make_fair_blend")
        FreeCADGui.doCommand(f"make_fair_blend({', '.join(args)})")
        FreeCADGui.Selection.clearSelection()


# --- Check curvature monotonicity -----------------------------------------------------------


def check_links(links, path=None):
    """The certificate of every edge of selection-style links [(obj, sub)]: one report per edge
    in the report view, and a curvature plot with the extrema marked (written to `path` if
    given, else shown). Returns ([(label, MonotonicityReport or None)], matplotlib Figure)."""
    results, plotted = [], []
    for edge, label in plot.link_edges(links):
        try:
            report = monotone.check_monotone_curvature(edge)
        except InputError as exc:
            FreeCAD.Console.PrintError(f"{label}: {exc}\n")
            results.append((label, None))
            continue
        show = FreeCAD.Console.PrintMessage if report.monotone else FreeCAD.Console.PrintWarning
        show(f"{label}: {report}\n")
        results.append((label, report))
        plotted.append((edge, label, report))
    if not plotted:
        return results, None
    marks = [
        (i, s.extremum[0], f"{label}: curvature {'maximum' if s.extremum[2] else 'minimum'}", "v" if s.extremum[2] else "^")
        for i, (_, label, report) in enumerate(plotted)
        for s in report.spans
        if s.extremum
    ]
    fig = plot.curvature_plot(
        [(edge, label) for edge, label, _ in plotted], path=path, title="Curvature monotonicity", marks=marks
    )
    return results, fig


class CheckMonotoneCommand:
    def GetResources(self):
        return {
            "Pixmap": icon_path("FairSplines_CheckMonotone"),
            "MenuText": QT_TRANSLATE_NOOP("FairSplines_CheckMonotone", "Check curvature monotonicity"),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FairSplines_CheckMonotone",
                "Certify whether the curvature of the selected planar edges is monotone (exact, per knot span):\n"
                "a report in the report view and a curvature plot with any extremum marked.",
            ),
        }

    def IsActive(self):
        return bool(_edge_links(selected_links()))

    def Activated(self):
        links = _edge_links(selected_links())
        if not links:
            return
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.monotone_commands")
        FreeCADGui.doCommand(f"freecad_workbench.gui.monotone_commands.check_links({_links_code(links)})")


# --- Monotone design (Algorithm 1) ----------------------------------------------------------


def _selected_design():
    for obj, _ in selected_links():
        if isinstance(getattr(obj, "Proxy", None), MonotoneDesign):
            return obj
    return None


class MonotoneDesignCommand:
    def GetResources(self):
        return {
            "Pixmap": icon_path("FairSplines_MonotoneDesign"),
            "MenuText": QT_TRANSLATE_NOOP("FairSplines_MonotoneDesign", "Monotone design"),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FairSplines_MonotoneDesign",
                "Design a cubic B-spline with monotone curvature from its control vectors (Algorithm 1).\n"
                "Edits the selected Monotone design, or creates one. Every difference of control vectors\n"
                "is kept in its fair location while you edit.",
            ),
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        obj = _selected_design()
        doc = FreeCAD.ActiveDocument
        FreeCADGui.doCommand("import FreeCAD, FreeCADGui")
        if obj is None:
            first, diffs = DEFAULT_DESIGN
            FreeCADGui.doCommand("from freecad_workbench.features.monotone_design import make_monotone_design")
            FreeCADGui.doCommand(
                f"_design = make_monotone_design(FreeCAD.getDocument({doc.Name!r}), {first!r}, {diffs!r})"
            )
            FreeCADGui.doCommand(f"FreeCADGui.getDocument({doc.Name!r}).setEdit(_design.Name)")
        else:
            FreeCADGui.doCommand(f"FreeCADGui.getDocument({obj.Document.Name!r}).setEdit({obj.Name!r})")
        FreeCADGui.Selection.clearSelection()


_panel = None


def active_design_panel():
    """The open Monotone design task panel, if any."""
    return _panel if FreeCADGui.Control.activeDialog() else None


class MonotoneDesignTaskPanel:
    """Edits a Monotone design's control vectors: V_0 and the differences dV_i. Whatever is
    typed, each dV_i is moved at once to the nearest vector that keeps C^2_i in its fair
    location (the table shows what is used, the last column how far it moved); the curve
    follows. OK keeps the edit, Cancel restores the design as it was."""

    COLUMNS = 3
    DIGITS = 6

    def __init__(self, obj):
        from .qt import QtGui, QtWidgets

        global _panel
        _panel = self
        self.obj = obj
        self.doc = obj.Document
        self.editing = False  # the undo step opens with the first change (not inside the command)
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("FairSplines", "Monotone design"))
        self.form.setWindowIcon(QtGui.QIcon(icon_path("FairSplines_MonotoneDesign")))
        layout = QtWidgets.QVBoxLayout(self.form)
        intro = QtWidgets.QLabel(
            translate(
                "FairSplines",
                "V0 is the first control vector; dV_i = V_(i+1) - V_i. Each dV_i is kept where the "
                "second-derivative control point C2_i lies in its fair location (Theorem 2), so the "
                "curvature is monotone.",
            )
        )
        intro.setWordWrap(True)
        layout.addWidget(intro)
        self.table = QtWidgets.QTableWidget(0, self.COLUMNS)
        self.table.setHorizontalHeaderLabels(["x", "y", translate("FairSplines", "moved")])
        self.table.horizontalHeader().setSectionResizeMode(QtWidgets.QHeaderView.Stretch)
        layout.addWidget(self.table)
        buttons = QtWidgets.QHBoxLayout()
        self.add_button = QtWidgets.QPushButton(translate("FairSplines", "Add vector"))
        self.remove_button = QtWidgets.QPushButton(translate("FairSplines", "Remove last"))
        buttons.addWidget(self.add_button)
        buttons.addWidget(self.remove_button)
        layout.addLayout(buttons)
        self.status = QtWidgets.QLabel()
        self.status.setWordWrap(True)
        layout.addWidget(self.status)
        first = obj.FirstVector
        diffs = [(v.x, v.y) for v in (obj.UsedDifferences or obj.Differences)]
        self._fill((first.x, first.y), diffs, [0.0] * len(diffs))
        self.table.itemChanged.connect(self.apply)
        self.add_button.clicked.connect(self.add_vector)
        self.remove_button.clicked.connect(self.remove_vector)
        self.status.setText(self._clamp(*self.vectors())[2])

    # -- table <-> vectors
    def _fill(self, first, diffs, moved):
        from .qt import QtCore, QtWidgets

        self.table.blockSignals(True)
        self.table.setRowCount(1 + len(diffs))
        self.table.setVerticalHeaderLabels(["V0"] + [f"dV{i}" for i in range(len(diffs))])
        rows = [first] + list(diffs)
        for r, (x, y) in enumerate(rows):
            for c, value in enumerate((x, y)):
                # Shown with DIGITS digits; the item keeps the exact value while its text is unchanged.
                item = QtWidgets.QTableWidgetItem(f"{value:.{self.DIGITS}g}")
                item.setData(QtCore.Qt.UserRole, float(value))
                self.table.setItem(r, c, item)
            note = "" if r == 0 or moved[r - 1] == 0.0 else f"{moved[r - 1]:.3g}"
            item = QtWidgets.QTableWidgetItem(note)
            item.setFlags(item.flags() & ~QtCore.Qt.ItemIsEditable)
            self.table.setItem(r, 2, item)
        self.table.blockSignals(False)

    def vectors(self):
        """(V0, [dV_i]) as shown: exact where a cell was not retyped; a cell that is not a
        number counts as 0."""
        from .qt import QtCore

        rows = []
        for r in range(self.table.rowCount()):
            row = []
            for c in range(2):
                item = self.table.item(r, c)
                exact = item.data(QtCore.Qt.UserRole) if item is not None else None
                if exact is not None and item.text() == f"{exact:.{self.DIGITS}g}":
                    row.append(exact)
                    continue
                try:
                    row.append(float(item.text()) if item is not None else 0.0)
                except ValueError:
                    row.append(0.0)
            rows.append(tuple(row))
        return rows[0], rows[1:]

    def set_vectors(self, first, diffs):
        """Put vectors in the table and apply them (as typing them would)."""
        self._fill(first, diffs, [0.0] * len(diffs))
        self.apply()

    # -- editing
    def _knots(self, diffs):
        """The design's knots if they still fit the number of vectors, else None (default)."""
        knots = list(self.obj.Knots)
        return knots if len(knots) == len(diffs) + 6 else None

    def _clamp(self, first, diffs):
        """(used differences, how far each moved, status text); used is None on bad input."""
        try:
            used, moved = monotone.clamp_to_fair_locations(first, diffs, self._knots(diffs))
        except InputError as exc:
            return None, None, str(exc)
        rows = [f"dV{i}" for i, m in enumerate(moved) if m > 0.0]
        text = (
            translate("FairSplines", "Moved into the fair location: ") + ", ".join(rows)
            if rows
            else translate("FairSplines", "Every difference is in its fair location.")
        )
        return used, moved, text

    def apply(self, *_):
        """Clamp what is in the table into the fair locations, show it, update the design."""
        first, diffs = self.vectors()
        used, moved, text = self._clamp(first, diffs)
        self.status.setText(text)
        if used is None:
            return
        self._fill(first, [tuple(u) for u in used], list(moved))
        if not self.editing:
            self.doc.openTransaction("Edit monotone design")
            self.editing = True
        if self._knots(diffs) is None and self.obj.Knots:
            self.obj.Knots = []  # the rows changed: back to clamped, uniform knots
        self.obj.FirstVector = FreeCAD.Vector(first[0], first[1], 0)
        self.obj.Differences = [FreeCAD.Vector(x, y, 0) for x, y in used]
        self.doc.recompute()

    def add_vector(self):
        first, diffs = self.vectors()
        self.set_vectors(first, diffs + [(0.0, 0.0)])

    def remove_vector(self):
        first, diffs = self.vectors()
        if len(diffs) > 2:
            self.set_vectors(first, diffs[:-1])

    def accept(self):
        if self.editing:
            self.doc.commitTransaction()
        self._close()
        return True

    def reject(self):
        if self.editing:
            self.doc.abortTransaction()
            self.doc.recompute()
        self._close()
        return True

    def _close(self):
        global _panel
        _panel = None
        gui_doc = FreeCADGui.getDocument(self.doc.Name)
        if gui_doc is not None and gui_doc.getInEdit() is not None:
            gui_doc.resetEdit()
        if FreeCADGui.Control.activeDialog():
            FreeCADGui.Control.closeDialog()


def register():
    """Add the commands to FreeCADGui (once)."""
    for name, command in zip(COMMANDS, (FairBlendCommand(), CheckMonotoneCommand(), MonotoneDesignCommand())):
        if name not in FreeCADGui.listCommands():
            FreeCADGui.addCommand(name, command)


register()
