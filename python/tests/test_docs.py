"""The documentation runs: the docstring examples of the package (Python
and compiled halves) and every Python example of python/README.md."""

import doctest
import json
import pathlib
import re
from fractions import Fraction

import pytest

import quadsect
import quadsect._components
import quadsect._errors
import quadsect.dask

README = pathlib.Path(__file__).resolve().parents[1] / "README.md"
ROOT_README = pathlib.Path(__file__).resolve().parents[2] / "README.md"
GLOBS = {"quadsect": quadsect, "Fraction": Fraction, "json": json,
         "RealAlgebraic": quadsect.RealAlgebraic, "Sphere": quadsect.Sphere,
         "QuadraticIrrational": quadsect.QuadraticIrrational,
         "Cylinder": quadsect.Cylinder, "Cone": quadsect.Cone}


@pytest.mark.parametrize("module", [quadsect, quadsect._components, quadsect._errors, quadsect.dask],
                         ids=lambda m: m.__name__)
def test_docstring_examples_of_the_python_half(module):
    result = doctest.testmod(module, extraglobs=GLOBS, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0 and result.failed == 0


def compiled_docstrings():
    """The docstrings of the compiled half (the Rust doc comments)."""
    ra, qi = quadsect.RealAlgebraic, quadsect.QuadraticIrrational
    objects = [quadsect.exact, quadsect.answer_line, ra, qi, quadsect._quadsect.Batch]
    objects += [getattr(ra, name) for name in dir(ra) if not name.startswith("_")]
    objects += [getattr(qi, name) for name in dir(qi) if not name.startswith("_")]
    return [(getattr(o, "__qualname__", getattr(o, "__name__", repr(o))), o.__doc__ or "") for o in objects]


def test_docstring_examples_of_the_compiled_half():
    parser, runner = doctest.DocTestParser(), doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    examples = 0
    for name, doc in compiled_docstrings():
        test = parser.get_doctest(doc, dict(GLOBS), name, None, 0)
        examples += len(test.examples)
        runner.run(test)
    assert examples >= 5
    assert runner.failures == 0


def test_every_public_item_has_a_docstring():
    for name in quadsect.__all__:
        obj = getattr(quadsect, name)
        if callable(obj):
            assert (obj.__doc__ or "").strip(), name


def python_blocks(path):
    return re.findall(r"```python\n(.*?)```", path.read_text(), flags=re.S)


@pytest.mark.parametrize("readme,least", [(README, 5), (ROOT_README, 1)], ids=["python/README.md", "README.md"])
def test_readme_python_examples_run(readme, least, tmp_path, monkeypatch):
    """Every ```python block of the README runs as written, in order, in one
    namespace (as a reader pasting them into one session), in a fresh
    directory."""
    blocks = python_blocks(readme)
    assert len(blocks) >= least
    monkeypatch.chdir(tmp_path)
    namespace: dict = {"__name__": "__main__"}
    for block in blocks:
        exec(compile(block, str(readme), "exec"), namespace)
