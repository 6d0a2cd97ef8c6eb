"""The type stubs (_tumble.pyi) name what the compiled module has, so that editors complete the
real API: every class, method and property of the module is in the stubs, and no more."""
import ast
import os

import tumble
from tumble import _tumble


def stubbed():
    path = os.path.join(os.path.dirname(_tumble.__file__), "_tumble.pyi")
    tree = ast.parse(open(path).read())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        elif isinstance(node, ast.FunctionDef):
            out[node.name] = None
    return out


def public(obj):
    return {n for n in vars(obj) if not n.startswith("_") or n in ("__init__", "__len__")}


def test_the_stubs_name_every_class_function_and_attribute_of_the_module():
    stubs = stubbed()
    module = {n for n in vars(_tumble) if not n.startswith("__")}
    assert set(stubs) - {"BadInput", "RunFailed", "TumbleWarning"} <= module
    for name in module:
        assert name in stubs, "not in _tumble.pyi: " + name
        value = getattr(_tumble, name)
        if isinstance(value, type) and not issubclass(value, BaseException):
            assert public(value) - {"__init__"} <= stubs[name] | {"__init__"}, name
            assert stubs[name] - {"__init__"} <= public(value), name


def test_the_package_exports_what_all_says():
    for name in tumble.__all__:
        assert hasattr(tumble, name), name
