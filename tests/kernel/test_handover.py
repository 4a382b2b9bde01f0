"""The hand-over of kernel curves to FreeCAD is exact on both routes."""
import numpy as np
import pytest

import freecad_workbench as fw  # noqa: F401  (imports FreeCAD first)
from freecad_workbench import _kernel, kernel


def bits(values):
    return np.ascontiguousarray(np.asarray(values, dtype=np.float64)).view(np.uint64)


def curves():
    rng = np.random.default_rng(9)
    poles = rng.standard_normal((12, 3)) * 123.456
    knots = np.cumsum(rng.random(10) + 0.1)
    mults = np.array([4] + [1] * 8 + [4], dtype=np.int32)
    yield "polynomial", _kernel.BSplineCurve(poles, knots, mults, 3, False)
    yield "rational", _kernel.BSplineCurve(poles, knots, mults, 3, False, rng.random(12) + 0.5)
    yield "planar", _kernel.csr_spline(rng.random((9, 2)))
    yield "periodic", _kernel.csr_spline(rng.random((9, 3)), closed=True)


@pytest.mark.parametrize("name, curve", list(curves()))
def test_both_routes_are_bit_exact(name, curve):
    for part in (kernel.to_part(curve), kernel.to_part_arrays(curve)):
        poles = np.array([tuple(p) for p in part.getPoles()])
        expected = curve.poles if curve.poles.shape[1] == 3 else np.c_[curve.poles, np.zeros(len(curve.poles))]
        assert np.array_equal(bits(poles), bits(expected)), name
        assert np.array_equal(bits(part.getKnots()), bits(curve.knots)), name
        assert list(part.getMultiplicities()) == curve.mults.tolist()
        assert part.isPeriodic() == curve.periodic
        if curve.rational:
            assert np.array_equal(bits(part.getWeights()), bits(curve.weights)), name
        else:
            assert not part.isRational()


def test_zero_copy_bridge_is_built():
    # make build compiles the SWIG bridge (Debian's swig is a build dependency).
    assert kernel._BRIDGE is not None


@pytest.mark.parametrize("closed", [False, True])
@pytest.mark.parametrize("n", [5, 300, 5000])
def test_csr_spline_goes_straight_to_occt_bit_exactly(closed, n):
    # fw.csr_spline fits straight into an OCCT edge (csr_edge_capsule); the curve is the
    # kernel's csr_spline bit for bit.
    rng = np.random.default_rng(n)
    angles = np.sort(rng.random(n)) * 6.0
    q = np.c_[np.cos(angles), np.sin(angles), 0.1 * rng.standard_normal(n)] * 37.5
    curve = _kernel.csr_spline(q, closed=closed)
    part = fw.csr_spline(q, closed=closed)
    poles = np.array([tuple(p) for p in part.getPoles()])
    assert np.array_equal(bits(poles), bits(curve.poles))
    assert np.array_equal(bits(part.getKnots()), bits(curve.knots))
    assert list(part.getMultiplicities()) == curve.mults.tolist()
    assert part.isPeriodic() == closed


def _rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


def test_a_shape_is_adopted_exactly_once():
    """Issue 13: the bridge took any integer as a TopoDS_Shape*; adopting one twice freed
    the shape twice. Now a capsule hands its shape over once."""
    capsule = _kernel.edge_capsule(next(curves())[1])
    shape = kernel.adopt(capsule)
    assert shape.ShapeType == "Edge" and shape.isValid()
    with pytest.raises(TypeError, match="adopted already"):
        kernel.adopt(capsule)
    for wrong in (12345, None, "edge", object()):
        with pytest.raises(TypeError, match="shape capsule"):
            kernel.adopt(wrong)
    assert shape.Edge1.Curve.NbPoles == 12  # the adopted shape is unharmed


def test_a_capsule_never_adopted_frees_its_shape():
    """Dropping capsules does not leak their shapes: 400 edges of 20000 poles each would hold
    about 190 MB if leaked."""
    rng = np.random.default_rng(3)
    big = _kernel.csr_spline(np.c_[np.cumsum(rng.random(20000)), rng.random(20000), np.zeros(20000)])
    for _ in range(20):  # warm up the allocator
        _kernel.edge_capsule(big)
    before = _rss_bytes()
    for _ in range(400):
        _kernel.edge_capsule(big)  # made and dropped at once
    assert _rss_bytes() - before < 40e6
