"""The type hints (.pyi) say what the compiled module has: mypy's stubtest compares every stub with
the imported module (names, signatures, properties that are read-only), so that editors and
type-checkers see the module as it is."""

import os
import pathlib
import subprocess
import sys

ALLOWLIST = pathlib.Path(__file__).with_name("stubtest_allowlist.txt")


def test_the_stubs_match_the_module(tmp_path):
    environment = dict(os.environ, MYPY_CACHE_DIR=str(tmp_path / "mypy_cache"))
    result = subprocess.run([sys.executable, "-m", "mypy.stubtest", "nibrig", "--allowlist", str(ALLOWLIST)],
                            capture_output=True, text=True, timeout=300, env=environment)
    assert result.returncode == 0, result.stdout + result.stderr
