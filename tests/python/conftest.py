"""Fixtures shared by the Python tests.

`tool_path`: the tool this build made, whose output several tests compare with the module's
(ctest passes its path in VIBROFRIC_TOOL, tests/python/CMakeLists.txt). Such a comparison is never
skipped: without the variable, or with a path that is not an executable, the test fails.
"""
import os

import pytest


@pytest.fixture(scope="session")
def tool_path():
    path = os.environ.get("VIBROFRIC_TOOL")
    if not path:
        pytest.fail("VIBROFRIC_TOOL (the tool's path) is not set: this test compares the module with the tool")
    if not os.access(path, os.X_OK):
        pytest.fail(f"VIBROFRIC_TOOL = {path!r} is not an executable")
    return path
