"""FairSplines' user preferences: the defaults new objects, combs, zebra shading and
curvature plots start from. Headless (no Qt): features and macros read them too.

    from freecad_workbench import preferences
    preferences.get("CombScale")            # 1.0 unless the user changed it
    preferences.set_value("ZebraStripes", 24)
    preferences.reset("ZebraStripes")       # back to the default

They live in FreeCAD's parameter group PARAM_PATH (Tools > Edit parameters), and the
FairSplines page of Edit > Preferences edits them (gui/preferences.py). A preference is
only a default: an object keeps the value it was created with, so documents open as they
were saved whatever the preferences say now.

`get` never fails: a value missing, of the wrong type or out of range (typed into the
parameter editor) gives the default or the nearest end of the range.
"""
from collections import namedtuple
import math

import FreeCAD

PARAM_PATH = "User parameter:BaseApp/Preferences/Mod/FairSplines"

Preference = namedtuple("Preference", "key type default minimum maximum unit stored_as description")
Preference.__doc__ = """One preference: parameter key, Python type (float, int or bool), default,
range [minimum, maximum] (None for bool), unit ("" if none), the parameter type it is
stored as ("Float", "Int", "Bool", "String") and what it does."""

PREFERENCES = {
    p.key: p
    for p in (
        Preference("CombScale", float, 1.0, -1000.0, 1000.0, "", "Float",
                   "Curvature comb scale factor: at 1 the longest tooth is at most a quarter of the curve's "
                   "size and no tooth reaches its centre of curvature; negative draws the comb on the other side"),
        Preference("CombSamples", int, 256, 8, 100000, "", "Int", "Curvature comb teeth per edge (at least)"),
        Preference("CombCommonScale", bool, False, None, None, "", "Bool",
                   "One scale for all combs shown, so tooth lengths compare between curves"),
        Preference("CombTorsion", bool, False, None, None, "", "Bool",
                   "Space curves get a second comb, of torsion along the binormal, so a torsion flip shows"),
        Preference("ZebraStripes", int, 16, 1, 256, "", "Int",
                   "Black and white stripe pairs a new zebra shading reflects"),
        # Stored as a string: FreeCAD 0.20 writes a Float parameter with 12 decimals
        # (printf %.12f), which would store 1e-13 as 0 and 2.5e-12 as 3e-12.
        Preference("CsrEpsilon", float, 1e-9, 1e-15, 1e-3, "", "String",
                   "Curvature tolerance of a new csr fit (eq. (6)), relative to 1/size of the data"),
        Preference("JoinTolerance", float, 1e-6, 1e-7, 10.0, "mm", "Float",
                   "End points of consecutive pieces of a new design spline closer than this are averaged "
                   "into one; farther apart they are joined by an edge"),
        Preference("PlotSamples", int, 1024, 16, 100000, "", "Int", "Curvature plot samples per curve"),
    )
}


def _params():
    return FreeCAD.ParamGet(PARAM_PATH)


def _preference(key):
    try:
        return PREFERENCES[key]
    except KeyError:
        raise KeyError(f"no FairSplines preference {key!r}: use one of {', '.join(PREFERENCES)}") from None


def default(key):
    """The built-in default of a preference."""
    return _preference(key).default


def clamp(key, value):
    """value as the preference's type, inside its range; the default if it is not a number."""
    pref = _preference(key)
    if pref.type is bool:
        return bool(value)
    try:
        value = pref.type(value)
    except (TypeError, ValueError, OverflowError):
        return pref.default
    if isinstance(value, float) and math.isnan(value):
        return pref.default
    return min(max(value, pref.minimum), pref.maximum)


def is_set(key):
    """Whether the parameter group holds a value for this preference."""
    pref = _preference(key)
    names = getattr(_params(), "Get" + pref.stored_as + "s")()
    return pref.key in names


def get(key):
    """The preference's value: the stored one (made valid by `clamp`), else the default."""
    pref = _preference(key)
    params = _params()
    if pref.stored_as == "Bool":
        return params.GetBool(key, pref.default)
    if pref.stored_as == "Int":
        return clamp(key, params.GetInt(key, pref.default))
    if pref.stored_as == "Float":
        return clamp(key, params.GetFloat(key, pref.default))
    text = params.GetString(key, "")
    if not text and key in params.GetFloats():  # a Float set by hand in the parameter editor
        return clamp(key, params.GetFloat(key))
    try:
        return clamp(key, float(text)) if text else pref.default
    except ValueError:
        return pref.default


def set_value(key, value):
    """Store a preference (made valid by `clamp`); returns the value stored."""
    pref = _preference(key)
    value = clamp(key, value)
    params = _params()
    if pref.stored_as == "Bool":
        params.SetBool(key, value)
    elif pref.stored_as == "Int":
        params.SetInt(key, value)
    elif pref.stored_as == "Float":
        params.SetFloat(key, value)
    else:
        params.SetString(key, repr(value))
    return value


def reset(key):
    """Forget the stored value: `get` gives the default again."""
    pref = _preference(key)
    getattr(_params(), "Rem" + pref.stored_as)(key)


def values():
    """{key: value} of every preference."""
    return {key: get(key) for key in PREFERENCES}
