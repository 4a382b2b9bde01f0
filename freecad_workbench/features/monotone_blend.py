"""The Monotone blend, as documents and macros made before fair blends name it: a Fair blend
(features/fair_blend.py) solved by the monotone-curvature paper's Algorithm 2, G1.

    from freecad_workbench.features.monotone_blend import make_monotone_blend
    blend = make_monotone_blend(doc, (line, "Edge1"), (arc, "Edge1"))   # as before

Saved documents store the proxy class MonotoneBlend of this module; it loads as a Fair blend
and is migrated (Continuity G1, Method paper), so it recomputes unchanged.
"""
from .fair_blend import ENDS, FairBlend, element_shape, end_conditions, end_tangent, make_fair_blend

__all__ = ["ENDS", "MonotoneBlend", "element_shape", "end_conditions", "end_tangent", "make_monotone_blend"]


class MonotoneBlend(FairBlend):
    """The proxy class Monotone blends were saved with: a Fair blend."""


def make_monotone_blend(
    doc, start, end, start_end="auto", end_end="auto", start_direction=None, end_direction=None,
    method="paper", name="MonotoneBlend",
):
    """Create a blend solved by the paper's Algorithm 2 ("paper", or its old name "fairest"; or
    "grid"), G1, as make_monotone_blend did before fair blends: make_fair_blend with
    continuity="G1". One undoable step."""
    return make_fair_blend(
        doc, start, end, start_end, end_end, start_direction, end_direction, continuity="G1",
        method="paper" if method == "fairest" else method, name=name, _proxy=MonotoneBlend, _label="Monotone blend",
    )
