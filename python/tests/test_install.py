# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# `cmake --install` puts the module into the prefix's site-packages, where it imports and runs.
import os
import pathlib
import subprocess
import sys

import pytest


def test_install_into_a_prefix_and_import_from_there(tmp_path):
    build = os.environ.get("CVT2_BUILD_DIR")
    site = os.environ.get("CVT2_PYTHON_INSTALL_DIR")
    if not build or not site:
        pytest.skip("not run by CTest (CVT2_BUILD_DIR, CVT2_PYTHON_INSTALL_DIR)")
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", build, "--prefix", str(prefix), "--component", "python"],
                   check=True, capture_output=True)
    package = prefix / site / "cvt2"
    assert (package / "__init__.py").is_file() and (package / "__init__.pyi").is_file()
    assert len(list(package.glob("_cvt2*.so"))) == 1
    script = (
        "import cvt2, numpy as np; "
        "d = cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]]); "
        "r = cvt2.optimize(d, cvt2.random_points(d, 100)); "
        "print(cvt2.__file__, r.stop_reason, len(r.bounded_voronoi().to_shapely()))"
    )
    env = dict(os.environ, PYTHONPATH=str(prefix / site))
    out = subprocess.run([sys.executable, "-c", script], check=True, capture_output=True,
                         text=True, env=env, cwd=tmp_path).stdout.split()
    assert pathlib.Path(out[0]).resolve() == (package / "__init__.py").resolve()
    assert out[1] == "converged" and out[2] == "104"
