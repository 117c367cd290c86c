"""Sphinx configuration of dispkin's API reference (`make docs`: build/docs/html, warnings are
errors). The reference is generated from the docstrings of the installed package: the compiled
module's (pybind11, with its signatures) and the Python modules'."""

import dispkin

project = "dispkin"
author = "the dispkin developers"
copyright = "2026, the dispkin developers"
release = version = dispkin.__version__

extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon"]
autodoc_default_options = {"members": True, "undoc-members": True, "show-inheritance": False}
autodoc_member_order = "bysource"
# The compiled classes are re-exported from dispkin._core: document them under `dispkin`.
add_module_names = False
html_theme = "alabaster"
html_title = f"dispkin {release} API reference"
exclude_patterns = ["_build"]
nitpicky = False


def _plain_text_marks(app, what, name, obj, options, lines):
    """dispkin's docstrings write |x| for an absolute value or a norm, never a reStructuredText
    substitution: escape every bar. The compiled module's docstrings are plain text (they read
    the same in help() and the stubs; pybind11 adds the signatures, with their bare `*`): escape
    their asterisks too."""
    compiled = getattr(obj, "__module__", None) == "dispkin._core" or type(obj).__name__ in (
        "builtin_function_or_method",
        "instancemethod",
        "property",
    )
    for i, line in enumerate(lines):
        line = line.replace("|", r"\|")
        lines[i] = line.replace("*", r"\*") if compiled else line


def setup(app):
    app.connect("autodoc-process-docstring", _plain_text_marks)
