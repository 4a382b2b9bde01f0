"""View providers of the FairSplines features (GUI only)."""
from . import icon_path


class ViewProviderCsrFit:
    """Tree icon of a csr fit: the fit icon, or a red-marked one while Status holds an error
    (the message is in the Status property and the report view)."""

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        obj = getattr(self, "Object", None)
        if obj is not None and getattr(obj, "Status", "ok") != "ok":
            return icon_path("FairSplines_CsrFitError")
        return icon_path("FairSplines_CsrFit")

    def updateData(self, obj, prop):
        if prop == "Status" and obj.ViewObject is not None:
            obj.ViewObject.signalChangeIcon()

    def onChanged(self, vobj, prop):
        pass

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None
