"""The type stub (python/blossom/__init__.pyi, shipped in the wheel) lists exactly the module's public
names and each class's public methods and properties."""

import ast
import pathlib

import blossom

STUB = pathlib.Path(__file__).resolve().parent.parent / "blossom" / "__init__.pyi"


def stub_names():
    tree = ast.parse(STUB.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            members[node.name] = {
                n.name if isinstance(n, ast.FunctionDef) else n.target.id
                for n in node.body
                if isinstance(n, (ast.FunctionDef, ast.AnnAssign))
            }
        elif isinstance(node, ast.FunctionDef):
            top.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            top.add(node.target.id)
    return top, members


def public(names):
    return {n for n in names if not n.startswith("_") or n in ("__version__", "__float__", "__init__")}


def test_module_names_match_the_stub():
    top, _ = stub_names()
    module = public(dir(blossom))
    assert module == top - {"Number", "ArrayLike", "Point"}


def test_class_members_match_the_stub():
    _, members = stub_names()
    for name, stubbed in members.items():
        if name == "Error":
            continue
        cls = getattr(blossom, name)
        actual = {n for n in dir(cls) if not n.startswith("_")}
        assert actual == {n for n in stubbed if not n.startswith("_")}, name
