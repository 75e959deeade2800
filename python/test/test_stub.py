"""norm_preserving.pyi, the stub beside the module, names what the module has: each class with its
attributes (an enum with its values), each function with its parameters, in order, the
keyword-only ones after `*`. Read with ast; the module's side by introspection (properties,
enum members, and the signature pybind11 writes first in each function's __doc__)."""

import ast
import pathlib

import pytest

import norm_preserving

STUB = pathlib.Path(norm_preserving.__file__).with_name("norm_preserving.pyi")


def stub():
    assert STUB.exists(), f"{STUB} is not beside the module"
    return ast.parse(STUB.read_text())


def stub_classes():
    return {node.name: node for node in stub().body if isinstance(node, ast.ClassDef) and not node.name.startswith("_")}


def stub_functions():
    return {node.name: node for node in stub().body if isinstance(node, ast.FunctionDef)}


def module_classes():
    return {name: value for name, value in vars(norm_preserving).items() if isinstance(value, type)}


def module_functions():
    return {name: value for name, value in vars(norm_preserving).items()
            if callable(value) and not isinstance(value, type) and not name.startswith("_")}


def test_the_stub_and_the_module_have_the_same_classes_and_functions():
    assert stub_classes().keys() == module_classes().keys()
    assert stub_functions().keys() == module_functions().keys()


@pytest.mark.parametrize("name", sorted(stub_classes()))
def test_each_class_has_the_stubs_attributes(name):
    annotated = [node.target.id for node in stub_classes()[name].body if isinstance(node, ast.AnnAssign)]
    cls = getattr(norm_preserving, name)
    if hasattr(cls, "__members__"):  # an enum: its values, in order
        assert annotated == list(cls.__members__)
    else:
        properties = [attribute for attribute, value in vars(cls).items() if isinstance(value, property)]
        assert sorted(annotated) == sorted(properties)


def signature_parameters(function):
    """The parameter names of pybind11's signature line, `*` where the keyword-only ones start."""
    line = function.__doc__.split("\n", 1)[0]
    assert line.startswith(function.__name__ + "("), line
    text, depth, parameters, current = line[len(function.__name__) + 1:], 0, [], ""
    for c in text:  # split at the top-level commas, up to the closing parenthesis
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                break
            depth -= 1
        elif c in "'\"":
            pass
        if c == "," and depth == 0:
            parameters.append(current)
            current = ""
        else:
            current += c
    parameters.append(current)
    return [p.split(":")[0].split("=")[0].strip() for p in parameters if p.strip()]


def stub_parameters(node):
    names = [a.arg for a in node.args.posonlyargs + node.args.args]
    if node.args.kwonlyargs:
        names += ["*"] + [a.arg for a in node.args.kwonlyargs]
    return names


@pytest.mark.parametrize("name", sorted(stub_functions()))
def test_each_function_has_the_stubs_parameters(name):
    assert stub_parameters(stub_functions()[name]) == signature_parameters(getattr(norm_preserving, name))
