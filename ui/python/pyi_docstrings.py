"""Writes the package's type stubs with the docstrings of the built module.

The hand-written stubs (ui/python/nibrig/*.pyi) carry the types only; every docstring is written
once, in the bindings (or a submodule's .py), and copied here into the stubs the build installs, so
that an editor shows what help() shows. Run by the build after the module is linked:

    python3 pyi_docstrings.py SOURCE_STUBS_DIR PACKAGE_DIR

with PACKAGE_DIR's parent on the import path. Refuses a stub that already holds a docstring.
"""

import ast
import importlib
import inspect
import pathlib
import re
import sys
from typing import Any, List, Optional, Tuple

_SIGNATURE = re.compile(r"^\w+\(.*\)( -> .*)?$")


def runtime_doc(obj: Any) -> Optional[str]:
    """The docstring a person reads, without pybind11's signature line."""
    doc = getattr(obj, "__doc__", None)
    if not doc or not doc.strip():
        return None
    if callable(obj) and not inspect.isclass(obj) and not isinstance(obj, property):
        head, _, rest = doc.lstrip().partition("\n")
        if _SIGNATURE.match(head):  # pybind11's signature line; an overload's stay in the text
            doc = rest
    doc = inspect.cleandoc(doc).strip()
    return doc or None


def quoted(doc: str, indent: str) -> List[str]:
    doc = doc.replace("\\", "\\\\").replace('"""', '\\"\\"\\"')
    lines = doc.split("\n")
    if len(lines) == 1:
        return [f'{indent}"""{doc}"""']
    return [f'{indent}"""{lines[0]}'] + [f"{indent}{line}" if line else "" for line in lines[1:]] + [f'{indent}"""']


def member(owner: Any, name: str) -> Any:
    obj = inspect.getattr_static(owner, name, None)
    if isinstance(obj, (staticmethod, classmethod)):
        obj = obj.__func__
    return obj


def insertions(stub: pathlib.Path, module: Any) -> List[Tuple[int, List[str], bool]]:
    """(line index, docstring lines, whether the line's trailing '...' goes) for each definition."""
    tree = ast.parse(stub.read_text(), str(stub))
    out: List[Tuple[int, List[str], bool]] = []
    if ast.get_docstring(tree) is not None:
        raise SystemExit(f"{stub}: the module docstring belongs in its .py or the bindings, not the stub")
    if (doc := runtime_doc(module)) is not None:
        out.append((0, quoted(doc, "") + [""], False))

    def walk(nodes: List[ast.stmt], owner: Any) -> None:
        for node in nodes:
            if not isinstance(node, (ast.ClassDef, ast.FunctionDef)):
                continue
            if ast.get_docstring(node) is not None:
                raise SystemExit(f"{stub}:{node.lineno}: {node.name}'s docstring belongs in the bindings")
            obj = member(owner, node.name) if owner is not None else None
            first = node.body[0]
            doc = runtime_doc(obj) if obj is not None else None
            if doc is not None:
                indent = " " * (node.col_offset + 4)
                # A body of `...` (after the colon or on its own line) gives way to the docstring.
                ellipsis = isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and first.value.value is Ellipsis
                start = min([first.lineno] + [d.lineno for d in getattr(first, "decorator_list", [])])
                out.append((start - 1, quoted(doc, indent), ellipsis))
            if isinstance(node, ast.ClassDef):
                walk(node.body, getattr(owner, node.name, None) if owner is not None else None)

    walk(tree.body, module)
    return out


def with_docstrings(stub: pathlib.Path, module: Any) -> str:
    lines = stub.read_text().split("\n")
    for at, doc, drops_ellipsis in sorted(insertions(stub, module), key=lambda i: (i[0], i[2]), reverse=True):
        if drops_ellipsis:
            line = lines[at]
            stripped = line.rstrip()
            assert stripped.endswith("..."), f"{stub}:{at + 1}: expected a body of '...'"
            head = stripped[: -len("...")].rstrip()
            if head:  # `def f() -> T: ...` becomes `def f() -> T:` and the docstring below
                lines[at : at + 1] = [head] + doc
            else:  # `...` alone: the docstring in its place
                lines[at : at + 1] = doc
        else:
            lines[at:at] = doc
    return "\n".join(lines)


def main(argv: List[str]) -> int:
    source, package = pathlib.Path(argv[1]), pathlib.Path(argv[2])
    sys.path.insert(0, str(package.parent))
    for stub in sorted(source.glob("*.pyi")):
        name = package.name if stub.stem == "__init__" else f"{package.name}.{stub.stem}"
        text = with_docstrings(stub, importlib.import_module(name))
        (package / stub.name).write_text(text)  # always: the build compares its time with the module's
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
