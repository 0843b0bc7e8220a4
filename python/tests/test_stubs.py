"""The type stubs name every class, function and method of the built module."""

import ast
import os
import sys

import cga._cga as ext

STUB = os.path.join(os.path.dirname(__file__), "..", "cga", "_cga.pyi")


def test_the_stub_names_everything_the_module_has():
    tree = ast.parse(open(STUB).read())
    stub = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            stub[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)} | {
                n.target.id for n in node.body if isinstance(n, ast.AnnAssign)
            }
        elif isinstance(node, ast.FunctionDef):
            stub[node.name] = set()
    missing = []
    for name in dir(ext):
        if name.startswith("_"):
            continue
        if name not in stub:
            missing.append(name)
            continue
        obj = getattr(ext, name)
        if isinstance(obj, type) and not issubclass(obj, Exception):
            for attr in vars(obj):
                if not attr.startswith("_") and attr not in stub[name]:
                    missing.append(f"{name}.{attr}")
    assert not missing, f"not in cga/_cga.pyi: {missing}"


def test_the_stub_is_what_its_generator_writes():
    """_cga.pyi is written by python/tools/stubs.py; an edit by hand would be lost."""
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tools"))
    try:
        import stubs
    finally:
        sys.path.pop(0)
    assert open(STUB).read() == stubs.stub(), "run python3 python/tools/stubs.py"
