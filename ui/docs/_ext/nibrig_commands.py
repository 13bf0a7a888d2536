"""Sphinx extension: a page per `nibrig` command, made from the built command's own --help.

At the start of each build it asks the built `nibrig` (cli_help.command_path()) for every command's
help, writes a stub page per command into commands/ (generated, not kept in git) and renders each
stub's `nibrig-help` directive from that help: usage, description, arguments, options, subcommands.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import Directive
from sphinx import addnodes
from sphinx.errors import ExtensionError

import cli_help

FOLDER = "commands"
STAMP = ".generated"  # marks the folder as ours to clear


def _stub(help: cli_help.Help) -> str:
    words = " ".join(help.words)
    lines = [f"# {help.name}", "", f"```{{nibrig-help}} {words}".rstrip(), "```", ""]
    if help.subcommands:
        lines += ["```{toctree}", ":hidden:", ""]
        lines += [cli_help.page_name([*help.words, s.names[0]]) for s in help.subcommands]
        lines += ["```", ""]
    return "\n".join(lines)


def _write_stubs(app) -> None:
    try:
        helps = cli_help.every_command()
    except (OSError, Exception) as error:  # a missing or broken build: say which file
        raise ExtensionError(
            f"cannot read the help of {cli_help.command_path()} (build it, or set "
            f"NIBRIG_COMMAND): {error}") from error
    app.env.nibrig_helps = {tuple(h.words): h for h in helps}
    folder = Path(app.srcdir) / FOLDER
    if folder.exists() and not (folder / STAMP).exists():
        raise ExtensionError(f"{folder} exists and was not written by this extension")
    wanted = {cli_help.page_name(h.words) + ".md": _stub(h) for h in helps}
    folder.mkdir(exist_ok=True)
    (folder / STAMP).write_text("Written by ui/docs/_ext/nibrig_commands.py at each build.\n")
    for stale in folder.glob("*.md"):
        if stale.name not in wanted:
            stale.unlink()
    for name, text in wanted.items():
        page = folder / name
        # Written only when changed, so that Sphinx rebuilds only the pages whose help changed.
        if not page.exists() or page.read_text() != text:
            page.write_text(text)


def _inline(text: str) -> list[nodes.Node]:
    """Help text with its `code` spans as literals; nothing else in it is markup."""
    # The help names the user's own folders under the home of whoever builds the site.
    text = text.replace(os.path.expanduser("~") + "/", "~/")
    out: list[nodes.Node] = []
    for i, part in enumerate(re.split(r"`([^`]+)`", text)):
        if part:
            out.append(nodes.literal(part, part) if i % 2 else nodes.Text(part))
    return out


def _paragraphs(text: str) -> list[nodes.Node]:
    # CLI11 keeps the help's own line breaks: a blank line or a short line ends a paragraph.
    blocks = [b for b in re.split(r"\n\s*\n", text) if b.strip()]
    return [nodes.paragraph("", "", *_inline(" ".join(b.split()))) for b in blocks]


class NibrigHelp(Directive):
    """```{nibrig-help} design loop``` renders `nibrig design loop --help`."""

    optional_arguments = 10
    has_content = False

    def run(self) -> list[nodes.Node]:
        env = self.state.document.settings.env
        words = tuple(self.arguments)
        help = getattr(env, "nibrig_helps", {}).get(words)
        if help is None:
            raise self.error(f"no command `nibrig {' '.join(words)}` in the built command's help")
        out: list[nodes.Node] = _paragraphs(help.description)
        out.append(nodes.literal_block(help.usage, help.usage))
        out += _paragraphs(help.footer)
        for title, entries in (("Arguments", help.positionals), ("Options", help.options)):
            if entries:
                out.append(nodes.rubric(title, title))
                out.append(self._entries(entries))
        if help.subcommands:
            out.append(nodes.rubric("Subcommands", "Subcommands"))
            listing = nodes.bullet_list()
            for sub in help.subcommands:
                name = sub.names[0]
                ref = addnodes.pending_xref(
                    "", nodes.literal(name, name), refdomain="std", reftype="doc",
                    reftarget=cli_help.page_name([*words, name]), refexplicit=True,
                    refdoc=env.docname, refwarn=True)
                item = nodes.paragraph("", "", ref, nodes.Text(": "), *_inline(sub.help))
                listing.append(nodes.list_item("", item))
            out.append(listing)
        if help.global_options:
            text = "Global options"
            out.append(nodes.rubric(text, text))
            out.append(self._entries(help.global_options))
        return out

    @staticmethod
    def _entries(entries: list[cli_help.Entry]) -> nodes.Node:
        listing = nodes.definition_list()
        for e in entries:
            term = nodes.term()
            term += nodes.literal(", ".join(e.names), ", ".join(e.names))
            if e.argument:
                term += nodes.Text(" ")
                term += nodes.emphasis(e.argument, e.argument)
            body = nodes.definition("", nodes.paragraph("", "", *_inline(e.help)))
            listing.append(nodes.definition_list_item("", term, body))
        return listing


def setup(app):
    app.connect("builder-inited", _write_stubs)
    app.add_directive("nibrig-help", NibrigHelp)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
