"""The `nibrig` example commands of the documentation site, read from its Markdown pages and the
files they include: fenced shell blocks (their lines, with backslash continuations joined) and
inline code that starts with `nibrig ` (or `nibrig-panel `). A block whose `code-block` carries `:class: runs-here` runs
as written in the tests."""

from __future__ import annotations

import dataclasses
import re
import shlex
from pathlib import Path

REPOSITORY = Path(__file__).resolve().parents[3]
SITE = REPOSITORY / "ui/docs"
SHELLS = {"sh", "bash", "shell", "console"}
FENCE = re.compile(r"^(`{3,}|~{3,})\s*(\{code-block\}\s*)?(\S*)\s*$")
INCLUDE = re.compile(r"^```\{include\}\s+(\S+)", re.M)
INLINE = re.compile(r"(?<!`)`(nibrig(?:-panel)? [^`]+)`(?!`)")
PROGRAMS = {"nibrig", "nibrig-panel"}


@dataclasses.dataclass
class Example:
    where: str         # file:line, for the failure message
    line: str          # the command as written
    block: int | None  # the fenced block it is in (None: inline code)
    runs_here: bool


def pages() -> list[Path]:
    """The site's own pages and every file they include, each once; the generated command pages
    are --help itself and are left out."""
    found: list[Path] = []
    for page in sorted(SITE.rglob("*.md")):
        if page.parent.name == "commands":
            continue
        found.append(page)
        for target in INCLUDE.findall(page.read_text()):
            found.append((page.parent / target).resolve())
    return list(dict.fromkeys(found))


def _commands(line: str) -> list[str]:
    # A shell line's commands: comments dropped, split at ; && || and |.
    try:
        words = shlex.split(line, comments=True)
    except ValueError:
        return [line]
    text = " ".join(shlex.quote(w) if w not in {";", "&&", "||", "|"} else w for w in words)
    return [c.strip() for c in re.split(r"\s(?:;|&&|\|\||\|)\s", text) if c.strip()]


def examples() -> list[Example]:
    out: list[Example] = []
    block = 0
    for page in pages():
        where = page.relative_to(REPOSITORY)
        lines = page.read_text().splitlines()
        fence, language, runs, pending, start = None, "", False, "", 0
        for number, raw in enumerate(lines, 1):
            match = FENCE.match(raw.strip())
            if fence is None and match and match.group(1):
                fence, language, runs = match.group(1), match.group(3), False
                block += 1
                continue
            if fence is not None:
                if raw.strip() == fence:
                    fence = None
                elif language in SHELLS:
                    if raw.strip().startswith(":class:") and "runs-here" in raw:
                        runs = True
                    elif raw.strip().startswith(":"):
                        pass  # another directive option
                    elif raw.rstrip().endswith("\\"):
                        pending, start = pending + raw.rstrip()[:-1] + " ", start or number
                    else:
                        full, first = pending + raw, start or number
                        pending, start = "", 0
                        for command in _commands(full):
                            words = shlex.split(command)
                            if words and Path(words[0]).name in PROGRAMS:
                                out.append(Example(f"{where}:{first}", command, block, runs))
                continue
            for code in INLINE.findall(raw):
                out.append(Example(f"{where}:{number}", code, None, False))
    return out
