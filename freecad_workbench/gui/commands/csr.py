"""The csr fit command (GUI only); it records a replayable macro line.

FairSplines_CsrFit   csr fit of the selected vertices, Points, sketch or edges
FairSplines_FairFit  fair fit (within a tolerance, few poles) of the same sources
"""
import FreeCADGui

from ...features.csr_fit import usable_source
from .common import QT_TRANSLATE_NOOP, doc_code, links_code, resources, selected_links

NAME = "FairSplines_CsrFit"
FAIR_NAME = "FairSplines_FairFit"


class _PointsFit:
    """A fit of the selected points (vertices, Points objects, sketch points, edges): FEATURE
    is (features module, its make_ function), called through the console so that macros
    record it."""

    FEATURE = ("", "")

    def IsActive(self):
        links = selected_links()
        return bool(links) and all(usable_source(obj, sub) for obj, sub in links)

    def Activated(self):
        links = selected_links()
        if not links:
            return
        module, make = self.FEATURE
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand(f"from freecad_workbench.features.{module} import {make}")
        FreeCADGui.doCommand(f"{make}({doc_code(links[0][0].Document)}, {links_code(links)})")
        FreeCADGui.Selection.clearSelection()


class CsrFitCommand(_PointsFit):
    def GetResources(self):
        return resources(
            NAME,
            QT_TRANSLATE_NOOP(NAME, "Spline through points"),
            QT_TRANSLATE_NOOP(
                NAME,
                "A smooth C2 spline through the selected vertices, Points object, sketch points or edges\n"
                "(the csr-spline: conics stay exact, no curvature wiggles). Select points in order;\n"
                "edges are sampled.",
            ),
            "Using it in the FreeCAD GUI",
            accel="F, F",
        )

    FEATURE = ("csr_fit", "make_csr_fit")


class FairFitCommand(_PointsFit):
    """Fair fit of the same sources as the csr fit (features/fair_fit.py)."""

    def GetResources(self):
        return resources(
            FAIR_NAME,
            QT_TRANSLATE_NOOP(FAIR_NAME, "Fair fit"),
            QT_TRANSLATE_NOOP(
                FAIR_NAME,
                "A fair C2 spline with few control points within a tolerance (mm) of the selected\n"
                "vertices, Points object, sketch points or edges: scan noise is smoothed away and the\n"
                "curvature changes sign only where the data does (the csr-spline of chosen points).",
            ),
            "Fair fit",
        )

    FEATURE = ("fair_fit", "make_fair_fit")


def command_objects():
    return {NAME: CsrFitCommand(), FAIR_NAME: FairFitCommand()}
