"""Curve analysis for every capability: curvature along a curve, its sign changes and
extrema, and the distance from data to a curve. Accepts Part edges and curves."""
from __future__ import annotations

from collections import namedtuple

from . import kernel
from .kernel import CurveLike, PointsLike, as_count, as_points, from_part

# The most samples a call takes (about 0.1 s of kernel work each way).
MAX_SAMPLES = 1_000_000

CurvatureProfile = namedtuple("CurvatureProfile", "u s kappa signed normal")
CurvatureProfile.__doc__ = (
    "Samples along a curve: parameters u, arc length s, curvature kappa (signed for planar curves, "
    "positive turning counter-clockwise about `normal`), `signed` flag and the plane normal."
)
CurvatureExtremum = namedtuple("CurvatureExtremum", "u s kappa maximum")


def curvature_profile(curve: CurveLike, n: int = 512) -> CurvatureProfile:
    """Curvature at about n samples (at least 8 per knot span) -> CurvatureProfile."""
    u, s, kappa, signed, normal = kernel.curvature_profile(from_part(curve), as_count(n, "n", 1, MAX_SAMPLES))
    return CurvatureProfile(u, s, kappa, bool(signed), tuple(normal))


def curvature_sign_changes(curve: CurveLike, samples_per_span: int = 32) -> int:
    """Number of sign changes of the curvature of a planar curve (0 for a non-planar one)."""
    return kernel.curvature_sign_changes(from_part(curve), as_count(samples_per_span, "samples_per_span", 1, 10_000))


def curvature_extrema(curve: CurveLike, n: int = 2048) -> list[CurvatureExtremum]:
    """Interior local extrema of the (signed) curvature: [CurvatureExtremum(u, s, kappa, maximum)]."""
    return [CurvatureExtremum(*e) for e in kernel.curvature_extrema(from_part(curve), as_count(n, "n", 1, MAX_SAMPLES))]


def max_distance(curve: CurveLike, points: PointsLike) -> float:
    """Largest distance from the points to the curve."""
    return kernel.max_distance(from_part(curve), as_points(points))
