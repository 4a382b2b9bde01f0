"""The Fair fit command: a Points object selected, the command run, a FairFit with its
view provider, icon, Status and undo step."""
import numpy as np

import FreeCAD
import Points

from tests.gui.test_gui import is_active, new_object, run, select
from tests.kernel.fair_fit_data import arc_parabola, sign_changes, signed_curvatures, within
from freecad_workbench.gui import icon_path


def test_fair_fit_command_fits_the_selected_points_object(doc):
    import FreeCADGui

    FreeCADGui.activateWorkbench("FairSplinesWorkbench")
    pts = arc_parabola(2000, noise=1e-4) * 40.0  # about 100 mm, 0.004 mm noise
    cloud = doc.addObject("Points::Feature", "Scan")
    cloud.Points = Points.Points([FreeCAD.Vector(x, y, 0) for x, y in pts])
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    assert not is_active("FairSplines_FairFit")
    select(doc, cloud)
    assert is_active("FairSplines_FairFit")
    before = {o.Name for o in doc.Objects}
    run("FairSplines_FairFit")
    fit = new_object(doc, before)
    from freecad_workbench.gui.view_providers import ViewProviderFairFit

    assert fit.Status.startswith("ok: ") and "mm" in fit.Status, fit.Status
    assert isinstance(fit.ViewObject.Proxy, ViewProviderFairFit)
    assert fit.ViewObject.Proxy.getIcon() == icon_path("FairSplines_FairFit")
    curve = fit.Shape.Edges[0].Curve
    assert within(curve, np.asarray(pts), fit.Tolerance.Value)[0]
    assert sign_changes(signed_curvatures(curve)) == 0
    assert doc.UndoNames[0] == "Create fair fit"
    name = fit.Name
    doc.undo()
    assert doc.getObject(name) is None
