"""The type hints (.pyi) say what the compiled module has: mypy's stubtest compares every stub with
the imported module (names, signatures, properties that are read-only), so that editors and
type-checkers see the module as it is."""

import ast
import inspect
import os
import pathlib
import subprocess
import sys

import nibrig

ALLOWLIST = pathlib.Path(__file__).with_name("stubtest_allowlist.txt")


def test_the_stubs_match_the_module(tmp_path):
    environment = dict(os.environ, MYPY_CACHE_DIR=str(tmp_path / "mypy_cache"))
    result = subprocess.run([sys.executable, "-m", "mypy.stubtest", "nibrig", "--allowlist", str(ALLOWLIST)],
                            capture_output=True, text=True, timeout=300, env=environment)
    assert result.returncode == 0, result.stdout + result.stderr


def _documented(owner, prefix):
    """(dotted name, docstring as help() shows it) of every documented class, function and property."""
    for name, obj in vars(owner).items():
        if name.startswith("_"):
            continue
        doc = inspect.getdoc(obj)
        if isinstance(obj, (type, property)) or callable(obj):
            if doc and callable(obj) and not isinstance(obj, (type, property)) and doc.startswith(name + "("):
                doc = doc.partition("\n")[2].strip()  # pybind11's signature line
            if doc:
                yield prefix + name, doc
        if isinstance(obj, type) and obj.__module__.startswith("nibrig"):
            yield from _documented(obj, prefix + name + ".")


def _pyi_docstrings(path):
    out = {}

    def walk(nodes, prefix):
        for node in nodes:
            if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
                doc = ast.get_docstring(node)
                if doc:
                    out[prefix + node.name] = doc
                if isinstance(node, ast.ClassDef):
                    walk(node.body, prefix + node.name + ".")

    walk(ast.parse(path.read_text()).body, "")
    return out


def test_the_stubs_carry_the_bindings_docstrings():
    """Written once in the bindings, copied into the installed stubs by the build, so that an editor's
    hover says what help() says (ui/python/pyi_docstrings.py)."""
    package = pathlib.Path(nibrig.__file__).parent
    checked = 0
    for module in (nibrig.audition, nibrig.design, nibrig.measure, nibrig.render, nibrig.rig, nibrig.space,
                   nibrig.study):
        stubs = _pyi_docstrings(package / (module.__name__.split(".")[-1] + ".pyi"))
        for name, doc in _documented(module, ""):
            if name.split(".")[0] not in module.__all__:
                continue
            assert stubs.get(name) == doc, name
            checked += 1
    assert checked > 150  # the module documents some two hundred names; all of them were compared


def test_the_source_stubs_hold_no_docstrings():
    """A docstring typed into a source stub would be a second copy that could disagree."""
    source = pathlib.Path(__file__).parents[3] / "ui" / "python" / "nibrig"
    for stub in source.glob("*.pyi"):
        tree = ast.parse(stub.read_text())
        assert ast.get_docstring(tree) is None, stub
        assert _pyi_docstrings(stub) == {}, stub
