"""Fixtures shared by the tools tests: the module behind
`examples/avalanche/study.py collect`."""
import pytest

from acoustic_tools import avalanche_collect


@pytest.fixture(scope="session")
def collect():
    return avalanche_collect
