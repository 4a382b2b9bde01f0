"""Coin drawings shown in 3D views beside the document's own: the one place that adds a
drawing's root to views' scene graphs and takes it out again, and fills their fields from
numpy arrays. GUI only."""
import numpy as np

import FreeCAD


class ViewAttached:
    """A drawing with a coin separator `root`, shown in the views it is attached to."""

    views = ()

    def attach(self, view):
        """Add the drawing to a 3D view's scene graph (once per view; None: nothing)."""
        if view is None or any(v is view for v in self.views):
            return
        view.getSceneGraph().addChild(self.root)
        self.views = [*self.views, view]

    def detach(self):
        """Take the drawing out of every view it was added to (closed views are skipped)."""
        for view in self.views:
            try:
                graph = view.getSceneGraph()
                if graph.findChild(self.root) >= 0:
                    graph.removeChild(self.root)
            except Exception:  # the view was closed
                pass
        self.views = []


def set_values(field, values, dtype=np.float32):
    """Replace the values of a coin multiple-value field (points, colours, vectors: float32;
    indices: pass dtype=np.int32) with the rows of an array. pivy takes the numpy array itself
    (FreeCAD 0.20, 1.0 and 1.1 alike), 5-7 times faster than a Python list: 10^5 colours in
    about 45 ms against 330 ms (bench/bench_surface_analysis.py, map recolour)."""
    array = np.ascontiguousarray(values, dtype=dtype)
    field.deleteValues(0)
    if len(array):
        field.setValues(0, len(array), array)


def event_position(event):
    """The pixel position (x, y) of a coin event. By index: pivy 0.6.10 (Debian sid's,
    FreeCAD 1.1) returns a bare pointer from SbVec2s.getValue(), older pivy a list."""
    position = event.getPosition()
    return int(position[0]), int(position[1])


def restore_display_mode(saved_modes, key):
    """Give the object named by key (document name, object name) back the display mode
    saved for it in saved_modes (and forget it), if both are still there."""
    mode = saved_modes.pop(key, None)
    doc = FreeCAD.listDocuments().get(key[0])
    target = doc.getObject(key[1]) if doc is not None else None
    if mode is not None and target is not None and getattr(target, "ViewObject", None) is not None:
        target.ViewObject.DisplayMode = mode
