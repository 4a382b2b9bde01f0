"""What every FairSplines feature shares: the proxy's life cycle and the error policy.

A feature proxy lists its properties; they are added only where missing, so documents
from older versions load, and a Version property allows migration. `execute` calls the
subclass's `build`. If that raises, the feature fails the way FreeCAD's own do:
- it keeps its last good shape;
- the message goes into the read-only Status property and the report view;
- its verdicts about the shape (VERDICTS: a certificate, the joins) are marked not known,
  so none of them is left looking valid;
- FeatureFailed is raised to FreeCAD, which marks the object invalid (the error mark in
  the tree, "Recompute failed" in the report view) and recomputes it again next time.
  Objects that do not depend on it recompute as usual; the document stays intact.

Headless: no GUI import; attach_view_provider imports the GUI's view providers only
when the GUI is up.
"""
import FreeCAD

OUTPUT = 8  # App::Property::Output: setting the property does not touch the object
NOT_KNOWN = "not known: the last recompute failed"


class FeatureFailed(RuntimeError):
    """Raised to FreeCAD from execute when a feature could not be built; the message is
    the reason (also in the feature's Status)."""


def attach_view_provider(obj, name):
    """Give obj the view provider `name` of gui/view_providers.py, when the GUI is up.
    The only way features reach the GUI."""
    if FreeCAD.GuiUp and getattr(obj, "ViewObject", None) is not None:
        from ..gui import view_providers

        getattr(view_providers, name)(obj.ViewObject)


class StatelessProxy:
    """A proxy that keeps everything in properties. FreeCAD 0.20 stores a proxy with
    __getstate__/__setstate__, older versions with dumps/loads."""

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None


class FeatureProxy(StatelessProxy):
    """Base of the FeaturePython proxies. Subclasses set Type, GROUP, PROPERTIES
    ((type, name, tooltip, default, editor mode) tuples; a "Status" and a "Version"
    property are expected among them), OUTPUTS (properties set by recompute) and
    implement build(obj) -> Part.Shape."""

    Type = "FeatureProxy"
    VERSION = 1
    GROUP = "FairSplines"
    PROPERTIES = ()
    ENUMERATIONS = {}  # {property name: choices} of App::PropertyEnumeration properties
    OUTPUTS = ("Status",)
    VERDICTS = ()  # outputs that judge the shape: marked NOT_KNOWN (strings) or cleared on failure

    def __init__(self, obj):
        obj.Proxy = self
        self.ensure_properties(obj)
        obj.Version = self.VERSION

    def onDocumentRestored(self, obj):
        """Add properties an older file lacks, then migrate."""
        self.ensure_properties(obj)
        self.migrate(obj)

    def migrate(self, obj):
        if obj.Version < self.VERSION:
            obj.Version = self.VERSION  # nothing to convert yet

    def ensure_properties(self, obj):
        """Add any missing property with its default; keep the values of existing ones;
        bring enumerations up to date, keeping a value that is still a choice."""
        for type_, name, tooltip, default, mode in self.PROPERTIES:
            choices = list(self.ENUMERATIONS.get(name, ()))
            if name not in obj.PropertiesList:
                obj.addProperty(type_, name, self.GROUP, tooltip, OUTPUT if name in self.OUTPUTS else 0)
                if choices:
                    setattr(obj, name, choices)
                if default is not None:
                    setattr(obj, name, default)
            elif choices and list(obj.getEnumerationsOfProperty(name)) != choices:
                value = getattr(obj, name)
                setattr(obj, name, choices)
                setattr(obj, name, value if value in choices else default)
            obj.setEditorMode(name, mode)

    def build(self, obj):
        raise NotImplementedError

    def execute(self, obj):
        try:
            shape = self.build(obj)
        except Exception as exc:  # InputError, or a source the kernel or OCCT could not read
            message = str(exc).strip() or type(exc).__name__
            fail(obj, message, self.VERDICTS)
            raise FeatureFailed(message) from None
        obj.Shape = shape
        set_if_changed(obj, "Status", "ok")


def set_if_changed(obj, name, value):
    """Set a property only when its value changes (no needless touch)."""
    current = getattr(obj, name)
    if (list(current) if isinstance(current, (list, tuple)) else current) != value:
        setattr(obj, name, value)


def fail(obj, message, verdicts=()):
    """Error state: keep the last good shape, show the message, mark the verdicts not known."""
    set_if_changed(obj, "Status", message)
    for name in verdicts:
        value = getattr(obj, name)
        set_if_changed(obj, name, NOT_KNOWN if isinstance(value, str) else [])
    FreeCAD.Console.PrintError(f"{obj.Label}: {message}\n")
