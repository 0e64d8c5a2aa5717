"""What the tests of the Python module share: the paths ctest passes, the
shapes with known curvature, and a failure (never a skip) when something
a test needs is missing."""
import os

import numpy as np
import pytest


def required_path(variable, what):
    """The path in environment variable `variable`; the test fails when it is unset or missing."""
    path = os.environ.get(variable)
    if not path:
        pytest.fail(f"{variable} is not set: run the tests through ctest (it passes {what})")
    if not os.path.exists(path):
        pytest.fail(f"{what} is missing: {path} (libcgal-demo's data are extracted by cmake; "
                    f"apt-get install libcgal-demo and run cmake again)")
    return path


def scan_path(name):
    return required_path("CAS3_TEST_DATA", "the folder of libcgal-demo's scans") + "/" + name


def fibonacci_sphere(n, radius=1.0):
    """n points spread evenly on a sphere and their outward normals."""
    i = np.arange(n) + 0.5
    z = 1 - 2 * i / n
    r = np.sqrt(1 - z * z)
    phi = np.pi * (1 + 5 ** 0.5) * i
    normals = np.column_stack([r * np.cos(phi), r * np.sin(phi), z])
    return radius * normals, normals


def ellipsoid(n, axes, noise=0.0, seed=1):
    """n points on the ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1, displaced along
    their normals by Gaussian noise of standard deviation `noise`; the points
    before the noise, their outward normals and mean curvatures."""
    a, b, c = axes
    unit, _ = fibonacci_sphere(n)
    exact = unit * np.array(axes)
    gradient = exact / np.array([a * a, b * b, c * c])
    normals = gradient / np.linalg.norm(gradient, axis=1)[:, None]
    x, y, z = exact.T
    # the mean curvature of an ellipsoid, positive with outward normals
    q = x * x / a**4 + y * y / b**4 + z * z / c**4
    mean = (x * x + y * y + z * z - a * a - b * b - c * c) / (2 * (a * b * c) ** 2 * q ** 1.5)
    rng = np.random.default_rng(seed)
    noisy = exact + normals * rng.normal(0.0, noise, n)[:, None] if noise > 0 else exact
    return noisy, normals, -mean
