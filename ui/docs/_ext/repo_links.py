"""Sphinx extension: Markdown links between the repository's own files, checked.

The hardware guide, the formats and the architecture are included from where they live
(rig/HARDWARE.md...), so their links are relative to that place, not to the page that includes
them. A link MyST could not resolve is resolved here from the file it was written in: to the page
that includes the linked Markdown file (and its heading, when it names one), or, for any other file
of the repository that exists (a drawing, a header), to a copy of it the site serves. A link to
nothing stays a warning, which -W makes an error.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from sphinx import addnodes
from sphinx.transforms import SphinxTransform
from sphinx.util.nodes import make_refnode

INCLUDE = re.compile(r"^```\{include\}\s+(\S+)", re.M)


def _repository(app) -> Path:
    return Path(app.confdir).resolve().parents[1]


def _target(node, repository: Path):
    """(the linked file's real path, its anchor), or None for what is not a repository file."""
    if node.get("reftype") not in ("myst", "any") or not node.source:
        return None
    path, _, anchor = node["reftarget"].partition("#")
    if not path or "://" in path:
        return None
    real = (Path(node.source).parent / path).resolve()
    return (real, anchor) if repository in real.parents else None


class FileLinks(SphinxTransform):
    """A link to a repository file that is not Markdown becomes a download of it."""

    default_priority = 400

    def apply(self, **kwargs) -> None:
        repository = _repository(self.app)
        doc_folder = Path(self.env.doc2path(self.env.docname)).parent
        for node in list(self.document.findall(addnodes.pending_xref)):
            found = _target(node, repository)
            if found and not found[1] and found[0].is_file() and found[0].suffix != ".md":
                download = addnodes.download_reference(
                    refdoc=self.env.docname, reftarget=os.path.relpath(found[0], doc_folder),
                    reftype="myst", refdomain=None, refexplicit=True, refwarn=False)
                download.source, download.line = node.source, node.line
                download += node.children
                node.replace_self(download)


def _included(env) -> dict[Path, str]:
    """Every Markdown file a page includes, by its real path, to that page."""
    if not hasattr(env, "nibrig_included"):
        found = {}
        for doc in env.found_docs:
            source = Path(env.doc2path(doc))
            if source.suffix == ".md":
                for target in INCLUDE.findall(source.read_text()):
                    found[(source.parent / target).resolve()] = doc
        env.nibrig_included = found
    return env.nibrig_included


def _page_link(app, env, node, contnode):
    found = _target(node, _repository(app))
    if not found or found[0] not in _included(env):
        return None
    page, anchor = _included(env)[found[0]], found[1]
    label = ""
    if anchor:
        std = env.get_domain("std")
        key = f"{env.doc2path(page, base=False)}#{anchor}"
        if key not in std.anonlabels:
            return None  # a heading that is not there: the warning stands
        label = std.anonlabels[key][1]
    return make_refnode(app.builder, node["refdoc"], page, label, contnode)


def setup(app):
    app.add_transform(FileLinks)
    app.connect("missing-reference", _page_link)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
