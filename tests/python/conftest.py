# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Shared fixtures of the Python module's tests. CTest runs them with the
# build's module directory on PYTHONPATH (tests/python/CMakeLists.txt).
import os
import pathlib

import pytest


@pytest.fixture(scope="session")
def source_dir():
    """The repository root (configs/, examples/)."""
    env = os.environ.get("TESSELLA_SOURCE_DIR")
    return pathlib.Path(env) if env else pathlib.Path(__file__).resolve().parents[2]
