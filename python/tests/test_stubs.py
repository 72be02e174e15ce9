"""The type stubs beside the module (carom/_carom.pyi, written by the build) name every public
function, class, method and property of the module, each with a description, so that editors
complete and document every call."""
import ast
import inspect
import pathlib

import pytest

import carom
from carom import _carom

STUBS = pathlib.Path(_carom.__file__).with_name("_carom.pyi")


def stub_tree():
    if not STUBS.is_file():
        pytest.fail(f"no stubs at {STUBS}: the build writes them after linking the module")
    return ast.parse(STUBS.read_text(), filename=str(STUBS))


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_the_package_is_marked_typed():
    assert STUBS.with_name("py.typed").is_file()


def test_every_public_name_has_a_stub():
    tree = stub_tree()
    stubbed = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            stubbed.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            stubbed.add(node.target.id)
    assert public(dir(_carom)) == public(stubbed)


def test_every_class_member_has_a_stub_and_every_stub_a_description():
    tree = stub_tree()
    classes = {node.name: node for node in tree.body if isinstance(node, ast.ClassDef)}
    undocumented = []
    for name, node in classes.items():
        cls = getattr(_carom, name)
        if issubclass(cls, BaseException):
            continue
        members = {item.name for item in node.body if isinstance(item, ast.FunctionDef)}
        assert public(vars(cls)) <= members, name
        if not ast.get_docstring(node):
            undocumented.append(name)
        for item in node.body:
            if not isinstance(item, ast.FunctionDef):
                continue
            is_setter = any(isinstance(d, ast.Attribute) and d.attr == "setter"
                            for d in item.decorator_list)
            if (not is_setter
                    and item.name not in ("__init__", "__repr__")
                    and not ast.get_docstring(item)):
                undocumented.append(f"{name}.{item.name}")
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and not ast.get_docstring(node):
            undocumented.append(node.name)
    assert undocumented == []


def test_the_stubs_give_the_parameters_the_module_takes():
    tree = stub_tree()
    functions = {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}
    sweep = functions["sweep_ball_ball"]
    assert [a.arg for a in sweep.args.args] == ["a", "move_a", "b", "move_b"]
    world = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "World")
    init = next(i for i in world.body if isinstance(i, ast.FunctionDef) and i.name == "__init__")
    keywords = [a.arg for a in init.args.kwonlyargs]
    assert "boundary" in keywords and "gravity" in keywords
    add_balls = next(i for i in world.body
                     if isinstance(i, ast.FunctionDef) and i.name == "add_balls")
    assert "NDArray" in ast.unparse(add_balls.returns)


def test_the_package_re_exports_the_module():
    assert public(dir(_carom)) <= public(dir(carom))
    assert inspect.getdoc(carom.World.step)
