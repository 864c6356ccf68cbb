import os
import sys

import pytest

# The module from the build tree (ctest sets PYTHONPATH); a clear message when it is not there.
try:
    import softgl  # noqa: F401
except ImportError as e:  # pragma: no cover
    sys.exit(f"softgl is not importable ({e}): build with -DSOFTGL_BUILD_PYTHON=ON and set PYTHONPATH")


@pytest.fixture
def reference_program():
    path = os.environ.get("SOFTGL_PYTHON_REFERENCE")
    if not path or not os.path.exists(path):
        pytest.fail("SOFTGL_PYTHON_REFERENCE must name the softgl_python_reference program (ctest sets it)")
    return path
