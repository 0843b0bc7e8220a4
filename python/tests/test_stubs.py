"""The type stubs name every class, function and method of the built module."""

import ast
import os

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
