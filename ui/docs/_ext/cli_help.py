"""The `nibrig` command's own --help, read as data: the command pages of the site and the test of
its example commands both take every command, option and subcommand from here, so that nothing
about the command line is written twice."""

from __future__ import annotations

import dataclasses
import os
import re
import subprocess
from pathlib import Path

REPOSITORY = Path(__file__).resolve().parents[3]

# CLI11 puts an entry's help at this column, or on the next line when the name is wider.
HELP_COLUMN = 30


def command_path() -> Path:
    """The built `nibrig`: $NIBRIG_COMMAND, else the release tree's."""
    return Path(os.environ.get("NIBRIG_COMMAND", REPOSITORY / "build/release/ui/nibrig"))


@dataclasses.dataclass
class Entry:
    names: list[str]  # "-o", "--output"; a positional's name
    argument: str     # "TEXT:FILE=design_search.json", "Excludes: --quiet", ""
    help: str


@dataclasses.dataclass
class Help:
    words: list[str]  # after "nibrig": [], ["design", "loop"]
    description: str = ""
    usage: str = ""
    positionals: list[Entry] = dataclasses.field(default_factory=list)
    options: list[Entry] = dataclasses.field(default_factory=list)
    global_options: list[Entry] = dataclasses.field(default_factory=list)
    subcommands: list[Entry] = dataclasses.field(default_factory=list)
    footer: str = ""

    @property
    def name(self) -> str:
        return " ".join(["nibrig", *self.words])

    def option_names(self) -> set[str]:
        return {n for e in self.options + self.global_options for n in e.names}


SECTIONS = {"Positionals:": "positionals", "Options:": "options",
            "Global options:": "global_options", "Subcommands:": "subcommands"}


def _entry(line: str, section: str, help_follows: bool) -> Entry:
    # A name of HELP_COLUMN characters or more has its help on the lines that follow.
    head, text = line, ""
    if not help_follows and len(line) > HELP_COLUMN:
        head, text = line[:HELP_COLUMN], line[HELP_COLUMN:]
    head = head.strip()
    if section == "subcommands":
        return Entry([head], "", text.strip())
    name, _, argument = head.partition(" ")
    return Entry(name.split(","), argument.strip(), text.strip())


def parse(words: list[str], text: str) -> Help:
    help = Help(list(words))
    description: list[str] = []
    footer: list[str] = []
    section = None
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("Usage: "):
            # The program's path as it was run, replaced by the name a user types.
            rest = line[len("Usage: "):].split(" ", 1)
            help.usage = "nibrig" + (" " + rest[1] if len(rest) > 1 else "")
            section = "after-usage"
        elif line in SECTIONS:
            section = SECTIONS[line]
        elif section is None:
            description.append(line)
        elif section in SECTIONS.values() and line.startswith("  "):
            entries = getattr(help, section)
            if line.startswith(" " * HELP_COLUMN) and entries:
                entries[-1].help = (entries[-1].help + " " + line.strip()).strip()
            else:
                follows = i + 1 < len(lines) and lines[i + 1].startswith(" " * HELP_COLUMN)
                entries.append(_entry(line, section, follows and len(line) >= HELP_COLUMN))
        elif line.strip() and section != "after-usage" or footer:
            section = "footer"
            footer.append(line)
    help.description = "\n".join(description).strip()
    help.footer = "\n".join(footer).strip()
    return help


def panel_path() -> Path:
    """The built `nibrig-panel`: $NIBRIG_PANEL, else the release tree's."""
    return Path(os.environ.get("NIBRIG_PANEL", REPOSITORY / "build/release/ui/panel/nibrig-panel"))


def read(words: list[str], command: Path | None = None) -> Help:
    run = subprocess.run([str(command or command_path()), *words, "--help"], capture_output=True,
                         text=True, timeout=60, check=True)
    return parse(words, run.stdout)


def every_command(command: Path | None = None) -> list[Help]:
    """Every visible command, root first, each followed by its subcommands, in --help's order."""
    found: list[Help] = []

    def walk(words: list[str]) -> None:
        help = read(words, command)
        found.append(help)
        for sub in help.subcommands:
            walk([*words, sub.names[0]])

    walk([])
    return found


def page_name(words: list[str]) -> str:
    return "-".join(["nibrig", *words])

