"""How the module behaves in a Python process: dtype and layout conversions,
the GIL released, progress, threads, Ctrl-C, memory over repeated calls."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import conformal_alpha_shapes as cas
from conftest import ellipsoid

POINTS, NORMALS, _ = ellipsoid(3000, (1.5, 1.0, 0.75), noise=0.001)
SMALL = dict(radii=("4s",))


def same_layers(r, s):
    assert r.layers == s.layers
    for name in r.layers:
        for key in r[name].keys():
            assert np.array_equal(r[name][key], s[name][key], equal_nan=True), (name, key)


def test_dtypes_and_layouts_are_converted():
    reference = cas.multiscale_curvatures(POINTS, **SMALL)
    fortran = np.asfortranarray(POINTS)
    strided = np.zeros((len(POINTS), 6))
    strided[:, ::2] = POINTS
    same_layers(reference, cas.multiscale_curvatures(fortran, **SMALL))
    same_layers(reference, cas.multiscale_curvatures(strided[:, ::2], **SMALL))
    same_layers(reference, cas.multiscale_curvatures(POINTS.tolist(), **SMALL))
    as_float32 = POINTS.astype(np.float32)
    same_layers(cas.multiscale_curvatures(as_float32.astype(np.float64), **SMALL),
                cas.multiscale_curvatures(as_float32, **SMALL))
    integers = np.rint(POINTS * 1000).astype(np.int32)
    same_layers(cas.multiscale_curvatures(integers.astype(np.float64), **SMALL),
                cas.multiscale_curvatures(integers, **SMALL))


def test_threads_give_the_same_bits():
    same_layers(cas.multiscale_curvatures(POINTS, threads=1), cas.multiscale_curvatures(POINTS, threads=2))


def test_progress_is_reported_in_order():
    calls = []
    cas.multiscale_curvatures(POINTS, scales=("auto", "50%"), progress=lambda stage, f: calls.append((stage, f)))
    fractions = [f for _, f in calls]
    assert fractions[0] == 0 and fractions[-1] == 1 and fractions == sorted(fractions)
    stages = [s for s, _ in calls]
    assert stages[0] == "conformal alpha shape" and "surface at scale 50%" in stages and stages[-1] == "done"


def test_progress_moves_inside_the_steps():
    """Calls at each step's start and every 0.1 s inside, by the time the steps take."""
    points, _, _ = ellipsoid(40000, (1.5, 1.0, 0.75), noise=0.002, seed=5)
    calls = []
    start = time.monotonic()
    cas.multiscale_curvatures(points, progress=lambda stage, f: calls.append((time.monotonic() - start, stage, f)))
    total = time.monotonic() - start
    fractions = [f for _, _, f in calls]
    assert fractions == sorted(fractions) and calls[-1][1:] == ("done", 1.0)
    stages = [stage for _, stage, _ in calls]
    assert stages[0] == "conformal alpha shape" and stages.count("conformal alpha shape") > 1
    assert stages.count("curvature at scale auto") > 2
    assert len(calls) >= total / 0.1 / 3, (len(calls), total)
    # halfway through the time, about halfway through the bar
    middle = [f for t, _, f in calls if t <= total / 2][-1]
    assert 0.2 < middle < 0.8, calls


def test_an_exception_in_progress_inside_a_step_stops_the_call():
    points, _, _ = ellipsoid(40000, (1.5, 1.0, 0.75), noise=0.002, seed=5)

    def fail(stage, fraction):
        if stage == "conformal alpha shape" and fraction > 0:
            raise RuntimeError("stop in the shape")
    start = time.monotonic()
    with pytest.raises(RuntimeError, match="stop in the shape"):
        cas.multiscale_curvatures(points, progress=fail)
    assert time.monotonic() - start < 2


def test_an_exception_in_progress_stops_the_call():
    def fail(stage, fraction):
        if stage.startswith("curvature"):
            raise RuntimeError("stop here")
    with pytest.raises(RuntimeError, match="stop here"):
        cas.multiscale_curvatures(POINTS, progress=fail)


def test_the_gil_is_released():
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.005)

    points, _, _ = ellipsoid(60000, (1.5, 1.0, 0.75), noise=0.001)
    counter = threading.Thread(target=count)
    counter.start()
    start = time.perf_counter()
    try:
        cas.multiscale_curvatures(points, radii=("4s",))
    finally:
        done.set()
        counter.join()
    during = [t for t in ticks if t > start + 0.2]
    # the other thread ran all along the call, not only at its checkpoints
    assert len(during) > 20, len(during)
    gaps = np.diff(during)
    assert gaps.max() < 0.5, gaps.max()


def test_ctrl_c_stops_a_long_call():
    points, _, _ = ellipsoid(200000, (1.5, 1.0, 0.75), noise=0.001)
    for delay in (0.5, 2.0, 4.0):  # in the construction, the front or the curvature
        sent = []
        timer = threading.Timer(delay, lambda: (sent.append(time.perf_counter()),
                                                os.kill(os.getpid(), signal.SIGINT)))
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            cas.multiscale_curvatures(points, scales=("auto", "25%", "50%"))
        stopped = time.perf_counter()
        timer.join()
        # the library checks every 20 ms; a loaded CI machine may take longer
        assert stopped - sent[0] < 2.0, (delay, stopped - sent[0])
    # the process works as before
    same_layers(cas.multiscale_curvatures(POINTS, **SMALL), cas.multiscale_curvatures(POINTS, **SMALL))


def resident_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def test_no_memory_grows_over_50_calls():
    for _ in range(5):
        cas.multiscale_curvatures(POINTS, NORMALS, **SMALL)
    before = resident_bytes()
    for _ in range(50):
        r = cas.multiscale_curvatures(POINTS, NORMALS, **SMALL)
        cas.ConformalAlphaShape(POINTS).surface()
        del r
    growth = resident_bytes() - before
    # one call's arrays are about 0.4 MB; 50 kept would be 20 MB
    assert growth < 8 * 2**20, growth
