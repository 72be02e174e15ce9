"""Writes carom/_carom.pyi, the type stubs of the compiled module, from the module itself.

pybind11 puts each function's signature, with its C++ types named in Python's terms, on the first
line of its docstring; this reads those lines (and the docstrings after them) and writes them as
a stub file, so that editors and type checkers complete and check calls into carom. The build
runs it after linking the module, so the stubs always describe the module beside them:

    python3 write_stubs.py BUILD/python/carom/_carom.pyi   (with BUILD/python on PYTHONPATH)
"""

import argparse
import importlib
import inspect
import pathlib
import re
import sys

HEADER = '''"""Type stubs of carom._carom, written from the module by python/write_stubs.py."""

from typing import Any, Callable, Dict, Iterator, List, Optional, Sequence, Tuple, Union, overload
import os

import numpy
import numpy.typing

'''

# pybind11's names for types, as a stub writes them.
REPLACEMENTS = [
    (re.compile(r"numpy\.ndarray\[([\w.]+)\]"), r"numpy.typing.NDArray[\1]"),
    (re.compile(r"\bnumpy\.ndarray\b(?!\[)"), "numpy.typing.NDArray[Any]"),
    (re.compile(r"\bcarom\._carom\."), ""),
    (re.compile(r"\bos\.PathLike\b"), "Union[str, os.PathLike[str]]"),
    (re.compile(r"\bfunction\b"), "Callable[..., Any]"),
]
# A signature line: name(parameters) -> result (a property's getter has no name).
SIGNATURE = re.compile(r"^(\w*)\((.*)\)\s*->\s*(.+)$")


def stub_type(text):
    for pattern, replacement in REPLACEMENTS:
        text = pattern.sub(replacement, text)
    return text


def split_top_level(text, separator=","):
    """Splits at separators outside brackets and quotes."""
    parts, depth, quote, current = [], 0, None, ""
    for ch in text:
        if quote:
            current += ch
            if ch == quote:
                quote = None
            continue
        if ch in "'\"":
            quote = ch
        elif ch in "([{<":
            depth += 1
        elif ch in ")]}>":
            depth -= 1
        elif ch == separator and depth == 0:
            parts.append(current.strip())
            current = ""
            continue
        current += ch
    if current.strip():
        parts.append(current.strip())
    return parts


def stub_parameters(text):
    """pybind11's parameter list with stub types and every default written as `...`."""
    out = []
    for part in split_top_level(text):
        if part in ("*", "/") or part.startswith("*"):
            out.append(part)
            continue
        name, _, rest = part.partition(":")
        if name.strip() == "self":
            out.append("self")
            continue
        annotation, has_default, _ = rest.partition("=")
        parameter = f"{name.strip()}: {stub_type(annotation.strip())}"
        out.append(parameter + (" = ..." if has_default else ""))
    return ", ".join(out)


def signatures_and_doc(routine):
    """The signatures (more than one when overloaded) and the description after them."""
    lines = (inspect.getdoc(routine) or "").splitlines()
    signatures, description = [], []
    for line in lines:
        numbered = re.match(r"^\d+\. (.*)$", line)
        candidate = numbered.group(1) if numbered else line
        match = SIGNATURE.match(candidate)
        if match and (numbered or not signatures) and match.group(1) in ("", routine.__name__):
            signatures.append(match)
        elif line.strip() and line.strip() != "Overloaded function.":
            description.append(line.strip())
    return signatures, " ".join(description)


def docstring(text, indent):
    if not text:
        return ""
    text = text.replace("\\", "\\\\").replace('"', '\\"')
    return f'{indent}"""{text}"""\n'


def write_routine(routine, indent, decorator=""):
    signatures, description = signatures_and_doc(routine)
    if not signatures:
        raise SystemExit(f"write_stubs: no signature in the docstring of {routine.__qualname__}")
    out = ""
    for match in signatures:
        if len(signatures) > 1:
            out += f"{indent}@overload\n"
        if decorator:
            out += f"{indent}{decorator}\n"
        name, parameters, result = match.groups()
        out += f"{indent}def {name}({stub_parameters(parameters)}) -> {stub_type(result)}:\n"
        out += docstring(description, indent + "    ") or f"{indent}    ...\n"
        if description:
            out += f"{indent}    ...\n"
    return out


def write_property(name, prop, indent):
    signatures, description = signatures_and_doc(prop.fget)
    if not signatures:
        raise SystemExit(f"write_stubs: no signature in the getter of property {name}")
    result = stub_type(signatures[0].group(3))
    own = inspect.getdoc(prop) or ""
    if own and not SIGNATURE.match(own.splitlines()[0]):
        description = " ".join(line.strip() for line in own.splitlines() if line.strip())
    out = f"{indent}@property\n{indent}def {name}(self) -> {result}:\n"
    out += docstring(description, indent + "    ") + f"{indent}    ...\n"
    if prop.fset is not None:
        out += f"{indent}@{name}.setter\n{indent}def {name}(self, value: {result}) -> None: ...\n"
    return out


def write_class(name, cls):
    bases = [b.__name__ for b in cls.__bases__ if b.__name__ not in ("pybind11_object", "object")]
    out = f"class {name}({', '.join(bases)}):\n" if bases else f"class {name}:\n"
    out += docstring(inspect.getdoc(cls) or "", "    ")
    body = ""
    for member, value in cls.__dict__.items():
        if member.startswith("__") and member not in ("__init__", "__len__", "__bool__",
                                                       "__repr__", "__iter__", "__getitem__"):
            continue
        if member.startswith("_") and not member.startswith("__"):
            continue
        if isinstance(value, property):
            body += write_property(member, value, "    ")
        elif isinstance(value, staticmethod):
            body += write_routine(value.__func__, "    ", "@staticmethod")
        elif callable(value):
            if member == "__init__" and not signatures_and_doc(value)[0]:
                continue  # made by the module only: no constructor bound
            body += write_routine(value, "    ")
    return out + (body or "    ...\n") + "\n"


def write_stubs(module):
    out = HEADER
    for name in sorted(dir(module)):
        if name.startswith("_"):
            continue
        value = getattr(module, name)
        if inspect.isclass(value) and issubclass(value, BaseException):
            base = value.__bases__[0].__name__
            out += f"class {name}({base}): ...\n\n"
        elif inspect.isclass(value):
            out += write_class(name, value)
        elif callable(value):
            out += write_routine(value, "") + "\n"
        else:
            out += f"{name}: {type(value).__name__}\n\n"
    return out.rstrip() + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output", help="the .pyi file to write")
    parser.add_argument("--module", default="carom._carom")
    arguments = parser.parse_args()
    # The source folder beside this script holds the package without its compiled module; the
    # built package comes from PYTHONPATH.
    here = pathlib.Path(__file__).resolve().parent
    sys.path[:] = [p for p in sys.path if pathlib.Path(p or ".").resolve() != here]
    text = write_stubs(importlib.import_module(arguments.module))
    compile(text, arguments.output, "exec")  # a stub that does not parse is a bug here
    with open(arguments.output, "w", encoding="utf-8") as stub:
        stub.write(text)


if __name__ == "__main__":
    sys.exit(main())
