"""One fuzz strategy per public callable of the macro API: REGISTRY maps a name
('csr_spline', 'basic.CircleArc', 'basic.BasicCurve.value', 'shapes.Torus.set_control')
to (strategy of (callable, args, kwargs), max_examples). test_coverage fails for a public
callable without an entry."""
import inspect
import math
from typing import NamedTuple

from hypothesis import strategies as st

import freecad_workbench as fw

from . import strategies as S


class Entry(NamedTuple):
    strategy: object
    examples: int


REGISTRY = {}


def _args(func_getter, args, kwargs):
    """(callable, args, kwargs) with the keyword arguments each present or not."""
    return st.tuples(st.just(func_getter), st.tuples(*args), st.fixed_dictionaries({}, optional=kwargs)).map(
        lambda t: (t[0](), t[1], t[2]))


def register(name, args=(), kwargs=None, examples=25, valid=None):
    """valid: arguments that are mostly good (half the examples), so that the work behind
    the argument checks is fuzzed too."""
    def getter():
        obj = fw
        for part in name.split("."):
            obj = getattr(obj, part)
        return obj

    strategy = _args(getter, args, kwargs or {})
    if valid is not None:
        strategy = st.one_of(strategy, _args(getter, valid, {}))
    REGISTRY[name] = Entry(strategy, examples)


def register_method(prefix, method, instances, args=(), kwargs=None, examples=25):
    """A method of every class of a module: instances draws objects of those classes."""
    strategy = st.tuples(instances, st.tuples(*args), st.fixed_dictionaries({}, optional=kwargs or {})).map(
        lambda t: (getattr(t[0], method), t[1], t[2]))
    REGISTRY[f"{prefix}.*.{method}"] = Entry(strategy, examples)


PARAM = S.choice_arg("chordal", "centripetal", "uniform")
GOOD_POINTS = [S.good_points]
# Ends 2.4e-63 apart gave an infinite variation before the analyses became scale-invariant:
# fair_blend_solution((2.4308653429145085e-63, 0.0), (0.0, 1.0), (0.0, 0.0), (1.0, 0.0)) (test_scale.cpp).
GOOD_ENDS = [S.good_vector] * 4
FIT = dict(closed=S.flag_arg, parametrization=PARAM)

# ---- curves -------------------------------------------------------------------------------
register("csr_spline", [S.points_arg], valid=GOOD_POINTS,
         kwargs=dict(FIT, epsilon=S.number_arg, epsilon_rule=S.choice_arg("case", "additive"),
                     parameters=S.parameters_arg), examples=60)
register("interpolate_classic", [S.points_arg], valid=GOOD_POINTS, kwargs=FIT, examples=40)
register("quasi_interpolant", [S.points_arg], valid=GOOD_POINTS, kwargs=FIT, examples=40)
register("control_point_spline", [S.points_arg], valid=GOOD_POINTS, kwargs=dict(closed=S.flag_arg), examples=40)
register("quadratic_design", [S.points_arg], valid=GOOD_POINTS, kwargs=dict(FIT, epsilon=S.number_arg), examples=40)

# ---- fair fit -----------------------------------------------------------------------------
TOLERANCE = st.one_of(st.floats(1e-3, 10.0), S.number_arg)
FAIR = dict(closed=S.flag_arg, noise=st.one_of(st.none(), S.number_arg), start_tangent=st.one_of(st.none(),
            S.vector_arg), end_tangent=st.one_of(st.none(), S.vector_arg),
            corners=S.choice_arg("refuse", "keep", "smooth"))
register("fair_fit", [S.points_arg, S.number_arg], valid=[S.good_points, st.floats(1e-2, 10.0)], kwargs=FAIR,
         examples=40)
register("fair_fit_report", [S.points_arg, S.number_arg], valid=[S.good_points, st.floats(1e-2, 10.0)],
         kwargs=FAIR, examples=20)
CLAMP = S.choice_arg("G0", "G1", "G2")
register("fair_edge", [S.curve_arg, TOLERANCE], kwargs=dict(clamp=CLAMP, samples=S.count_arg), examples=25)
register("fair_edge_report", [S.curve_arg, TOLERANCE], kwargs=dict(clamp=CLAMP, samples=S.count_arg), examples=15)

# ---- analysis -----------------------------------------------------------------------------
register("curvature_profile", [S.curve_arg], dict(n=S.count_arg), examples=30)
register("curvature_sign_changes", [S.curve_arg], dict(samples_per_span=S.count_arg), examples=30)
register("curvature_extrema", [S.curve_arg], dict(n=S.count_arg), examples=30)
register("max_distance", [S.curve_arg, S.points_arg], valid=[S.curve_arg, S.good_points], examples=30)

# ---- design with basic curves -------------------------------------------------------------
marks = st.one_of(st.lists(S.number_arg, max_size=6), st.lists(st.floats(0, 1), max_size=6).map(sorted),
                  st.lists(S.vector_arg, max_size=3), S.junk)
piece = st.one_of(st.tuples(S.basic_curve, marks), st.tuples(S.curve_arg, marks), S.samples_piece,
                  st.tuples(S.samples_piece, st.one_of(st.none(), marks)), S.junk)
register("design_spline", [st.one_of(st.lists(piece, max_size=3), piece, S.junk)],
         dict(join_tolerance=S.number_arg, details=S.flag_arg), examples=30)
register("revolve_profile", [S.curve_arg], dict(axis_point=S.vector_arg, axis_direction=S.vector_arg), examples=20)
register("approximation_error", [st.one_of(S.basic_curve, S.junk), marks], dict(samples=S.count_arg), examples=20)

# ---- blends -------------------------------------------------------------------------------
CONT = S.choice_arg("C2", "C1")
METHOD = S.choice_arg("rho", "sigma", "mixed")
AT = st.one_of(st.none(), S.choice_arg("end", "start"))
register("blend_basic_shape", [S.shape_arg], valid=[S.shape],
         kwargs=dict(freeform=S.freeform_arg, continuity=CONT, method=METHOD, at=AT), examples=12)
register("blend_naive", [S.shape_arg], valid=[S.shape], kwargs=dict(freeform=S.freeform_arg, continuity=CONT, at=AT),
         examples=10)
register("join_basic_shapes", [S.shape_arg, S.shape_arg], valid=[S.shape, S.shape],
         kwargs=dict(continuity=CONT, method=METHOD), examples=10)
register("join_naive", [S.shape_arg, S.shape_arg], valid=[S.shape, S.shape], examples=8)
CHAIN_END = st.one_of(st.none(), st.just("default"), S.freeform_arg, S.choice_arg("default"))
register("blend_chain", [st.one_of(S.shape_arg, st.lists(S.shape_arg, max_size=3))],
         valid=[st.lists(S.shape, min_size=1, max_size=2)], kwargs=dict(start=CHAIN_END, end=CHAIN_END, method=METHOD),
         examples=12)
register("freeform_knots", [S.shape_arg], valid=[S.shape], kwargs=dict(method=METHOD, continuity=CONT), examples=20)

# ---- monotone curvature and fair blends ---------------------------------------------------
ENDS = [S.planar_vector] * 4
curvature = st.one_of(st.none(), S.number_arg)
register("monotone_end_conditions", ENDS, valid=GOOD_ENDS, examples=40)
register("monotone_curvature_solution", ENDS, valid=GOOD_ENDS,
         kwargs=dict(method=S.choice_arg("paper", "grid", "fairest"), grid_step=S.number_arg), examples=30)
register("monotone_curvature_spline", ENDS, valid=GOOD_ENDS,
         kwargs=dict(k0=curvature, k1=curvature, normal=st.one_of(st.none(), S.vector_arg),
                     method=S.choice_arg("fair", "paper", "grid")), examples=25)
register("fair_blend_solution", ENDS, valid=GOOD_ENDS,
         kwargs=dict(k0=curvature, k1=curvature, normal=st.one_of(st.none(), S.vector_arg)), examples=25)
register("fair_blend_space_solution", [S.vector_arg] * 4, valid=GOOD_ENDS,
         kwargs=dict(K0=st.one_of(st.none(), S.vector_arg), K1=st.one_of(st.none(), S.vector_arg)), examples=25)
END = st.one_of(S.choice_arg("start", "end"), S.vector_arg)
register("fair_blend", [S.curve_arg, END, S.curve_arg, END], valid=[S.curve_arg, S.choice_arg("start", "end")] * 2,
         kwargs=dict(continuity=S.choice_arg("G2", "G1")), examples=25)
# Differences of any size: Algorithm 1 is scale-invariant (its vectors are divided by a power of
# two first); 1e307 apart gave NaN before (cpp/tests/test_scale.cpp).
moderate = st.one_of(st.sampled_from([0.0, 1.0, -1.0, 0.5, 1e-9, 1e-300, 1e6, 1e50, 1e307, -1e307, 1e308]),
                     st.floats(-100, 100))
differences = st.one_of(st.lists(st.tuples(moderate, moderate), max_size=8), S.points_arg)
register("monotone_curvature_design", [S.planar_vector, differences],
         dict(knots=S.parameters_arg, start=st.one_of(st.none(), S.vector_arg)), examples=30)
register("clamp_to_fair_locations", [S.planar_vector, differences], dict(knots=S.parameters_arg), examples=30)
register("check_monotone_curvature", [S.curve_arg], dict(rel_tol=S.number_arg), examples=30)
register("curvature_variation", [S.curve_arg], examples=25)
register("derivative_polygons", [S.curve_arg], examples=25)

# ---- fw.basic -----------------------------------------------------------------------------
V, N = S.vector_arg, S.number_arg
FRAME = dict(normal=V, x_axis=st.one_of(st.none(), V))
register("basic.LineSegment", [V, V], examples=20)
register("basic.CircleArc", [], dict(FRAME, center=V, radius=N, start_angle=N, end_angle=N), examples=30)
register("basic.EllipseArc", [], dict(FRAME, center=V, major_radius=N, minor_radius=N, start=N, end=N), examples=30)
register("basic.ParabolaArc", [], dict(FRAME, vertex=V, focal=N, t0=N, t1=N), examples=30)
register("basic.HyperbolaArc", [], dict(FRAME, center=V, major_radius=N, minor_radius=N, t0=N, t1=N), examples=30)
register("basic.RationalCubic", [], dict(poles=st.one_of(S.points_arg, st.lists(V, max_size=5)),
                                         weights=st.one_of(st.lists(N, max_size=5), S.junk),
                                         homogeneous=st.one_of(S.points_arg,
                                                               st.lists(st.tuples(N, N, N, N), max_size=5))),
         examples=30)
register("basic.ArchimedeanSpiral", [], dict(FRAME, center=V, a=N, b=N, theta0=N, theta1=N), examples=20)
register("basic.CircleInvolute", [], dict(FRAME, center=V, radius=N, t0=N, t1=N), examples=20)
functions = st.sampled_from([lambda s: (s, s * s, 0.0), lambda s: (float("nan"), s, 0), lambda s: "abc",
                             lambda s: (s, 1e308 * s), lambda s: (0, 0, 0), lambda s: (s,), None, "f"])
register("basic.ParametricCurve", [functions], dict(s0=N, s1=N), examples=20)
register("basic.from_edge", [S.curve_arg], examples=30)
register("basic.Samples", [S.points_arg], valid=GOOD_POINTS,
         kwargs=dict(parametrization=PARAM, epsilon=S.number_arg, epsilon_rule=S.choice_arg("case", "additive")),
         examples=40)
register_method("basic", "value", S.basic_curve, [N], examples=20)
register_method("basic", "d1", S.basic_curve, [N], examples=20)
register_method("basic", "d2", S.basic_curve, [N], examples=20)
register_method("basic", "parameter_of", S.basic_curve, [V], dict(tolerance=N), examples=20)
register_method("basic", "size", S.basic_curve, examples=10)
register_method("basic", "to_part", st.one_of(S.basic_curve, S.samples_piece), examples=10)

# ---- fw.shapes ----------------------------------------------------------------------------
A = S.angle_list
register("shapes.SphereZone", [V, N, A, A], dict(axis=V, x_axis=st.one_of(st.none(), V)), examples=30)
register("shapes.Cylinder", [V, N, A, A], dict(axis=V, x_axis=st.one_of(st.none(), V)), examples=30)
register("shapes.Cone", [V, N, N, A, A], dict(axis=V, x_axis=st.one_of(st.none(), V)), examples=30)
register("shapes.Torus", [V, N, N, A, A], dict(axis=V, x_axis=st.one_of(st.none(), V)), examples=30)
# Issue 32: a designed profile revolved, quadrics, images and cyclides.
PROFILE = st.one_of(S.junk, st.sampled_from(["parabola", "crossing"]).map(S.revolution_profile))
register("shapes.Revolution", [PROFILE, V, V, A], dict(splits=st.one_of(st.none(), A)),
         valid=[st.just("parabola").map(S.revolution_profile), st.just((0, 0, 0)), st.just((0, 0, 1)),
                st.just([0.0, 2.0, 4.0, 2 * math.pi])], examples=30)
register("shapes.Paraboloid", [V, N, A, A], dict(axis=V, x_axis=st.one_of(st.none(), V)), examples=20)
register("shapes.Hyperboloid", [V, N, N, A, A], dict(sheets=st.one_of(st.sampled_from([1, 2]), S.junk), axis=V,
                                                     x_axis=st.one_of(st.none(), V)), examples=20)
register("shapes.Ellipsoid", [V, st.one_of(st.lists(N, min_size=0, max_size=4), S.junk), A, A],
         dict(axis=V, x_axis=st.one_of(st.none(), V)), examples=20)
register("shapes.HyperbolicCylinder", [V, N, N, A, A], dict(axis=V, x_axis=st.one_of(st.none(), V)), examples=20)
register("shapes.DupinCyclide", [V, N, N, N, A, A], dict(axis=V, x_axis=st.one_of(st.none(), V)), examples=20)
MATRIX = st.one_of(S.junk, st.lists(N, min_size=9, max_size=9), st.lists(st.floats(-3, 3), min_size=9, max_size=9))
register("shapes.AffineImage", [st.one_of(S.shape, S.junk), MATRIX], dict(translation=V), examples=20)
register("shapes.ProjectiveImage", [st.one_of(S.shape, S.junk),
                                    st.one_of(S.junk, st.lists(st.floats(-3, 3), min_size=16, max_size=16))],
         examples=20)
INDEX = st.one_of(st.integers(-2, 6), S.junk, st.sampled_from([1.5, True, 2 ** 63]))
register_method("shapes", "control_point", S.shape, [INDEX] * 4, examples=25)
register_method("shapes", "set_control", S.shape, [INDEX] * 4 + [V], dict(weight=st.one_of(st.none(), N)), examples=25)
register_method("shapes", "reset_control", S.shape, examples=5)
register_method("shapes", "g2", S.shape, examples=5)
register_method("shapes", "control", S.shape, examples=5)
register_method("shapes", "patches", S.shape, examples=5)
register_method("shapes", "pole_at", S.shape, [st.one_of(S.choice_arg("start", "end"), S.junk)], examples=10)

# ---- surface analysis ---------------------------------------------------------------------
_uv = st.floats(-1.0, 7.0)
GOOD_UV = st.lists(st.tuples(_uv, _uv), min_size=1, max_size=6)
register("surface_curvature", [st.one_of(S.analysis_face, S.junk), st.one_of(S.points_arg, GOOD_UV)],
         valid=[S.analysis_face, GOOD_UV], kwargs=dict(threads=st.one_of(st.none(), S.count_arg)), examples=25)
register("edge_continuity", [st.one_of(S.analysis_shape, S.junk)], valid=[S.analysis_shape],
         kwargs=dict(samples=st.one_of(st.none(), S.count_arg), gap_tolerance=st.one_of(st.none(), S.number_arg),
                     angle_tolerance=S.number_arg, curvature_tolerance=S.number_arg), examples=15)
register("curvature_map", [st.one_of(S.analysis_shape, S.junk)], valid=[S.analysis_shape],
         kwargs=dict(quantity=S.choice_arg("gaussian", "mean", "max_abs", "min", "max", "radius"),
                     deflection=st.one_of(st.none(), S.number_arg), fraction=S.number_arg, levels=S.count_arg),
         examples=10)

# ---- face blends ----------------------------------------------------------------------------
_EDGE = st.one_of(S.count_arg, S.choice_arg("start", "end", "Edge1"), S.junk)
_G = S.choice_arg("G1", "G2")
_BLEND_KW = dict(continuity=st.one_of(_G, st.tuples(_G, _G), st.lists(_G, max_size=3)), flip=S.flag_arg,
                 start=st.one_of(st.none(), S.number_arg),
                 end=st.one_of(st.none(), S.number_arg), sections=S.count_arg,
                 scale_a=st.one_of(st.none(), S.number_arg), scale_b=st.one_of(st.none(), S.number_arg),
                 measure=st.just(False))
register("blend_faces", [st.one_of(S.analysis_face, S.shape, S.junk), _EDGE, st.one_of(S.analysis_face, S.junk), _EDGE],
         kwargs=_BLEND_KW, valid=[S.blend_side.map(lambda s: s[0]), S.blend_side.map(lambda s: s[1]),
                                  S.blend_side.map(lambda s: s[0]), S.blend_side.map(lambda s: s[1])],
         examples=20)
register("blend_errors", [st.one_of(S.analysis_face, S.junk), st.one_of(S.analysis_face, S.junk), S.junk, S.junk],
         examples=5)

# Public names that are not functions to fuzz: exceptions and the result types the API
# returns (their fields are checked by the contract wherever they come back).
NOT_CALLABLES = {"InputError", "NoMonotoneSolution", "DesignResult", "ApproximationError", "CurvatureProfile",
                 "BlendResult", "FairBlendReport", "FairFitReport", "FaceBlendReport",
                 "SurfaceCurvature", "EdgeContinuity", "CurvatureMap", "basic.BasicCurve", "basic", "shapes"}


def public_callables():
    """Every public callable of the macro API: fw.__all__, the classes and functions of the
    public submodules (fw.basic, fw.shapes) and the public methods of those classes
    (as 'module.*.method': one entry fuzzes the method on instances of every class)."""
    names = set()
    for name in fw.__all__:
        obj = getattr(fw, name)
        if inspect.ismodule(obj):
            for sub in obj.__all__:
                member = getattr(obj, sub)
                names.add(f"{name}.{sub}")
                if inspect.isclass(member):
                    for attr, value in inspect.getmembers(member):
                        if not attr.startswith("_") and callable(value) and not isinstance(value, type):
                            names.add(f"{name}.*.{attr}")
        elif callable(obj):
            names.add(name)
    return names - NOT_CALLABLES
