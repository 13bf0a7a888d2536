# The nibrig documentation site: `sphinx-build -W --keep-going -b html ui/docs build/docs/html`.
# The command reference comes from the built `nibrig` ($NIBRIG_COMMAND) and the Python reference from
# the built module ($NIBRIG_PYTHON, else build/release/python), so both say what the build does.
import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPOSITORY = HERE.parents[1]
sys.path.insert(0, str(HERE / "_ext"))
sys.path.insert(0, os.environ.get("NIBRIG_PYTHON", str(REPOSITORY / "build/release/python")))

project = "nibrig"
author = "the nibrig authors"
copyright = "the nibrig authors"

extensions = ["myst_parser", "sphinx.ext.autodoc", "nibrig_commands", "repo_links"]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
exclude_patterns = ["_build"]
myst_enable_extensions = ["colon_fence"]
# Options are written --name: docutils' smart quotes would make their "--" an en dash.
smartquotes = False
myst_heading_anchors = 4  # GitHub's heading slugs, so the repository's Markdown links still work

html_theme = "alabaster"
html_title = "nibrig"
html_theme_options = {"nosidebar": False, "page_width": "1100px", "sidebar_width": "240px"}
html_sidebars = {"**": ["about.html", "navigation.html", "relations.html", "searchbox.html"]}

autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": True}


def _plain_docstring(app, what, name, obj, options, lines):
    # The bindings' docstrings are plain text for help() and the stubs, where |H(f)| is a modulus,
    # not a reStructuredText substitution.
    lines[:] = [line.replace("|", "\\|") for line in lines]


def setup(app):
    app.connect("autodoc-process-docstring", _plain_docstring)
