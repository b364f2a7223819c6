"""Fixtures shared by the tools tests: the modules behind the command lines
examples/avalanche/collect.py and record.py."""
import pytest

from acoustic_tools import avalanche_collect, avalanche_record


@pytest.fixture(scope="session")
def collect():
    return avalanche_collect


@pytest.fixture(scope="session")
def record():
    return avalanche_record
