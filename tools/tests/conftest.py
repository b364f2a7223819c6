"""Fixtures shared by the tools tests: the scripts of examples/avalanche,
loaded as modules (they are not on the import path)."""
import importlib.util
import os

import pytest

AVALANCHE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "avalanche")


def load_avalanche_script(name):
    spec = importlib.util.spec_from_file_location(f"avalanche_{name}", os.path.join(AVALANCHE, f"{name}.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="session")
def collect():
    return load_avalanche_script("collect")


@pytest.fixture(scope="session")
def record():
    return load_avalanche_script("record")
