"""The tree's `nibrig` executable, which the tests compare the module with: $NIBRIG_COMMAND (ctest
sets it); a run without it skips those comparisons."""

import os

import pytest


def nibrig_command() -> str:
    path = os.environ.get("NIBRIG_COMMAND")
    if not path:
        pytest.skip("NIBRIG_COMMAND (the nibrig executable) not given")
    return path
